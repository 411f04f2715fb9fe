"""The job's outline as a short program of plain lines (issue 21, "Trace the outline").

``outline_lines(toolpath, feed)`` traces, spindle off, at the job's highest Z (the top
of everything its moves reach: its safe height), the bounding rectangle in X and Y of
the points its moves reach; with ``hull=True`` their convex hull (arcs as chords within
0.01 mm). Work coordinates, as the job's own, so the normal job path (preflight
against the travel, streaming, hold and stop) runs it like any program.
"""

from __future__ import annotations

import numpy as np

from app.gcode.features.paper import fmt
from app.i18n import msg

HULL_TOLERANCE_MM = 0.01


def visited(toolpath) -> np.ndarray:
    """The points (m, 3) the job's moves reach: every end, arcs as chords within
    ``HULL_TOLERANCE_MM``, from the first move in X or Y on (before it the tool stands
    wherever the machine happens to be when the job starts)."""
    points, _ = toolpath.polyline(HULL_TOLERANCE_MM, threads=1)
    if not len(points):
        return points
    moved = np.flatnonzero(np.any(np.abs(points[:, :2] - points[0, :2]) > 1e-9, axis=1))
    return points[moved[0]:] if len(moved) else points[:0]


def rectangle(points: np.ndarray) -> list[tuple[float, float]]:
    """The corners of the XY bounding box of ``points``, counter-clockwise from (xmin, ymin)."""
    (x0, y0), (x1, y1) = points[:, :2].min(axis=0), points[:, :2].max(axis=0)
    return [(float(x0), float(y0)), (float(x1), float(y0)), (float(x1), float(y1)), (float(x0), float(y1))]


def convex_hull(points: np.ndarray) -> list[tuple[float, float]]:
    """The convex hull of XY ``points`` (n, 2), counter-clockwise, no repeated corner
    (Andrew's monotone chain)."""
    pts = sorted({(float(x), float(y)) for x, y in points})
    if len(pts) < 3:
        return pts

    def half(seq):
        chain: list[tuple[float, float]] = []
        for p in seq:
            while len(chain) >= 2 and _cross(chain[-2], chain[-1], p) <= 0:
                chain.pop()
            chain.append(p)
        return chain[:-1]

    return half(pts) + half(reversed(pts))


def _cross(o, a, b) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def outline_corners(points: np.ndarray, hull: bool = False) -> list[tuple[float, float]]:
    return convex_hull(points[:, :2]) if hull else rectangle(points)


def outline_lines(toolpath, feed_mm_min: float, hull: bool = False) -> list[str]:
    """The outline program (see the module docstring); ValueError for a job that moves
    nowhere in X and Y or a feed that is not above 0."""
    if not feed_mm_min > 0:
        raise ValueError(msg("outline feed must be above 0, not {feed:g}", feed=float(feed_mm_min)))
    points = visited(toolpath)
    corners = outline_corners(points, hull) if len(points) else []
    if len(set(corners)) < 2:
        raise ValueError(msg("the job moves nowhere in X and Y: no outline to trace"))
    safe_z = float(points[:, 2].max())
    first = corners[0]
    lines = ["G21 G90", "M05", f"G00 Z{fmt(safe_z)}", f"G00 X{fmt(first[0])} Y{fmt(first[1])}"]
    lines += [f"G01 X{fmt(x)} Y{fmt(y)} F{fmt(feed_mm_min)}" for x, y in corners[1:] + [first]]
    return lines + ["M30"]
