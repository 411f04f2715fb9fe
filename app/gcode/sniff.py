"""Does a program need the expander (``macro``)? The loader's cheap test on a file's bytes.

``needs_expander(raw)``: ``#``, ``[``, an ``O`` word, ``WHILE``/``END``/``GOTO``/``DO``
outside comments, ``M98``/``M99``/``G65``. It lives apart from ``macro`` so that loading
a plain program never imports the expander. A nested comment ``(a (b) c)`` counts as a
comment here: no control reads it, but the line's error is the plain path's to report
(the expander would cost a plain file its speed and far more memory).

``chunk_plain`` and ``letters_plain`` give the same answer a chunk at a time, for the
fast path's scan to find it on the way (no pass of its own over a big file; see
``program._interpret``).
"""

from __future__ import annotations

import re

_LINE_PARENS = re.compile(rb"\([^()\n]*\)")
_SEMI = re.compile(rb";[^\n]*")
_PARENS = re.compile(rb"\([^()]*\)")
_PLAIN = b" \t\r0123456789.-+GXYZIJKFMSNRTgxyzijkfmsnrt"  # what plain lines are made of
_MACRO_BYTES = b"#[oOwWeE"  # parameters, expressions, o-words, O numbers, GOTO, DO, WHILE, END
_UPPER = bytes.maketrans(b"abcdefghijklmnopqrstuvwxyz", b"ABCDEFGHIJKLMNOPQRSTUVWXYZ")
NESTING = 8  # levels of nested comments looked through (each costs a pass over the comments)
_CALLS = (b"M98", b"M99", b"G65", b"M098", b"M099", b"G065")
_CALL_WORDS = b"PpLl"  # M98 P, G65 P, L counts: a call is looked for where one of these stands


def _without_comments(rest: bytes, parens: re.Pattern) -> bytes:
    """``rest`` without its comments: parentheses first (nested ones too, one pass per
    level, up to ``NESTING`` levels), then ``;`` to the end of the line."""
    for _ in range(NESTING):
        rest, count = parens.subn(b"", rest)
        if not count or b"(" not in rest:
            break
    return _SEMI.sub(b"", rest) if b";" in rest else rest


_SUSPECT_LETTERS = b"OoWwEePpLl"  # letters that may make a program the expander's (O, WHILE, M98 P, L)
_OTHER_LETTERS = bytes(c for c in range(256) if c not in _SUSPECT_LETTERS)


def letters_plain(letters: bytes) -> bool:
    """Part of ``chunk_plain`` for a chunk the fast path read whole (every line well-formed
    words and single-level comments, so nothing but letters can call for the expander):
    its word ``letters`` hold none that may."""
    return not letters.translate(None, _OTHER_LETTERS)


def chunk_plain(chunk: bytes) -> bool:
    """True when ``chunk`` (whole lines of a program) shows nothing that needs the expander
    and every comment in it ends on its own line: if every chunk of a file is so, then
    ``needs_expander`` of the file is False (its comments cannot reach across lines or
    chunks). False means "not known": ask ``needs_expander`` of the whole file."""
    rest = chunk.translate(None, _PLAIN)
    if b"(" in rest or b")" in rest:
        rest = _LINE_PARENS.sub(b"", rest)
        if b"(" in rest or b")" in rest:
            return False
    if b";" in rest:
        rest = _SEMI.sub(b"", rest)
    return not _holds_any(rest, _MACRO_BYTES + _CALL_WORDS)


def _holds_any(rest: bytes, chars: bytes) -> bool:
    return any(rest.find(c) >= 0 for c in (bytes([b]) for b in chars))


class NeedsExpander(Exception):
    """Raised by a load that read a program on the fast path and found it needs the expander."""


def needs_expander(raw: bytes) -> bool:
    """True when the program uses anything beyond plain words (see the module docstring).

    Costs two ``bytes.translate`` passes: the bytes of plain lines are dropped first,
    so only comments and unusual letters are left to look at."""
    rest = raw.translate(None, _PLAIN)
    if b";" in rest:
        rest = _without_comments(rest, _LINE_PARENS)
    elif b"(" in rest:  # lines need not be told apart: drop the newlines before the comments
        rest = _without_comments(rest.translate(None, b"\n"), _PARENS)
    if _holds_any(rest, _MACRO_BYTES):
        return True
    if _holds_any(rest, _CALL_WORDS):
        squeezed = raw.translate(_UPPER, b" \t\r")
        return any(call in squeezed for call in _CALLS)
    return False
