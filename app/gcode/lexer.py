"""The general lexer: one physical source line -> words, or a diagnostic.

Accepted (as LinuxCNC's rs274ngc reads it): words of one letter and a number, in
either case (``g1x10Y-2.5``), and LinuxCNC's polar words ``@`` (radius) and ``^``
(angle); spaces and tabs anywhere outside comments, even inside
a number (``X1 0.5`` is ``X10.5``); numbers ``1``, ``.5``, ``-0.``, ``+3``; comments
``( ... )`` anywhere (not nested) and ``; ...`` to the end of the line; a ``%`` line; a leading
``/`` (block delete: the line is skipped); a ``*checksum`` suffix (ignored).

Refused with the line and the 1-based column: ``#`` parameters, ``[`` expressions,
o-words, an unclosed or nested comment, a letter without a number, any other character, and a
number ``limits.word_problem`` refuses (too large, a negative feed or speed, ...).
``lex_line`` never raises. The fast path (``bulk.py``) reads the common shapes of
line in bulk and hands every line it is unsure of to this module.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.i18n import msg

from .diagnostics import Diagnostic
from .limits import word_problem

_SPACE = " \t\r"
_DIGITS = "0123456789"
_SPECIAL = {
    "#": msg("'#' parameters are not supported (a later version adds macros)"),
    "[": msg("'[' expressions are not supported"),
    "o": msg("o-words (subroutines, loops) are not supported"),
}


_POLAR = "@^"  # LinuxCNC's polar words: @ radius, ^ angle (degrees)


@dataclass(frozen=True)
class Word:
    """One letter (upper case) and its number, at a 1-based column."""

    letter: str
    value: float
    column: int


@dataclass
class LexedLine:
    """Result of lexing one line: the words, or an error; ``skip`` marks / and % lines."""

    words: list[Word] = field(default_factory=list)
    error: Diagnostic | None = None
    skip: str = ""


def _fail(line_no: int, col: int, message: str) -> LexedLine:
    return LexedLine(error=Diagnostic(line_no, col + 1, "error", message))


def _skip_space(text: str, i: int) -> int:
    while i < len(text) and text[i] in _SPACE:
        i += 1
    return i


def _read_number(text: str, i: int) -> tuple[str, int]:
    """The characters of the number starting at ``i`` (spaces dropped) and the end index."""
    chars = []
    seen_dot = False
    while i < len(text):
        c = text[i]
        if c in _DIGITS:
            chars.append(c)
        elif c == "." and not seen_dot:
            seen_dot = True
            chars.append(c)
        elif c in "+-" and not chars:
            chars.append(c)
        elif c not in _SPACE:
            break
        i += 1
    return "".join(chars), i


def _number_ok(token: str) -> bool:
    return any(c in _DIGITS for c in token)


def _comment_end(text: str, i: int, line_no: int) -> tuple[int, LexedLine | None]:
    """Index after the ``)`` closing the comment opened at ``i``, or the error of a
    comment that is not closed or holds another ``(`` (rs274: "Nested comment found")."""
    end = text.find(")", i + 1)
    inner = text.find("(", i + 1, len(text) if end < 0 else end)
    if inner >= 0:
        return i, _fail(line_no, inner, msg("nested comment: '(' inside a comment"))
    if end < 0:
        return i, _fail(line_no, i, msg("comment '(' is not closed on this line"))
    return end + 1, None


def _lead(text: str, line_no: int) -> tuple[int, LexedLine | None]:
    """Handle a leading ``/`` or ``%``; return where words start or a finished result."""
    i = _skip_space(text, 0)
    if i < len(text) and text[i] == "/":
        return i, LexedLine(skip="block delete")
    if i < len(text) and text[i] == "%":
        rest = lex_line(text[i + 1 :], line_no)
        if rest.error is None and not rest.words:
            return i, LexedLine(skip="%")
        return i, _fail(line_no, i, msg("unexpected text after '%'"))
    return i, None


def lex_line(text: str, line_no: int) -> LexedLine:
    """Split one source line into words; errors name ``line_no`` and the column."""
    i, done = _lead(text, line_no)
    if done is not None:
        return done
    words: list[Word] = []
    while i < len(text):
        c = text[i]
        if c in _SPACE:
            i += 1
        elif c == "(":
            i, failed = _comment_end(text, i, line_no)
            if failed:
                return failed
        elif c == ";" or c == "*":
            break
        elif c.lower() in _SPECIAL:
            return _fail(line_no, i, _SPECIAL[c.lower()])
        elif c.isascii() and c.isalpha() or c in _POLAR:
            token, end = _read_number(text, i + 1)
            if end < len(text) and text[end] in "#[":
                return _fail(line_no, end, _SPECIAL[text[end]])
            if not _number_ok(token):
                return _fail(line_no, i, msg("word {letter} has no number", letter=c.upper()))
            value = float(token)
            problem = word_problem(c.upper(), value)
            if problem:
                return _fail(line_no, i, problem)
            words.append(Word(c.upper(), value, i + 1))
            i = end
        else:
            return _fail(line_no, i, msg("unexpected character {char!r}", char=c))
    return LexedLine(words=words)
