"""The one exception of the expander: a problem at a place in a source file.

``MacroError(message, line, column)`` carries the 1-based line and column (0 when the
whole line is meant); the file is added by whoever knows which file was being read
(``at_file``). ``str()`` reads ``file line 12, column 5: message``.
"""

from __future__ import annotations


class MacroError(Exception):
    """A refused program: what went wrong and where (file, line, column)."""

    def __init__(self, message: str, line: int = 0, column: int = 0, file: str = ""):
        super().__init__(message)
        self.message, self.line, self.column, self.file = message, line, column, file

    def at(self, line: int, file: str) -> MacroError:
        """Fill in the line and file where they are still unknown; returns self."""
        self.line = self.line or line
        self.file = self.file or file
        return self

    def __str__(self) -> str:
        where = f"line {self.line}" + (f", column {self.column}" if self.column else "")
        return f"{self.file + ' ' if self.file else ''}{where}: {self.message}"


class TooLarge(MacroError):
    """The expansion passed the move limit: the walk stops and its rows are dropped
    (the program is refused; keeping millions of rows would only fill the memory)."""


class Stopped(MacroError):
    """The interpreter refused a block and reported it already: the walk stops there at
    once (rs274ngc stops at its first error), whatever loop or call it was in."""

    def __init__(self, line: int = 0) -> None:
        super().__init__("", line)
