"""Where each row of an expansion comes from, kept beside the rows as they are made.

``Trace`` has four integer columns, one entry per row: the file (id into
``files``), the main program's line that caused the row, the subprogram (id into
``names``) and the loop pass. A ``Column`` grows by Python items (rows the
interpreter makes one at a time) and by numpy chunks (a batch of the fast path),
kept in order, and becomes one array at the end. ``FileReport`` is a ``Report``
seen through one file: what ``interpret_line`` reports gets the file's name.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from app.gcode.diagnostics import ERROR, WARNING, Report


class Column:
    """A growing column of integers (see the module docstring)."""

    __slots__ = ("_parts", "_tail", "_done")

    def __init__(self) -> None:
        self._parts: list[np.ndarray] = []
        self._tail: list[int] = []
        self._done = 0  # entries in ``_parts``

    def extend(self, items) -> None:
        self._tail.extend(items)

    def add(self, chunk: np.ndarray) -> None:
        """Append a numpy chunk of entries."""
        self._close_tail()
        self._parts.append(chunk)
        self._done += len(chunk)

    def __len__(self) -> int:
        return self._done + len(self._tail)

    def array(self, dtype) -> np.ndarray:
        """Every entry so far, in order, as one array of ``dtype``."""
        self._close_tail()
        if not self._parts:
            return np.zeros(0, dtype)
        return np.concatenate([p.astype(dtype, copy=False) for p in self._parts])

    def _close_tail(self) -> None:
        if self._tail:
            self._parts.append(np.asarray(self._tail, np.int64))
            self._done += len(self._tail)
            self._tail = []


@dataclass
class Trace:
    """Per row of the expansion: file id, main-program line, subprogram id, iteration."""

    files: list[str]
    names: list[str] = field(default_factory=lambda: [""])
    file: Column = field(default_factory=Column)
    call_line: Column = field(default_factory=Column)
    context: Column = field(default_factory=Column)
    iteration: Column = field(default_factory=Column)
    state: object = None  # the interpreter's state after the walk

    def repeat(self, n: int, file_id: int, context: int, iteration: int, call_lines) -> None:
        """``n`` rows of one frame; ``call_lines``: one line for all, or a line each."""
        self.file.extend([file_id] * n)
        self.call_line.extend([call_lines] * n if isinstance(call_lines, int) else call_lines)
        self.context.extend([context] * n)
        self.iteration.extend([iteration] * n)


class FileReport:
    """A ``Report`` seen through one file: what ``interpret_line`` reports gets the file."""

    def __init__(self, report: Report, file: str):
        self.report, self.file = report, file

    def error(self, line, column, message, key=""):
        self.report.add(line, column, ERROR, message, key, file=self.file)

    def warning(self, line, column, message, key=""):
        self.report.add(line, column, WARNING, message, key, file=self.file)

    def take_back(self, line: int) -> None:
        """Drop the error just reported for ``line`` (a repeat of one already listed)."""
        items = self.report.items
        if items and items[-1].line == line and items[-1].severity == ERROR:
            items.pop()
