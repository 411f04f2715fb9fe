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
        self._raw = (seg.astype(np.float32), move.astype(np.int32))
        extent = 1e-6
        if len(seg):
            extent = max(np.ptp(seg[:, [0, 2]]), np.ptp(seg[:, [1, 3]]), extent)
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
    """Indices (in program order) of the first segment of every (start cell, end cell) pair."""
    ox = min(seg[:, 0].min(), seg[:, 2].min())
    oy = min(seg[:, 1].min(), seg[:, 3].min())
    q = np.empty((len(seg), 4), dtype=np.int64)
    for col, origin in ((0, ox), (1, oy), (2, ox), (3, oy)):
        q[:, col] = ((seg[:, col] - origin) / cell).astype(np.int64)
    key = ((q[:, 0] * 16411 + q[:, 1]) * 16411 + q[:, 2]) * 16411 + q[:, 3]
    order = np.argsort(key)  # (2.5x faster than np.unique(return_index=True))
    ordered = key[order]
    runs = np.flatnonzero(np.concatenate([[True], ordered[1:] != ordered[:-1]]))
    first = np.minimum.reduceat(order, runs)
    extremes = [np.argmin(seg[:, 0]), np.argmax(seg[:, 2]), np.argmin(seg[:, 1]), np.argmax(seg[:, 3])]
    extremes += [np.argmax(seg[:, 0]), np.argmin(seg[:, 2]), np.argmax(seg[:, 1]), np.argmin(seg[:, 3])]
    return np.union1d(first, extremes)  # sorted: program order


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


def group_segments(points: np.ndarray, move: np.ndarray, group: np.ndarray, which: int):
    """The segments of one drawing group: (n, 4) x0, y0, x1, y1 and their moves."""
    ends = np.flatnonzero(group[1:] == which) + 1
    seg = np.empty((len(ends), 4), dtype=np.float32)
    seg[:, 0:2] = points[ends - 1, :2]
    seg[:, 2:4] = points[ends, :2]
    return seg, move[ends]
