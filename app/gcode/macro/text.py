"""A source line made ready to parse, as rs274ngc does before reading a block.

``squeeze(line, line_no)`` drops spaces and tabs, comments ``( ... )`` and what
follows ``;``, and lower-cases the rest (``*`` is multiplication here, not a
checksum); it keeps, per character left, its 1-based column in the source line, so
every later error can point at the right place. An unclosed comment is an error.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.i18n import msg

from .errors import MacroError


@dataclass(frozen=True)
class Squeezed:
    """The characters that matter and their source columns (1-based)."""

    text: str
    columns: tuple[int, ...]

    def column(self, i: int) -> int:
        """Source column of character ``i`` (the column after the last for the end)."""
        if i < len(self.columns):
            return self.columns[i]
        return self.columns[-1] + 1 if self.columns else 1


def squeeze(line: str, line_no: int) -> Squeezed:
    """The line without spaces, comments and case (see the module docstring)."""
    chars: list[str] = []
    cols: list[int] = []
    i, n = 0, len(line)
    while i < n:
        c = line[i]
        if c == "(":
            end = line.find(")", i + 1)
            if end < 0:
                raise MacroError(msg("comment '(' is not closed on this line"), line_no, i + 1)

            i = end + 1
            continue
        if c == ";":
            break
        if c not in " \t\r":
            chars.append(c.lower())
            cols.append(i + 1)
        i += 1
    return Squeezed("".join(chars), tuple(cols))
