"""The record of executed lines: ``(seq, line)`` of every line the CNC MCU finished.

Kept in memory (``entries``) and, with a path, appended to a file as ``seq<TAB>line``
per line (``--exec-log FILE``), the record fault tests compare with the program.

A line goes to the file in one write of the whole record; when that fails (a full
disk: ENOSPC at any byte) the file is cut back to its length before the record, so
no torn line is ever left, and ``failure`` says what happened: the CNC MCU then stops
the job with ``X EXEC_LOG`` (``take_failure``). ``open_append`` is the filesystem
seam (tests put a failing file there).
"""

from __future__ import annotations

import errno
import os
from pathlib import Path


class ExecLog:
    def __init__(self, path: str | Path | None = None) -> None:
        self.entries: list[tuple[int, str]] = []
        self.path = Path(path) if path else None
        self.failure: str | None = None

    def open_append(self, path: Path):
        """An unbuffered binary file to append records to (the filesystem seam)."""
        return path.open("ab", buffering=0)

    def add(self, seq: int, line: str) -> None:
        self.entries.append((seq, line))
        if self.path is not None:
            try:
                self._write(f"{seq}\t{line}\n".encode())
            except OSError as exc:
                self.failure = f"line {seq} not logged: {exc.strerror or exc}"

    def _write(self, record: bytes) -> None:
        """Append ``record`` whole, or cut the file back and raise OSError."""
        with self.open_append(self.path) as out:
            start = out.seek(0, os.SEEK_END)
            try:
                view = memoryview(record)
                while view:
                    written = out.write(view)
                    if not written:
                        raise OSError(errno.ENOSPC, "no byte written")
                    view = view[written:]
            except OSError:
                out.truncate(start)
                raise

    def take_failure(self) -> str | None:
        """The failure since the last call, or None."""
        failure, self.failure = self.failure, None
        return failure

    def clear(self) -> None:
        self.entries.clear()

    def __len__(self) -> int:
        return len(self.entries)

    def __iter__(self):
        return iter(self.entries)

    def __getitem__(self, index):
        return self.entries[index]
