"""The source lines of a program, split only when someone needs them all.

``Lines`` is a read-only sequence of the physical lines of a file (split at ``\\n``,
a ``\\r`` before it dropped, no empty last line), as ``program._split`` gives them.
Built from a list it is that list; built from the file's bytes (valid UTF-8) it
decodes one line at a time for the interpreter, which reads only the lines the fast
path leaves to it, and makes the whole list on the first call of ``as_list()``
(``Program.source_lines``). Loading a big file thus builds no string per line, and a
listing that shows a few lines at a time reads only those.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

CHUNK_BYTES = 1 << 18


def chunks(data: bytes) -> list[tuple[int, int, int]]:
    """(start, end, newlines) of byte ranges of about CHUNK_BYTES, each ending after a
    newline (the last one at the end of ``data``)."""
    out, start = [], 0
    while start < len(data):
        end = data.find(b"\n", start + CHUNK_BYTES)
        end = len(data) if end < 0 else end + 1
        newlines = np.count_nonzero(np.frombuffer(data, np.uint8, end - start, start) == 10)
        out.append((start, end, int(newlines)))  # numpy counts 4x faster than bytes.count
        start = end
    return out


class Lines(Sequence):
    """Source lines over a list or over UTF-8 bytes (see the module docstring)."""

    def __init__(self, lines: list[str] | None = None, data: bytes = b"",
                 origin: tuple[str, int] | None = None):
        """``origin``: (path, offset) when ``data`` is that file's bytes from that offset on,
        as read (the helper process then reads its part of the scan there itself)."""
        self._list = lines
        self._data = data
        self.origin = origin
        self.chunks = chunks(data) if lines is None else []  # also the fast path's chunks
        self._firsts = np.cumsum([0] + [c[2] for c in self.chunks])  # first line of each chunk
        self._ends: dict[int, np.ndarray] = {}  # chunk -> offsets of its newlines (as read)
        self._chunk_starts: np.ndarray | None = None
        if lines is None:
            self._count = int(self._firsts[-1]) + (0 if data.endswith(b"\n") or not data else 1)
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
        k = int(np.searchsorted(self._firsts, i, "right")) - 1  # the chunk holding line i
        if k >= len(self.chunks):  # the last line, with no newline after it
            start, end = self._data.rfind(b"\n") + 1, len(self._data)
        else:
            begin, _, _ = self.chunks[k]
            ends = self._chunk_ends(k)
            j = i - int(self._firsts[k])
            start, end = (int(ends[j - 1]) + 1 if j else begin), int(ends[j])
        line = self._data[start:end].decode("utf-8")
        return line[:-1] if line.endswith("\r") else line

    def line_of(self, data: bytes, offset: int) -> int:
        """The 1-based line of byte ``offset`` of ``data``: from the chunk table when ``data``
        is the bytes these lines hold (newlines counted in one chunk), else counted."""
        if data is not self._data or not self.chunks:
            return data.count(b"\n", 0, offset) + 1
        k = int(np.searchsorted(self._starts(), offset, "right")) - 1
        return int(self._firsts[k]) + data.count(b"\n", self.chunks[k][0], offset) + 1

    def _starts(self) -> np.ndarray:
        """Offsets of the chunks' first bytes (found once)."""
        if self._chunk_starts is None:
            self._chunk_starts = np.array([start for start, _, _ in self.chunks], np.int64)
        return self._chunk_starts

    def _chunk_ends(self, k: int) -> np.ndarray:
        """Offsets of chunk ``k``'s newlines, found once (a listing reads nearby lines)."""
        ends = self._ends.get(k)
        if ends is None:
            begin, stop, _ = self.chunks[k]
            ends = np.flatnonzero(np.frombuffer(self._data, np.uint8, stop - begin, begin) == 10) + begin
            self._ends[k] = ends
        return ends

    def encoded(self) -> bytes:
        """The lines as UTF-8 bytes, ``\\n`` after each (the file's bytes while they are kept)."""
        if self._list is None:
            return self._data
        return "".join(line + "\n" for line in self._list).encode("utf-8")

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
            self._data = b""
            self._ends.clear()
        return self._list
