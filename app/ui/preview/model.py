"""What the preview shows, apart from how it is drawn (no Qt).

``PreviewModel(toolpath)`` splits the path into drawing groups (rapids, cuts above
the stock, depth bands), each a ``LodSegments``; the finished part is the same
segments cut at a move. ``frame(view, pixel)`` gives the arrays to draw for a view.
"""

from __future__ import annotations

import numpy as np

from app.gcode.threads import each_on
from app.ui.preview.geometry import RAPID_GROUP, PathGeometry
from app.ui.preview.lod import LodSegments, group_segments

FIT_MARGIN = 0.03
FRAME_BUDGET = 50_000  # segments drawn per frame, shared by the groups
MIN_BUDGET = 4_096


class PreviewModel:
    def __init__(self, toolpath, tolerance: float = 0.01, threads: int = 2):
        """``threads``: 1 when built in the background while the window is in use (a
        second busy thread would make each redraw wait longer for the GIL)."""
        self.toolpath = toolpath
        self.tolerance = tolerance
        self.threads = threads
        self.geometry = PathGeometry.from_toolpath(toolpath, tolerance, threads)
        g = self.geometry
        parts = group_segments(g.points, g.move, g.group, g.group_count)
        self.groups = [LodSegments(seg, move) for seg, move in parts]
        self.device_index = _device_index(toolpath)
        self._bounds = _bounds(self.geometry.points)
        self.levels_built = False  # every level of every group (build_all)

    @property
    def empty(self) -> bool:
        return len(self.geometry.points) == 0

    def bounds(self) -> tuple[float, float, float, float]:
        """xmin, xmax, ymin, ymax of every vertex (the extents of what is plotted)."""
        return self._bounds

    def fitted_range(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """The X and Y range a view fitted to the program shows (3 % margin)."""
        xmin, xmax, ymin, ymax = self.bounds()
        pad = max(xmax - xmin, ymax - ymin, 1.0) * FIT_MARGIN
        return (xmin - pad, xmax + pad), (ymin - pad, ymax + pad)

    def frame(self, view, pixel: float, wait: bool = True):
        """A list of (x, y) point pairs per group for this view. ``wait=False``: use the
        nearest level already built rather than build one now (see ``levels_built``)."""
        return [group.visible(view, pixel, self._budget(group), wait=wait) for group in self.groups]

    def _budget(self, group) -> int:
        total = max(sum(len(g) for g in self.groups), 1)
        return max(MIN_BUDGET, FRAME_BUDGET * len(group) // total)

    def done_frame(self, view, pixel: float, upto_move: int, wait: bool = True):
        """(x, y) point pairs of every segment of moves up to ``upto_move``, all groups."""
        if upto_move < 0:
            return np.zeros(0), np.zeros(0)
        parts = [g.visible(view, pixel, self._budget(g), upto=upto_move, wait=wait) for g in self.groups[1:]]
        return np.concatenate([p[0] for p in parts]), np.concatenate([p[1] for p in parts])

    def recent_segments(self, after_move: int, upto_move: int):
        """(x, y) point pairs of the cut segments of moves ``after_move+1 .. upto_move``."""
        g = self.geometry
        lo = int(np.searchsorted(g.move[1:], after_move + 1, "left"))
        hi = int(np.searchsorted(g.move[1:], upto_move, "right"))
        ends = np.arange(lo + 1, hi + 1)
        ends = ends[g.group[ends] != RAPID_GROUP]
        x = np.column_stack([g.points[ends - 1, 0], g.points[ends, 0]]).ravel()
        y = np.column_stack([g.points[ends - 1, 1], g.points[ends, 1]]).ravel()
        return x, y

    def move_of_device_line(self, seq: int) -> int:
        """The last move produced by device lines up to ``seq`` (-1 when none)."""
        if self.device_index is None:
            return seq
        return int(np.searchsorted(self.device_index, seq, "right")) - 1

    def move_of_source_line(self, line: int) -> int | None:
        source = getattr(self.toolpath, "source_line", None)
        if source is None or not len(source):
            return None
        hits = np.flatnonzero(np.asarray(source) == line)
        return int(hits[0]) if len(hits) else None

    def warm(self, size: tuple[float, float]) -> None:
        """Build the levels a view of ``size`` pixels fitted to the program asks for first."""
        if self.empty:
            return
        (x0, x1), (y0, y1) = self.fitted_range()
        pixel = max((x1 - x0) / max(size[0], 1.0), (y1 - y0) / max(size[1], 1.0))  # aspect locked
        self._each(lambda group: group.visible((x0, x1, y0, y1), pixel, self._budget(group)),
                   sorted(self.groups, key=len, reverse=True))

    def _each(self, fn, items) -> list:
        """``[fn(item) for item in items]``, on two threads unless ``threads`` is 1."""
        return each_on(self.threads)(fn, items, "preview")

    def build_all(self) -> None:
        """Build every level of detail of every group (zooming then never waits)."""
        for polyline in self.groups:
            polyline.build_all()
        self.levels_built = True


def screen_tolerance(toolpath, size: tuple[float, float], tolerance: float) -> float:
    """The chord tolerance a view of ``size`` pixels fitted to the program can show:
    half a pixel, never finer than ``tolerance``. The program's extent is that of its
    moves' ends (arcs may bulge past them: the real pixel is then a little larger, and
    the tolerance finer than half of it, never coarser), with no pass over the arcs."""
    ends = toolpath.end
    spans = [float(np.ptp(ends[:, axis])) if len(ends) else 0.0 for axis in (0, 1)]
    pad = 2 * max(*spans, 1.0) * FIT_MARGIN  # as fitted_range pads
    pixel = max((span + pad) / max(side, 1.0) for span, side in zip(spans, size, strict=True))
    return max(tolerance, pixel / 2)


def _bounds(points: np.ndarray) -> tuple[float, float, float, float]:
    if not len(points):
        return (0.0, 0.0, 0.0, 0.0)
    x, y = points[:, 0], points[:, 1]  # a column at a time: numpy reduces (n, 3) along
    return (float(x.min()), float(x.max()), float(y.min()), float(y.max()))  # rows 30x slower


def _device_index(toolpath):
    index = getattr(toolpath, "device_index", None)
    return None if index is None else np.asarray(index)
