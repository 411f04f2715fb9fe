"""The quick check of a chunk for the fast path: clean chunks skip ``tokens.tokenize``.

A chunk (as ``tokens.py`` describes it: comments marked, spaces gone, ending with a
newline) is *clean* when every line in it would pass ``tokenize`` with nothing bad,
and its numbers never end in a dot (``X1.``; such chunks simply take ``tokenize``).
The check is a few passes over the bytes: one table lookup gives each byte a class,
a second lookup of every pair of neighbouring classes finds any pair that cannot
occur in a clean chunk, and the letters, dots and line ends (a quarter of the bytes)
then give each number's line, start and decimals without any search. ``quick``
returns ``None`` for a chunk that is not clean; the caller then uses ``tokenize``,
so the two give the same result on every chunk ``quick`` accepts.
"""

from __future__ import annotations

import numpy as np

from .tokens import MAX_TOKEN, Tokens

NL, MARK, LETTER, DOT, DIGIT, SIGN, BAD = range(7)
_CLASS = np.full(256, BAD, np.uint8)
_CLASS[ord("\n")], _CLASS[1], _CLASS[ord(".")] = NL, MARK, DOT
_CLASS[np.frombuffer(b"0123456789", np.uint8)] = DIGIT
_CLASS[np.frombuffer(b"+-", np.uint8)] = SIGN
for _c in range(26):
    _CLASS[[65 + _c, 97 + _c]] = LETTER
_CLASS_TABLE = bytes(_CLASS)
_NUMBER = (DOT, DIGIT, SIGN)
_BAD_PAIR = np.zeros(7 * 7, bool)  # (class before) * 7 + (class after) -> never in a clean chunk
for _a, _b in [(LETTER, NL), (LETTER, MARK), (LETTER, LETTER), (SIGN, NL), (SIGN, MARK),
               (SIGN, LETTER), (DOT, NL), (DOT, MARK), (DOT, LETTER), (DOT, DOT)]:
    _BAD_PAIR[_a * 7 + _b] = True
for _n in _NUMBER:
    _BAD_PAIR[[NL * 7 + _n, MARK * 7 + _n, _n * 7 + SIGN]] = True  # a number needs its letter;
    # a sign only comes right after the letter
_BAD_PAIR[BAD * 7 : BAD * 7 + 7] = _BAD_PAIR[BAD::7] = True  # a byte no clean line holds
_GOOD_PAIRS = bytes(np.flatnonzero(~_BAD_PAIR).astype(np.uint8))


def quick(text: bytes) -> tuple[Tokens, np.ndarray] | None:
    """(tokens, line of every letter) of a clean chunk, or ``None`` (use ``tokenize``).

    The tokens' ``newlines`` and ``bad`` are ``None``: a clean chunk needs neither."""
    cls = np.frombuffer(text.translate(_CLASS_TABLE), np.uint8)
    if len(cls) < 2 or cls[0] not in (NL, MARK, LETTER) or cls[-1] != NL:
        return None
    pair = cls[:-1] * np.uint8(7)
    pair += cls[1:]
    if pair.tobytes().translate(None, _GOOD_PAIRS):
        return None
    del pair
    where = np.flatnonzero(cls < DIGIT)  # line ends, comment marks, letters and dots
    kind = cls[where]
    del cls
    at = np.flatnonzero(kind == LETTER)
    after = at + 1
    dotted = kind[after] == DOT
    if np.count_nonzero(kind == DOT) != np.count_nonzero(dotted):  # a number with two dots
        return None
    letters = where[at]
    nxt = where[after]  # the dot, or the end of a number without one
    after += dotted
    ends = where[after]  # the letter or line end after each number
    if len(ends) and int((ends - letters).max()) > MAX_TOKEN + 1:
        return None
    decimals = ends - nxt
    decimals -= 1
    decimals *= dotted
    line = np.cumsum(kind == NL, dtype=np.int32)[at]
    return Tokens(letters, letters + 1, ends - 1, decimals, None, None), line
