"""Level of detail for many line segments (no Qt).

A ``LodSegments`` holds segments (x0, y0, x1, y1) in program order with the move each
belongs to. A level for a cell size keeps one segment per pair of (start cell, end
cell) — the first one in program order — so a path that passes over the same spot a
thousand times is drawn once, and the number of segments of a level is bounded by
the cells the path covers, not by the length of the file. Every level is cut into
chunks with a bounding box; ``visible(view, pixel, budget)`` returns the segments of
the chunks that meet the view, at the finest level whose cell is no larger than a
pixel and whose visible part fits the budget. A level is built from the next finer
one already built when there is one, so the coarser levels cost little.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

import numpy as np

CHUNK = 512
PACKED_BITS = 64  # a level's sort packs a key and an index into one uint64 when they fit
LEVEL_STEPS = range(13, 5, -1)  # cells of extent / 2**k, finest first
_EMPTY = np.zeros(0)


@dataclass(frozen=True)
class Level:
    cell: float
    seg: np.ndarray  # (n, 4) float32: x0, y0, x1, y1
    move: np.ndarray  # (n,) int32, non-decreasing
    boxes: np.ndarray  # (chunks, 4): xmin, xmax, ymin, ymax


class LodSegments:
    def __init__(self, seg: np.ndarray, move: np.ndarray):
        self._raw = (np.asarray(seg, np.float32), np.asarray(move, np.int32))  # not copied when so
        extent = 1e-6
        if len(seg):
            xmin, xmax, ymin, ymax = _extent(self._raw[0])
            extent = max(float(xmax - xmin), float(ymax - ymin), extent)
        self.cells = [0.0] + [extent / 2**k for k in LEVEL_STEPS]
        self._levels: dict[int, Level] = {}
        self._locks = [threading.Lock() for _ in self.cells]

    def __len__(self) -> int:
        return len(self._raw[1])

    def level(self, index: int) -> Level:
        with self._locks[index]:
            if index not in self._levels:
                self._levels[index] = _build_level(*self._source(index), self.cells[index])
            return self._levels[index]

    def _source(self, index: int):
        """The segments a level is built from: the nearest finer level already built
        (cells nest, each twice the last: its representatives are those of the raw
        segments, from far fewer), else the raw segments."""
        finer = [i for i in self._levels if 0 < i < index]
        if not finer:
            return self._raw
        level = self._levels[max(finer)]
        return level.seg, level.move

    def build_all(self) -> None:
        """Build every level, finest first (each coarser one from the one before)."""
        for index in range(len(self.cells)):
            self.level(index)

    def pick_level(self, pixel: float) -> int:
        """The coarsest level whose cell is no larger than one pixel."""
        fits = [i for i, cell in enumerate(self.cells) if cell <= pixel]
        return fits[-1] if fits else 0

    def visible(self, view, pixel: float, budget: int, upto: int | None = None, wait: bool = True):
        """(x, y) point pairs to draw for ``view`` = (xmin, xmax, ymin, ymax). With
        ``wait=False`` a level not built yet is replaced by the nearest built one."""
        if not len(self):
            return _EMPTY, _EMPTY
        index = self._usable(self.pick_level(pixel), wait)
        while True:
            level = self.level(index)
            chunks, end = _chunks_in_view(level, view, upto)
            coarser = self._usable(index + 1, wait) if index + 1 < len(self.cells) else None
            if len(chunks) * CHUNK <= budget or coarser is None or coarser <= index:
                return _gather(level, chunks, end)
            index = coarser

    def _usable(self, index: int, wait: bool) -> int:
        """``index``, or when not waiting and it is not built, the nearest built level
        (the coarser on a tie; ``index`` itself when none is built)."""
        built = list(self._levels)
        if wait or index in self._levels or not built:
            return index
        return min(built, key=lambda i: (abs(i - index), i < index))


def _build_level(seg, move, cell) -> Level:
    if cell > 0 and len(seg):
        keep = _representatives(seg, cell)
        seg, move = seg[keep], move[keep]
    return Level(cell, seg, move, _chunk_boxes(seg))


def _representatives(seg, cell):
    """Indices (in program order) of the first segment of every (start cell, end cell)
    pair, and of the segments that reach the extremes (a level spans what the path does)."""
    keep = np.zeros(len(seg), bool)
    keep[_firsts(*_pair_keys(seg, cell))] = True
    for column in range(4):
        keep[np.argmin(seg[:, column])] = keep[np.argmax(seg[:, column])] = True
    return np.flatnonzero(keep)  # program order, with no sort


def _firsts(key, bound: int):
    """Indices of the first occurrence of every value of ``key`` (each in ``0 .. bound-1``),
    in no particular order. When a key and an index fit in PACKED_BITS, one sort of the
    values ``key << bits | index`` (4x faster than a stable argsort: a value sort is
    vectorised); otherwise an argsort, and the least index of each run of equal keys."""
    if not len(key):
        return np.zeros(0, np.intp)
    bits = max(len(key) - 1, 1).bit_length()
    if bound << bits <= 1 << PACKED_BITS:
        packed = key.view(np.uint64) << np.uint64(bits)
        packed |= np.arange(len(key), dtype=np.uint64)
        packed.sort()
        return (packed[_run_starts(packed >> np.uint64(bits))] & np.uint64((1 << bits) - 1)).astype(np.intp)
    order = np.argsort(key)
    return np.minimum.reduceat(order, np.flatnonzero(_run_starts(key[order])))


def _run_starts(ordered):
    """True where a sorted array's value differs from the one before (and at 0)."""
    starts = np.empty(len(ordered), bool)
    starts[0] = True
    np.not_equal(ordered[1:], ordered[:-1], out=starts[1:])
    return starts


def _pair_keys(seg, cell):
    """One int64 per segment naming its (start cell, end cell) pair, cells of ``cell``
    from the lowest corner, and the number of keys there can be (the product of the
    cells a side, twice: at most (2**13 + 1)**4 for the finest level)."""
    xmin, _, ymin, _ = _extent(seg)
    key = np.zeros(len(seg), np.int64)
    scratch = np.empty(len(seg), seg.dtype)
    cells = np.empty(len(seg), np.int64)
    bound = 1
    for column, origin in ((0, xmin), (1, ymin), (2, xmin), (3, ymin)):
        np.subtract(seg[:, column], origin, out=scratch)
        scratch /= cell
        np.copyto(cells, scratch, casting="unsafe")  # truncated: cell indices from 0
        side = int(cells.max()) + 1
        key *= side
        key += cells
        bound *= side
    return key, bound


def _extent(seg):
    """xmin, xmax, ymin, ymax of the segments' ends (a column at a time: no copies)."""
    xs, ys = (seg[:, 0], seg[:, 2]), (seg[:, 1], seg[:, 3])
    return (min(c.min() for c in xs), max(c.max() for c in xs),
            min(c.min() for c in ys), max(c.max() for c in ys))


def _chunk_boxes(seg):
    count = -(-len(seg) // CHUNK)
    if count == 0:
        return np.zeros((0, 4))
    pad = np.full((count * CHUNK - len(seg), 4), np.nan, dtype=seg.dtype)
    body = np.concatenate([seg, pad]).reshape(count, CHUNK, 4)
    xs = body[:, :, [0, 2]].reshape(count, -1)
    ys = body[:, :, [1, 3]].reshape(count, -1)
    lo_hi = [np.fmin.reduce(xs, axis=1), np.fmax.reduce(xs, axis=1)]
    lo_hi += [np.fmin.reduce(ys, axis=1), np.fmax.reduce(ys, axis=1)]
    return np.column_stack(lo_hi)


def _chunks_in_view(level: Level, view, upto):
    xmin, xmax, ymin, ymax = view
    b = level.boxes
    hit = (b[:, 0] <= xmax) & (b[:, 1] >= xmin) & (b[:, 2] <= ymax) & (b[:, 3] >= ymin)
    chunks = np.flatnonzero(hit)
    end = len(level.move)
    if upto is not None:
        end = int(np.searchsorted(level.move, upto, "right"))
        chunks = chunks[chunks * CHUNK < end]
    return chunks, end


def _gather(level: Level, chunks, end):
    if not len(chunks):
        return _EMPTY, _EMPTY
    idx = (chunks[:, None] * CHUNK + np.arange(CHUNK)[None, :]).ravel()
    idx = idx[idx < end]
    seg = level.seg[idx]
    return seg[:, [0, 2]].ravel().astype(float), seg[:, [1, 3]].ravel().astype(float)


def group_segments(points: np.ndarray, move: np.ndarray, group: np.ndarray, count: int):
    """The segments of each drawing group ``0 .. count-1``, in program order: a list of
    ((n, 4) float32 x0, y0, x1, y1; (n,) int32 moves). Vertex ``i > 0`` ends a segment
    of group ``group[i]``."""
    pairs = np.empty((len(points), 4), np.float32)  # row i: the segment that ends at vertex i
    pairs[1:, 0:2] = points[:-1, :2]
    pairs[1:, 2:4] = points[1:, :2]
    ends = np.argsort(group[1:], kind="stable") + 1  # (int8: a linear sort) each group in order
    sizes = np.bincount(group[1:], minlength=count)
    move = np.asarray(move, np.int32)
    return [(pairs.take(part, axis=0), move.take(part)) for part in np.split(ends, np.cumsum(sizes)[:-1])]
