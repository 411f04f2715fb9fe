"""The fast path: read every plain line of a program at once, with numpy.

``scan(data)`` takes the whole source as bytes and returns a ``Scan``: one row per
physical line with the motion code ``g`` (G0-G3), the ``units`` code (G20 = 1,
G21 = 0), the values of X, Y, Z, I, J, F, M (3 or 5 only) and S (NaN when absent) and
a ``simple`` flag. A line is simple when it holds only those words (and N), each at
most once, well formed, with nothing but spaces and well-closed comments around them
(and perhaps a leading ``/``, block delete, flagged in ``deleted``, or a ``*checksum``
at its end), and M or S only on a line with no motion word: the shape of nearly every line
Inkscape's Gcodetools writes (``tokens.py`` gives the byte-level rules). Every other
line is left to the general lexer and interpreter, which are the reference; the tests
check that both paths agree. ``scan_stream`` yields the table a window of lines at a
time (``Scan.first``: the window's first line), so the loader interprets the head of a
big file while its tail is still being read (part of it by the helper process of
``workers.py``, on the second core), and only one window's table (a few MB) is held
at once, never a table of the whole file (72 bytes a line).
"""

from __future__ import annotations

import re
import zlib
from dataclasses import dataclass
from functools import partial

import numpy as np

from . import forked, workers
from .clean import quick
from .sniff import chunk_plain, letters_plain
from .source import chunks as chunk_table
from .tokens import numbers, tokenize

COLUMNS = "GXYZIJFMS"  # the words of a simple line (and N, read and dropped)
_COMMENT = re.compile(rb"\([^()\n]*\)")
COMMENT_MARK = b"\x01"  # a comment separates words: "X1(c)0" is not X10
_SEMI = re.compile(rb";[^\n]*")  # a ";" comment ends the words of a line,
_CHECKSUM = re.compile(rb"\*[^\n]*")  # and so does a "*checksum" (not one [;*] pattern: a literal
# first byte is searched far faster than a class)
SHARE_BYTES = 8 << 20  # a file this big has its tail scanned by the helper process (workers.py)
WINDOW_BYTES = 4 << 20  # source bytes of one window of the table (about 85,000 lines, 6 MB of table)
HELPER_GROUPS = 32  # a shared file is scanned in this many runs of chunks (see scan_stream)

@dataclass
class Scan:
    """Per-line table of the fast path for lines ``first .. first + n`` (row ``k`` is
    line ``first + k``, 0-based); rows where ``simple`` is False are unread."""

    simple: np.ndarray  # bool (n,)
    g: np.ndarray  # int8 (n,), motion code 0-3, -1 when none
    units: np.ndarray  # int8 (n,), 1 for G20, 0 for G21, -1 when none
    values: dict[str, np.ndarray]  # letter X Y Z I J F M S -> float64 (n,), NaN when absent
    first: int = 0
    plain: bool = True  # every chunk read shows the program needs no expander (``sniff.chunk_plain``)
    deleted: np.ndarray | None = None  # bool (n,): the line starts with "/" (block delete); None: none does


def _table(first: int, n: int) -> tuple[Scan, np.ndarray]:
    """An empty window of ``n`` lines from line ``first`` and its (9, n) table of values."""
    table = np.full((len(COLUMNS), n), np.nan)  # one contiguous row per letter
    window = Scan(np.zeros(n, bool), np.full(n, -1, np.int8), np.full(n, -1, np.int8),
                  {c: table[i] for i, c in enumerate(COLUMNS) if c != "G"}, first, deleted=np.zeros(n, bool))
    return window, table


_NO_LINES = np.empty(0, np.int64)


def _scan_chunk(raw: bytes, n_lines: int):
    """Words of the good lines of one chunk: (odd mask, line, letter, value, lines that
    start with "/", plain), with ``plain`` as ``sniff.chunk_plain`` (from the words'
    letters when every line is clean)."""
    if b"\x01" in raw:  # the comment mark below must not occur in the source
        return np.ones(n_lines, bool), *(np.empty(0, t) for t in (np.int64, np.uint8, np.float64)), \
            _NO_LINES, False
    text = raw.translate(None, b" \t\r")  # rs274ngc ignores spaces: "X 1 0" is X10
    text = _COMMENT.sub(COMMENT_MARK, text) if b"(" in text else text  # (spaces inside are gone too)
    text = _SEMI.sub(b"", text) if b";" in text else text
    text = _CHECKSUM.sub(b"", text) if b"*" in text else text
    text, deleted = _block_delete(text) if b"/" in text else (text, _NO_LINES)
    b = np.frombuffer(text, np.uint8)
    clean = quick(text)
    if clean is not None:  # nearly every chunk: no line needs the general lexer
        tk, line = clean
        letters = b[tk.letters]
        return np.zeros(n_lines, bool), line, letters, numbers(text, b, tk), deleted, \
            letters_plain(letters.tobytes())
    plain = chunk_plain(raw)
    tk = tokenize(b)
    odd = np.zeros(n_lines, bool)
    if len(tk.bad):
        odd[np.searchsorted(tk.newlines, tk.bad)] = True
        text = _blank_lines(text, tk.newlines, odd)
        b = np.frombuffer(text, np.uint8)
        tk = tokenize(b)
    if len(tk.bad) or len(tk.letters) != len(tk.starts):  # cannot happen once blanked; be safe
        return np.ones(n_lines, bool), *(np.empty(0, t) for t in (np.int64, np.uint8, np.float64)), \
            deleted, plain
    line = np.searchsorted(tk.newlines, tk.letters)
    return odd, line, b[tk.letters], numbers(text, b, tk), deleted, plain


def _block_delete(text: bytes) -> tuple[bytes, np.ndarray]:
    """``text`` without the "/" that starts a line (block delete; the lexer's ``skip``),
    and the lines that had one. A "/" anywhere else stays: the general lexer refuses it."""
    b = np.frombuffer(text, np.uint8)
    slash = np.flatnonzero(b == ord("/"))
    lead = slash[b[slash - 1] == ord("\n")]  # (index -1 is the chunk's last newline)
    return np.delete(b, lead).tobytes(), np.searchsorted(np.flatnonzero(b == ord("\n")), lead)


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


def _fill(window: Scan, table: np.ndarray, base: int, odd, line, letters, values, deleted) -> None:
    """Write one chunk's words into the table (one scatter); flag other letters and repeats."""
    n, simple = len(odd), window.simple
    window.deleted[base + deleted] = True
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


def _classify(result: Scan, table: np.ndarray, a: int, b: int) -> None:
    """Lines ``a..b``: G codes into motion and units; M 3 or 5 and S only on lines
    without motion words."""
    g = table[0, a:b]
    motion = (g == 0) | (g == 1) | (g == 2) | (g == 3)
    units = (g == 20) | (g == 21)
    simple = result.simple[a:b]
    simple &= np.isnan(g) | motion | units
    result.g[a:b] = np.where(motion, g, -1)
    result.units[a:b] = np.where(units, g == 20, -1)
    m, s = result.values["M"][a:b], result.values["S"][a:b]
    spindle = ~np.isnan(m) | ~np.isnan(s)
    bad_m = ~np.isnan(m) & (m != 3) & (m != 5)
    moving = motion | ~np.isnan(table[1:7, a:b]).all(axis=0)  # X Y Z I J F
    simple &= ~(bad_m | (spindle & moving))


def scan(data: bytes, n_lines: int, chunks: list | None = None, share_bytes: int | None = None,
         origin: tuple[str, int] | None = None) -> Scan:
    """Scan ``data`` (``n_lines`` lines joined by newlines) with the fast path, the
    whole table at once; ``chunks``, when given, is ``source.chunks(data)`` (data ending
    with a newline); ``origin`` as for ``scan_stream``."""
    result, _ = _table(0, n_lines)
    for window, _ in scan_stream(data, n_lines, chunks, share_bytes, origin):
        rows = slice(window.first, window.first + len(window.simple))
        result.simple[rows], result.g[rows], result.units[rows] = window.simple, window.g, window.units
        result.deleted[rows] = window.deleted
        for letter, column in window.values.items():
            result.values[letter][rows] = column
    return result


def scan_stream(data: bytes, n_lines: int, chunks: list | None = None, share_bytes: int | None = None,
                origin: tuple[str, int] | None = None):
    """``scan`` as it goes: yields ``(window, ready)`` each time lines ``0..ready`` are
    final, ``window`` the ``Scan`` of lines ``window.first..ready`` (a new one each time:
    the caller reads it before asking for the next), at least once.

    Data of ``share_bytes`` (default ``SHARE_BYTES``) or more is shared with the
    helper process when there is one (``Helped``: it scans the groups of chunks in order
    from the second, this process interprets each as it comes and scans the last ones
    itself while it would wait), or in a one-shot load (no helper) with a forked child
    (``forked.Shared``, the same order).
    ``origin``: (path, offset) where ``data`` lies in a file as read: the helper reads its
    groups there (``scan_file_chunks``) rather than be sent them."""
    if not data.endswith(b"\n"):
        data, chunks = data + b"\n", None
    big = len(data) >= (SHARE_BYTES if share_bytes is None else share_bytes)
    parts = chunks or chunk_table(data)
    helper = big and len(parts) >= 2 and workers.ready()
    fork = big and len(parts) >= 2 and not helper and forked.usable()  # a one-shot load
    groups = _split(parts) if helper or fork else _windows(parts)
    firsts = np.cumsum([0] + [sum(count for *_, count in group) for group in groups]).tolist()
    window_of = partial(group_window, data, groups, firsts, n_lines)
    shared = forked.Shared(window_of, len(groups)) if fork else None
    shared = Helped(data, groups, origin, window_of) if helper else shared
    try:
        for k in range(len(groups)):
            yield shared.take(k) if shared else window_of(k), min(firsts[k + 1], n_lines)
    finally:  # (also when the caller stops early: a program that needs the expander)
        if shared:
            shared.close()
    if firsts[-1] < n_lines:  # lines the chunks did not count: none is simple
        yield _table(firsts[-1], n_lines - firsts[-1])[0], n_lines


def group_window(data: bytes, groups: list, firsts: list, n_lines: int, k: int,
                 words_of: list | None = None) -> Scan:
    """The ``Scan`` of group ``k`` of chunks ``(start, end, lines)`` of ``data``, its lines
    from line ``firsts[k]`` on (at most to ``n_lines``); ``words_of``: the group's words when
    already scanned (``scan_chunks``, by the helper process), else they are scanned here."""
    group, first = groups[k], firsts[k]
    words_of = words_of or scan_chunks(data, group)
    window, table = _table(first, min(sum(count for *_, count in group), n_lines - first))
    base = 0
    for (*words, plain), (_, _, count) in zip(words_of, group, strict=True):
        _fill(window, table, base, *words)
        window.plain &= plain
        base += count
    _classify(window, table, 0, len(window.simple))
    return window


def scan_chunks(data: bytes, parts: list) -> list:
    """The words of each chunk ``(start, end, lines)`` of ``data`` (the helper's work)."""
    return [_scan_chunk(data[start:end], count) for start, end, count in parts]


def _split(parts: list) -> list[list]:
    """``parts`` in HELPER_GROUPS runs of chunks (each cut in windows if need be)."""
    size = -(-len(parts) // HELPER_GROUPS)
    return [piece for i in range(0, len(parts), size) for piece in _windows(parts[i : i + size])]


def _windows(parts: list) -> list[list]:
    """``parts`` in runs of chunks of at most about WINDOW_BYTES each (at least one)."""
    out, run, size = [], [], 0
    for part in parts:
        if run and size + part[1] - part[0] > WINDOW_BYTES:
            out.append(run)
            run, size = [], 0
        run.append(part)
        size += part[1] - part[0]
    return [*out, run]


def scan_file_chunks(path: str, offset: int, size: int, parts: list) -> tuple[int, list] | None:
    """(zlib.crc32 of the ``size`` bytes of ``path`` from ``offset``, ``scan_chunks`` of
    them), or None when they cannot be read (the helper's work for a group of a file)."""
    try:
        with open(path, "rb") as file:
            file.seek(offset)
            data = file.read(size)
    except OSError:
        return None
    return (zlib.crc32(data), scan_chunks(data, parts)) if len(data) == size else None


def _submit(data: bytes, group: list, origin: tuple[str, int] | None):
    """The helper's scan of a group: read from the file when ``origin`` says where
    ``data`` lies in one (no copy of the bytes sent), else sent."""
    first, last = group[0][0], group[-1][1]
    parts = [(s - first, e - first, c) for s, e, c in group]
    if origin is None:
        return workers.submit(scan_chunks, data[first:last], parts)
    path, offset = origin
    return workers.submit(scan_file_chunks, path, offset + first, last - first, parts)


class Helped:
    """``window_of(k)`` for groups ``k = 0 .. len(groups) - 1`` of ``data``, taken in
    order by this process, their scans shared with the helper process.

    The helper is handed groups 1, 2, ... in order at once (``_submit``); ``take(k)``
    gives group ``k``'s window from the helper's words when it has sent them. While the
    helper is still on ``k`` (or has it next in its pipe), this process scans the last
    group the helper has not begun instead (withdrawn from it, kept for later), and
    waits only when the helper holds every group left: so the caller interprets each
    group as the helper sends it and neither side stands idle while work is left. A
    group the helper has not sent after ``forked.STUCK_S`` of waiting, failed, or read
    from a file that changed (``_words``) is scanned here: a helper costs time, never
    the result."""

    def __init__(self, data: bytes, groups: list, origin, window_of):
        self._data, self._groups, self._window_of = data, groups, window_of
        self._futures = {k: _submit(data, groups[k], origin) for k in range(1, len(groups))}
        self._ahead: dict[int, list] = {}  # groups scanned here, ahead of their turn
        self._back = len(groups) - 1  # groups after this one are scanned here (or being)

    def take(self, k: int) -> Scan:
        """Group ``k``'s window (groups are taken in order: 0, 1, 2, ...)."""
        if k in self._ahead:
            return self._window_of(k, self._ahead.pop(k))
        future = self._futures.pop(k, None)
        while future is not None and not future.done() and not future.cancel():  # the helper has k
            if not self._scan_ahead(k):
                break  # it has every group left: wait for k
        return self._window_of(k, _words(future, self._data, self._groups[k]))

    def _scan_ahead(self, k: int) -> bool:
        """Scan the last group after ``k`` that the helper has not begun; False when the
        helper has begun (or been sent) every group up to the ones scanned here."""
        while self._back > k:
            j, self._back = self._back, self._back - 1
            future = self._futures.pop(j, None)
            if future is None or future.cancel():
                self._ahead[j] = scan_chunks(self._data, self._groups[j])
                return True
            self._futures[j] = future  # begun: so is every group before it (taken in order)
            self._back = k
        return False

    def close(self) -> None:
        """Withdraw the groups the helper has not begun (the caller stopped early)."""
        for future in self._futures.values():
            future.cancel()


def _words(future, data: bytes, group: list) -> list | None:
    """The helper's words for a group (waiting up to ``forked.STUCK_S`` for them), or
    ``None`` when this process is to scan it: no helper, a failed or slow one, or the
    words of a group it read from a file that no longer holds these bytes (their crc32)."""
    if future is None or future.cancelled():
        return None
    from concurrent.futures import wait

    if not wait([future], timeout=forked.STUCK_S).done:
        future.cancel()
        return None
    words = workers.result(future)
    if not isinstance(words, tuple):
        return words
    first, last = group[0][0], group[-1][1]
    crc, words = words
    return words if crc == zlib.crc32(memoryview(data)[first:last]) else None
