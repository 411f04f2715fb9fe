"""The ``%`` lines that open and close a program, as rs274ngc reads them.

A program whose first line holding anything is ``%`` ends at the next ``%`` line:
the lines after it are never run (``percent_lines``); a ``%`` line anywhere else is
refused. Such a program that reaches the end of the file with neither a closing
``%`` nor M2/M30 is refused on its last line ("File ended with no percent sign",
rs274ngc). Found on the bytes with ``find`` (no line split), so a plain program pays
a scan at memory speed, and nothing when it holds no ``%``. An ``(ABORT, text)``
comment ends a plain program there with an error holding the text (``abort_line``;
the expander stops where its flow reaches one).
"""

from __future__ import annotations

import re

from app.i18n import msg

from .diagnostics import Report
from .lexer import lex_line

_BLANK = b" \t\r\n"
_ABORT = re.compile(rb"\((?i:\s*abort\s*,([^)\n]*))\)")  # one pass from each "("


def abort_message(text: str) -> str:
    """The operator's message of an ``(ABORT, text)`` comment."""
    return msg("(ABORT) the program stops here: {text}", text=text.strip())


def _counted(raw: bytes):
    """``line_of`` for ``raw``: the 1-based line of a byte offset, newlines counted."""
    return lambda offset: raw.count(b"\n", 0, offset) + 1


def abort_line(raw: bytes, line_of=None) -> tuple[int, str]:
    """(1-based line, text) of the first ``(ABORT, text)`` comment of a plain program (it
    stops there, as LinuxCNC stops with the text), or (0, ""). ``line_of(offset)``: the
    1-based line of a byte offset of ``raw``, if the caller knows a quicker way."""
    found = _ABORT.search(raw) if b"," in raw else None  # no comma, no (ABORT, ...): a memchr, not a regex
    if found is None:
        return 0, ""
    return (line_of or _counted(raw))(found.start()), found.group(1).decode("utf-8", "replace")


def _line_start(raw: bytes, pos: int) -> int:
    return raw.rfind(b"\n", 0, pos) + 1


def _percent_lines(raw: bytes):
    """Byte offsets of the ``%`` that start a line (after spaces), in order."""
    pos = raw.find(b"%")
    while pos >= 0:
        start = _line_start(raw, pos)
        if not raw[start:pos].strip(b" \t\r"):
            yield pos
        pos = raw.find(b"%", pos + 1)


def percent_lines(raw: bytes, line_of=None) -> tuple[int, int, int]:
    """1-based lines of the opening ``%``, of the closing one, and of the first ``%`` line
    that is neither (a program that does not open with ``%``); 0 where there is none.
    ``line_of`` as for ``abort_line``."""
    found = _percent_lines(raw)
    first = next(found, -1)
    if first < 0:
        return 0, 0, 0
    line = raw.count(b"\n", 0, first) + 1
    if raw[:first].strip(_BLANK):
        return 0, 0, line
    second = next(found, -1)
    if second < 0:
        return line, 0, 0
    return line, (line_of(second) if line_of else raw.count(b"\n", first, second) + line), 0


def report_tail(lines, found: tuple[int, int, int], ended: int, report: Report) -> None:
    """One warning for the first line after the closing ``%`` that holds anything, or the
    error of a file opened by ``%`` that ends with neither it nor M2/M30, or of a ``%``
    line in a program that did not open with one (rs274ngc: "Bad character '%' used")."""
    opening, closing, stray = found
    if stray and not (ended and ended < stray):
        report.error(stray, 1, msg("'%' here: a '%' line only opens a program (its first line) "
                                   "and closes it"))
    if not opening or ended:
        return
    if not closing:
        last = len(lines)
        report.error(last, 0, msg("the file ended with no closing '%' (the program opened with '%' at "
                                  "line {line}, and has no M2 or M30)", line=opening))
        return
    for i in range(closing, len(lines)):
        lexed = lex_line(lines[i], i + 1)
        if lexed.words or lexed.error:
            report.warning(i + 1, 0, msg("ignored: the program ended at the closing '%' of line {line}",
                                         line=closing))
            return
