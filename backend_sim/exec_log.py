"""The record of executed lines: ``(seq, line)`` of every line the CNC MCU finished.

Kept in memory (``entries``) and, with a path, appended to a file as ``seq<TAB>line``
per line (``--exec-log FILE``), the record fault tests compare with the program.
"""

from __future__ import annotations

from pathlib import Path


class ExecLog:
    def __init__(self, path: str | Path | None = None) -> None:
        self.entries: list[tuple[int, str]] = []
        self.path = Path(path) if path else None

    def add(self, seq: int, line: str) -> None:
        self.entries.append((seq, line))
        if self.path is not None:
            with self.path.open("a", encoding="utf-8") as out:
                out.write(f"{seq}\t{line}\n")

    def clear(self) -> None:
        self.entries.clear()

    def __len__(self) -> int:
        return len(self.entries)

    def __iter__(self):
        return iter(self.entries)

    def __getitem__(self, index):
        return self.entries[index]
