"""Byte-level tokens of one chunk of a program, for the fast path (``bulk.py``).

A chunk is whole lines of bytes ending in a newline, each comment replaced by byte 1
(it separates words) and spaces, tabs and carriage returns deleted (rs274ngc ignores
them: ``X 1 0`` is ``X10``). The fast path then reads only: a letter followed at once by its number, numbers
``[+-]digits[.digits]`` or ``[+-].digits`` of at most ``MAX_TOKEN`` characters.
``tokenize`` returns the letters, the number spans (one per letter once the chunk
is clean), the newlines, and the positions that make a line unusable here (the
general lexer then reads that line). ``numbers`` turns the spans into doubles: the
digits are read as one integer by numpy's C parser and divided by a power of ten;
both are exact, so the result is the correctly rounded value ``float()`` gives.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

MAX_TOKEN = 15  # characters of a number read here (exact in an int64 and a double)
_POW10 = np.array([float(10**i) for i in range(MAX_TOKEN + 1)])
_NUMBERS_ONLY = bytes(c if chr(c) in "0123456789.+-" else 32 for c in range(256))  # the sign is parsed too
DOT, MINUS, PLUS, NEWLINE = ord("."), ord("-"), ord("+"), ord("\n")


@dataclass
class Tokens:
    """Positions in the chunk (``starts``/``ends``/``decimals`` per number)."""

    letters: np.ndarray
    starts: np.ndarray
    ends: np.ndarray
    decimals: np.ndarray
    newlines: np.ndarray
    bad: np.ndarray


def _digit(c: np.ndarray) -> np.ndarray:
    return (c - 48) < 10


def _edges(isnum: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Masks of the first and the last character of every number."""
    start = np.empty(len(isnum), bool)
    start[0] = isnum[0]
    np.greater(isnum[1:], isnum[:-1], out=start[1:])
    end = np.empty(len(isnum), bool)
    end[-1] = isnum[-1]
    np.greater(isnum[:-1], isnum[1:], out=end[:-1])
    return start, end


def _shape_bad(b, starts, ends) -> np.ndarray:
    """Numbers whose first characters do not make a number, or that are too long."""
    first, c1 = b[starts], b[starts + 1]  # a chunk ends with a newline, never in a number
    c2 = b[np.minimum(starts + 2, len(b) - 1)]
    sign = (first == MINUS) | (first == PLUS)
    ok = _digit(first) | ((first == DOT) & _digit(c1))
    ok |= sign & (_digit(c1) | ((c1 == DOT) & _digit(c2)))
    return starts[~ok | (ends - starts >= MAX_TOKEN)]


def _inner(b, special, start, starts, ends):
    """Bad positions among signs and dots inside numbers, and each number's decimals."""
    inner = np.flatnonzero(special & ~start)
    dots = inner[b[inner] == DOT]
    token = np.searchsorted(starts, dots, "right") - 1  # the number each dot is in
    dotted = b[starts] == DOT
    decimals = np.where(dotted, ends - starts, 0)
    decimals[token] = ends[token] - dots
    bad = [inner[b[inner] != DOT], dots[1:][token[1:] == token[:-1]], dots[dotted[token]]]
    return np.concatenate(bad), decimals


def tokenize(b: np.ndarray) -> Tokens:
    """The tokens of chunk ``b`` (uint8, ending with a newline)."""
    special = (b == DOT) | (b == MINUS) | (b == PLUS)
    isnum = _digit(b) | special
    isletter = ((b | 0x20) - 97) < 26
    other = (b == 32) | (b == NEWLINE) | (b == 1)  # 1 marks where a comment was
    start, end = _edges(isnum)
    letters = np.flatnonzero(isletter)
    follows = start[letters + 1]
    if follows.all() and np.count_nonzero(start) == len(letters):
        starts = letters + 1  # every number right after its letter: no need to search
    else:
        starts = np.flatnonzero(start)
    ends = np.flatnonzero(end)
    inner_bad, decimals = _inner(b, special, start, starts, ends)
    bad = np.concatenate([
        np.flatnonzero(~(isnum | isletter | other)),
        letters[~follows],  # a letter without a number right after it
        starts[~isletter[starts - 1]],  # a number without its letter (index -1 is the newline)
        _shape_bad(b, starts, ends),
        inner_bad,
    ])
    return Tokens(letters, starts, ends, decimals, np.flatnonzero(b == NEWLINE), bad)


def numbers(text: bytes, b: np.ndarray, tokens: Tokens) -> np.ndarray:
    """The value of every number of a clean chunk, in order."""
    digits = text.translate(_NUMBERS_ONLY, b".")
    if not len(tokens.starts):
        return np.empty(0)
    mantissa = np.fromstring(digits, dtype=np.int64, sep=" ")  # signed
    value = mantissa / _POW10[tokens.decimals]  # a quotient of exact numbers: correctly rounded
    zero = np.flatnonzero(mantissa == 0)
    value[zero[b[tokens.starts[zero]] == MINUS]] = -0.0  # "-0.0" keeps its sign, as float() does
    return value
