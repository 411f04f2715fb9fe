"""``LineError``: how the interpreter's parts refuse a line."""

from __future__ import annotations


class LineError(Exception):
    """A refused line: a 1-based column (0 = the whole line) and the reason."""

    def __init__(self, column: int, message: str):
        super().__init__(message)
        self.column = column
        self.message = message
