"""The source lines of a program, split only when someone needs them all.

``Lines`` is a read-only sequence of the physical lines of a file (split at ``\\n``,
a ``\\r`` before it dropped, no empty last line), as ``program._split`` gives them.
Built from a list it is that list; built from the file's bytes (valid UTF-8) it
decodes one line at a time for the interpreter, which reads only the lines the fast
path leaves to it, and makes the whole list on the first call of ``as_list()``
(``Program.source_lines``). Loading a big file thus builds no string per line.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np


class Lines(Sequence):
    """Source lines over a list or over UTF-8 bytes (see the module docstring)."""

    def __init__(self, lines: list[str] | None = None, data: bytes = b""):
        self._list = lines
        self._data = data
        self._ends: np.ndarray | None = None
        if lines is None:
            self._count = data.count(b"\n") + (0 if data.endswith(b"\n") or not data else 1)
        else:
            self._count = len(lines)

    def __len__(self) -> int:
        return self._count

    def __getitem__(self, i):
        if self._list is not None or isinstance(i, slice):
            return self.as_list()[i]
        if i < 0:
            i += self._count
        if not 0 <= i < self._count:
            raise IndexError(i)
        if self._ends is None:
            self._ends = np.flatnonzero(np.frombuffer(self._data, np.uint8) == 10)
        start = int(self._ends[i - 1]) + 1 if i else 0
        end = int(self._ends[i]) if i < len(self._ends) else len(self._data)
        line = self._data[start:end].decode("utf-8")
        return line[:-1] if line.endswith("\r") else line

    def as_list(self) -> list[str]:
        """Every line as a list of strings (built once)."""
        if self._list is None:
            text = self._data.decode("utf-8")
            lines = text.split("\n")
            if lines and lines[-1] == "":
                lines.pop()
            if "\r" in text:
                lines = [line[:-1] if line.endswith("\r") else line for line in lines]
            self._list = lines
            self._data, self._ends = b"", None
        return self._list
