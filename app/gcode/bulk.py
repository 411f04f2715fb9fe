"""The fast path: read every plain line of a program at once, with numpy.

``scan(data)`` takes the whole source as bytes and returns a ``Scan``: one row per
physical line with the motion code ``g`` (G0-G3), the ``units`` code (G20 = 1,
G21 = 0), the values of X, Y, Z, I, J, F, M (3 or 5 only) and S (NaN when absent) and
a ``simple`` flag. A line is simple when it holds only those words (and N), each at
most once, well formed, with nothing but spaces and well-closed comments around them,
and M or S only on a line with no motion word: the shape of nearly every line
Inkscape's Gcodetools writes (``tokens.py`` gives the byte-level rules). Every other
line is left to the general lexer and interpreter, which are the reference; the tests
check that both paths agree.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from .clean import quick
from .source import chunks as chunk_table
from .tokens import numbers, tokenize

COLUMNS = "GXYZIJFMS"  # the words of a simple line (and N, read and dropped)
_COMMENT = re.compile(rb"\([^()\n]*\)")
COMMENT_MARK = b"\x01"  # a comment separates words: "X1(c)0" is not X10
_SEMI = re.compile(rb";[^\n]*")

@dataclass
class Scan:
    """Per-line table of the fast path; rows where ``simple`` is False are unread."""

    simple: np.ndarray  # bool (n,)
    g: np.ndarray  # int8 (n,), motion code 0-3, -1 when none
    units: np.ndarray  # int8 (n,), 1 for G20, 0 for G21, -1 when none
    values: dict[str, np.ndarray]  # letter X Y Z I J F M S -> float64 (n,), NaN when absent


def _scan_chunk(raw: bytes, n_lines: int):
    """Words of the good lines of one chunk: (odd mask, line, letter, value)."""
    if b"\x01" in raw:  # the comment mark below must not occur in the source
        return np.ones(n_lines, bool), *(np.empty(0, t) for t in (np.int64, np.uint8, np.float64))
    text = raw.translate(None, b" \t\r")  # rs274ngc ignores spaces: "X 1 0" is X10
    text = _COMMENT.sub(COMMENT_MARK, text) if b"(" in text else text  # (spaces inside are gone too)
    text = _SEMI.sub(b"", text) if b";" in text else text
    b = np.frombuffer(text, np.uint8)
    clean = quick(text)
    if clean is not None:  # nearly every chunk: no line needs the general lexer
        tk, line = clean
        return np.zeros(n_lines, bool), line, b[tk.letters], numbers(text, b, tk)
    tk = tokenize(b)
    odd = np.zeros(n_lines, bool)
    if len(tk.bad):
        odd[np.searchsorted(tk.newlines, tk.bad)] = True
        text = _blank_lines(text, tk.newlines, odd)
        b = np.frombuffer(text, np.uint8)
        tk = tokenize(b)
    if len(tk.bad) or len(tk.letters) != len(tk.starts):  # cannot happen once blanked; be safe
        return np.ones(n_lines, bool), *(np.empty(0, t) for t in (np.int64, np.uint8, np.float64))
    line = np.searchsorted(tk.newlines, tk.letters)
    return odd, line, b[tk.letters], numbers(text, b, tk)


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
_COLUMN_TABLE = _COLUMN.tobytes()


def _fill(table: np.ndarray, simple: np.ndarray, base: int, odd, line, letters, values) -> None:
    """Write one chunk's words into the table (one scatter); flag other letters and repeats."""
    n = len(odd)
    ok = ~odd
    col = np.frombuffer(letters.tobytes().translate(_COLUMN_TABLE), np.int8)
    if (col < 0).any():  # N words (dropped) or letters a simple line never holds
        ok[line[col == -1]] = False
        keep = col >= 0
        line, col, values = line[keep], col[keep], values[keep]
    flat = line * len(COLUMNS) + col
    counts = np.bincount(flat, minlength=n * len(COLUMNS))
    if counts.max(initial=0) > 1:
        ok[flat[counts[flat] > 1] // len(COLUMNS)] = False
    table.reshape(-1)[col.astype(np.intp) * table.shape[1] + (base + line)] = values
    simple[base : base + n] = ok


def _classify(result: Scan, table: np.ndarray) -> None:
    """G codes into motion and units; M 3 or 5 and S only on lines without motion words."""
    g = table[0]
    motion = (g == 0) | (g == 1) | (g == 2) | (g == 3)
    units = (g == 20) | (g == 21)
    result.simple &= np.isnan(g) | motion | units
    result.g = np.where(motion, g, -1).astype(np.int8)
    result.units = np.where(units, g == 20, -1).astype(np.int8)
    m, s = result.values["M"], result.values["S"]
    spindle = ~np.isnan(m) | ~np.isnan(s)
    bad_m = ~np.isnan(m) & (m != 3) & (m != 5)
    moving = motion | ~np.isnan(table[1:7]).all(axis=0)  # X Y Z I J F
    result.simple &= ~(bad_m | (spindle & moving))


def scan(data: bytes, n_lines: int, chunks: list | None = None) -> Scan:
    """Scan ``data`` (``n_lines`` lines joined by newlines) with the fast path;
    ``chunks``, when given, is ``source.chunks(data)`` (data ending with a newline)."""
    table = np.full((len(COLUMNS), n_lines), np.nan)  # one contiguous row per letter
    simple = np.zeros(n_lines, bool)
    if not data.endswith(b"\n"):
        data, chunks = data + b"\n", None
    base = 0
    for start, end, count in chunks or chunk_table(data):
        raw = data[start:end]
        _fill(table, simple, base, *_scan_chunk(raw, count))
        base += count
    result = Scan(simple, np.empty(0, np.int8), np.empty(0, np.int8),
                  {c: table[i] for i, c in enumerate(COLUMNS) if c != "G"})
    _classify(result, table)
    return result
