"""A block of stock as a height map, cut by a flat end mill move by move (issue 19).

The map holds, per cell of ``GRID`` mm, the height of the material left (``-inf``:
no material there). Every motion move is sampled (``toolcheck.samples``) and every
sample lowers the cells under the tool disk to its height; before that the move is
judged by the rules every feature keeps:

- no rapid goes down below the stock top or sideways below it (straight up out of the
  cut is a rapid);
- no vertical feed down into material (a plunge), except where the feature drills
  (``drilling=True``: holes);
- a move that goes down while it cuts material descends at most ``MAX_SLOPE``
  (a ramp or a helix).
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from app.gcode.features.entry import RAMP_SLOPE
from app.gcode.features.moves import RAPID

from .toolcheck import samples

GRID = 0.1  # mm
MAX_SLOPE = RAMP_SLOPE * 1.05 + 1e-6  # arcs sampled by chords descend a little more steeply
EPS = 1e-6


class Stock:
    """Material over ``bounds`` (x0, y0, x1, y1) at ``top`` where ``solid`` (a shapely
    area; None: everywhere), air elsewhere; cut by a tool of ``radius``."""

    def __init__(self, bounds, top: float, radius: float, solid=None) -> None:
        x0, y0, x1, y1 = bounds
        self.xs = np.arange(x0 + GRID / 2, x1, GRID)
        self.ys = np.arange(y0 + GRID / 2, y1, GRID)
        self.top, self.radius = top, radius
        self.height = np.full((len(self.ys), len(self.xs)), top)
        if solid is not None:
            gx, gy = np.meshgrid(self.xs, self.ys)
            self.height[~shapely.contains_xy(solid, gx, gy)] = -np.inf

    def _disk(self, x: float, y: float, radius: float):
        """(rows, cols) slices and the mask of cells within ``radius`` of (x, y)."""
        c0 = max(0, int(np.searchsorted(self.xs, x - radius)))
        c1 = int(np.searchsorted(self.xs, x + radius, "right"))
        r0 = max(0, int(np.searchsorted(self.ys, y - radius)))
        r1 = int(np.searchsorted(self.ys, y + radius, "right"))
        dx = self.xs[c0:c1][None, :] - x
        dy = self.ys[r0:r1][:, None] - y
        return (slice(r0, r1), slice(c0, c1)), dx * dx + dy * dy <= radius * radius

    def material_above(self, x: float, y: float, z: float, shrink: float = 0.02) -> float:
        """How far material under the tool at (x, y) stands above ``z`` (<= 0: none)."""
        cells, mask = self._disk(x, y, self.radius - shrink)
        block = self.height[cells][mask]
        return float(block.max() - z) if block.size else -np.inf

    def cut_at(self, x: float, y: float, z: float) -> None:
        cells, mask = self._disk(x, y, self.radius)
        view = self.height[cells]
        view[mask] = np.minimum(view[mask], z)

    def run(self, moves, start, drilling: bool = False) -> list[str]:
        """Cut ``moves`` from ``start``; the broken rules, one text per move."""
        bad = []
        motion = [m for m in moves if m.kind in ("rapid", "feed", "arc")]
        for (kind, pts), move in zip(samples(moves, start), motion, strict=True):
            a, b = pts[0], pts[-1]
            flat = math.dist(a[:2], b[:2])
            if kind == RAPID:
                down = b[2] < min(a[2], self.top) - EPS
                if down or (flat > EPS and min(a[2], b[2]) < self.top - EPS):
                    bad.append(f"rapid below the top to {b} ({move.note})")
                continue
            cuts = any(self.material_above(*p) > EPS for p in pts[1:])
            if cuts and b[2] < a[2] - EPS:
                if flat < EPS and not drilling:
                    bad.append(f"plunge into material to {b} ({move.note})")
                elif flat >= EPS and (a[2] - b[2]) / _length(pts) > MAX_SLOPE:
                    bad.append(f"descent steeper than a ramp to {b} ({move.note})")
            for p in pts:
                self.cut_at(*p)
        return bad

    def heights(self, area) -> np.ndarray:
        """The material heights of the cells whose centres lie in ``area``."""
        return self.height[self.cells(area)]

    def cells(self, area) -> np.ndarray:
        gx, gy = np.meshgrid(self.xs, self.ys)
        return shapely.contains_xy(area, gx, gy)

    def left_above(self, area, level: float) -> int:
        """Cells in ``area`` above ``level`` whose four neighbours are too: stock wider
        than a cell (a sliver between two sweeps that only touch is not counted)."""
        high = self.cells(area) & (self.height > level)
        thick = high.copy()
        thick[1:, :] &= high[:-1, :]
        thick[:-1, :] &= high[1:, :]
        thick[:, 1:] &= high[:, :-1]
        thick[:, :-1] &= high[:, 1:]
        return int(thick.sum())


def _length(pts) -> float:
    return sum(math.dist(p[:2], q[:2]) for p, q in zip(pts, pts[1:], strict=False)) or 1e-12
