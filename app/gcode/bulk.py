"""The fast path: read every plain line of a program at once, with numpy.

``scan(data)`` takes the whole source as bytes and returns a ``Scan``: one row per
physical line with the motion code ``g`` (G0-G3), the ``units`` code (G20 = 1,
G21 = 0), the values of X, Y, Z, I, J, F, M (3 or 5 only) and S (NaN when absent) and
a ``simple`` flag. A line is simple when it holds only those words (and N), each at
most once, well formed, with nothing but spaces and well-closed comments around them,
and M or S only on a line with no motion word: the shape of nearly every line
Inkscape's Gcodetools writes. Every other
line is left to the general lexer and interpreter, which are the reference; the tests
check that both paths agree. A number's digits are read as one integer by numpy's C
parser and divided by a power of ten, which is exact to the last bit for numbers of
up to ``MAX_TOKEN`` characters (longer ones take the general path).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

CHUNK_BYTES = 1 << 18
COLUMNS = "GXYZIJFMS"  # the words of a simple line (and N, read and dropped)
_COMMENT = re.compile(rb"\([^()\n]*\)")
_SEMI = re.compile(rb";[^\n]*")

# character classes
SPACE, LETTER, DIGIT, DOT, SIGN, NEWLINE, BAD = range(7)
_CLASS = np.full(256, BAD, np.uint8)
_CLASS[[ord(c) for c in " \t\r"]] = SPACE
_CLASS[[ord(c) for c in "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"]] = LETTER
_CLASS[[ord(c) for c in "0123456789"]] = DIGIT
_CLASS[ord(".")] = DOT
_CLASS[[ord("+"), ord("-")]] = SIGN
_CLASS[ord("\n")] = NEWLINE
_NUMBERS_ONLY = bytes(c if chr(c) in "0123456789.+-" else 32 for c in range(256))


@dataclass
class Scan:
    """Per-line table of the fast path; rows where ``simple`` is False are unread."""

    simple: np.ndarray  # bool (n,)
    g: np.ndarray  # int8 (n,), motion code 0-3, -1 when none
    units: np.ndarray  # int8 (n,), 1 for G20, 0 for G21, -1 when none
    values: dict[str, np.ndarray]  # letter X Y Z I J F M S -> float64 (n,), NaN when absent


def _chunks(data: bytes):
    """(start, end) byte ranges of about CHUNK_BYTES, each ending after a newline."""
    start = 0
    while start < len(data):
        end = data.find(b"\n", start + CHUNK_BYTES)
        end = len(data) if end < 0 else end + 1
        yield start, end
        start = end


_KIND = np.zeros(256, np.uint8)  # letters 1, newline 3, bad 6; numbers are marked below
_KIND[_CLASS == LETTER] = 1
_KIND[_CLASS == NEWLINE] = 3
_KIND[_CLASS == BAD] = 6
_INNER = np.zeros(256, np.uint8)  # inside a number: a dot is 4, a sign is bad (6)
_INNER[_CLASS == DOT] = 4
_INNER[_CLASS == SIGN] = 6
MAX_TOKEN = 15  # characters of a number the fast path reads (exact in an int64 and a double)
_POW10 = np.array([float(10**i) for i in range(MAX_TOKEN + 1)])




def _kinds(b: np.ndarray):
    """Positions and kinds (1 letter, 2 number start, 3 newline, 4 dot, 6 bad) in order,
    and the position of the last character of every number. ``b`` ends with a newline."""
    special_mask = (b == 46) | (b == 45) | (b == 43)  # . - +
    isnum = ((b - 48) < 10) | special_mask
    start = np.empty(len(b), bool)
    start[0] = isnum[0]
    np.greater(isnum[1:], isnum[:-1], out=start[1:])
    end = np.empty(len(b), bool)
    end[-1] = False
    np.greater(isnum[:-1], isnum[1:], out=end[:-1])
    t = np.take(_KIND, b)
    t |= start.view(np.uint8) << 1
    special = np.flatnonzero(special_mask)
    inner = special[(special > 0) & isnum[special - 1]]
    t[inner] = np.take(_INNER, b[inner])
    pos = np.flatnonzero(t != 0)  # much faster than nonzero() of a uint8 array
    return pos, t[pos], np.flatnonzero(end)


def _bad_tokens(b, pos, k, ends) -> np.ndarray:
    """Mask over ``pos`` of elements that make their line unusable by the fast path."""
    bad = k == 6
    nxt = np.empty_like(k)
    nxt[:-1] = k[1:]
    nxt[-1] = 3
    prv = np.empty_like(k)
    prv[1:] = k[:-1]
    prv[0] = 3
    bad |= (k == 1) & (nxt != 2)
    bad |= (k == 2) & (prv != 1)
    bad |= (k == 4) & (prv == 4)
    is_start = np.flatnonzero(k == 2)
    starts = pos[is_start]
    first = np.take(_CLASS, b[starts])
    c1 = np.take(_CLASS, b[starts + 1])  # the chunk ends with a newline, never inside a number
    c2 = np.take(_CLASS, b[np.minimum(starts + 2, len(b) - 1)])
    ok = (first == DIGIT) | ((first == DOT) & (c1 == DIGIT))
    ok |= (first == SIGN) & ((c1 == DIGIT) | ((c1 == DOT) & (c2 == DIGIT)))
    bad[is_start[~ok | (ends - starts >= MAX_TOKEN)]] = True
    dot_start = is_start[first == DOT]
    after = dot_start + 1
    after = after[after < len(k)]
    bad[after[k[after] == 4]] = True
    return bad


def _line_of(k: np.ndarray) -> np.ndarray:
    nl = k == 3
    return np.cumsum(nl) - nl


def _values(text: bytes, b, pos, k, ends, good) -> np.ndarray:
    """The numbers of the good tokens: digits read as one integer, divided by 10**decimals.

    Both operands are exact, so the quotient is the correctly rounded value: the same
    double ``float()`` gives for the text (up to the sign of zero, restored here).
    """
    numbers = text.translate(_NUMBERS_ONLY, b".")
    if not numbers.strip():
        return np.empty(0)
    mantissa = np.fromstring(numbers, dtype=np.int64, sep=" ")
    first = np.flatnonzero(k == 2)
    starts = pos[first]
    after = np.minimum(first + 1, len(k) - 1)  # on a good line a dot inside follows its start
    dot = np.where(k[after] == 4, pos[after], np.where(b[starts] == ord("."), starts, -1))
    decimals = np.where(dot >= 0, ends - dot, 0)
    keep = good[first]
    value = mantissa / _POW10[decimals[keep]]
    return np.copysign(value, np.where(b[starts[keep]] == ord("-"), -1.0, 1.0))


def _scan_chunk(raw: bytes, n_lines: int):
    """Words of the good lines of one chunk: (odd mask, line, letter, value)."""
    text = _COMMENT.sub(b" ", raw) if b"(" in raw else raw
    text = _SEMI.sub(b"", text) if b";" in text else text
    b = np.frombuffer(text, np.uint8)
    pos, k, ends = _kinds(b)
    line = _line_of(k)
    odd = np.zeros(n_lines, bool)
    odd[line[_bad_tokens(b, pos, k, ends)]] = True
    if odd.any():
        text = _blank_lines(text, pos[k == 3], odd)
    good = ~odd[line]
    values = _values(text, b, pos, k, ends, good)
    letters = b[pos[(k == 1) & good]] & 0xDF
    if len(values) != len(letters):  # cannot happen for well-formed tokens; be safe
        return np.ones(n_lines, bool), *(np.empty(0, t) for t in (np.int64, np.uint8, np.float64))
    return odd, line[(k == 1) & good], letters, values


def _blank_lines(text: bytes, newlines: np.ndarray, odd: np.ndarray) -> bytes:
    buf = bytearray(text)
    starts = np.concatenate(([0], newlines + 1))
    for i in np.flatnonzero(odd):
        buf[starts[i] : newlines[i]] = b" " * int(newlines[i] - starts[i])
    return bytes(buf)


_COLUMN = np.full(256, -1, np.int8)  # word letter -> column of the table; N is read and dropped
for _i, _c in enumerate(COLUMNS):
    _COLUMN[[ord(_c), ord(_c.lower())]] = _i
_COLUMN[[ord("N"), ord("n")]] = -2


def _fill(table: np.ndarray, simple: np.ndarray, base: int, odd, line, letters, values) -> None:
    """Write one chunk's words into the table (one scatter); flag other letters and repeats."""
    n = len(odd)
    ok = ~odd
    col = np.take(_COLUMN, letters)
    ok[line[col == -1]] = False
    keep = col >= 0
    flat = line[keep] * len(COLUMNS) + col[keep]
    counts = np.bincount(flat, minlength=n * len(COLUMNS))
    ok[flat[counts[flat] > 1] // len(COLUMNS)] = False
    table.reshape(-1)[base * len(COLUMNS) + flat] = values[keep]
    simple[base : base + n] = ok


def _classify(result: Scan, table: np.ndarray) -> None:
    """G codes into motion and units; M 3 or 5 and S only on lines without motion words."""
    g = table[:, 0]
    motion = (g == 0) | (g == 1) | (g == 2) | (g == 3)
    units = (g == 20) | (g == 21)
    result.simple &= np.isnan(g) | motion | units
    result.g = np.where(motion, g, -1).astype(np.int8)
    result.units = np.where(units, g == 20, -1).astype(np.int8)
    m, s = result.values["M"], result.values["S"]
    spindle = ~np.isnan(m) | ~np.isnan(s)
    bad_m = ~np.isnan(m) & (m != 3) & (m != 5)
    moving = motion | ~np.isnan(table[:, 1:7]).all(axis=1)  # X Y Z I J F
    result.simple &= ~(bad_m | (spindle & moving))


def scan(data: bytes, n_lines: int) -> Scan:
    """Scan ``data`` (``n_lines`` lines joined by newlines) with the fast path."""
    table = np.full((n_lines, len(COLUMNS)), np.nan)
    simple = np.zeros(n_lines, bool)
    if not data.endswith(b"\n"):
        data += b"\n"
    base = 0
    for start, end in _chunks(data):
        raw = data[start:end]
        count = raw.count(b"\n")
        _fill(table, simple, base, *_scan_chunk(raw, count))
        base += count
    result = Scan(simple, np.empty(0, np.int8), np.empty(0, np.int8),
                  {c: table[:, i] for i, c in enumerate(COLUMNS) if c != "G"})
    _classify(result, table)
    return result
