"""Checks of a toolpath against the geometry it must cut (the issue's definitions).

Moves become sampled tool-centre points; the tests then ask: does the tool disk stay
inside the region (no gouge), is the floor swept, are the walls at the tool radius,
is the last depth exact, does any rapid or plunge go into uncut stock.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import LineString, Point

from app.gcode.features.contour import Segment
from app.gcode.features.moves import ARC, FEED, RAPID

STEP = 0.2  # mm between samples along a move


def samples(moves, start=(0.0, 0.0, 0.0)):
    """[(kind, [(x, y, z), ...])] per motion move, its points from start to end."""
    out, pos = [], start
    for m in moves:
        if m.kind not in (RAPID, FEED, ARC):
            continue
        if m.kind == ARC:
            flat = [pos[:2]] + Segment(pos[:2], m.end[:2], m.center, m.cw).points(0.002)
        else:
            count = max(1, math.ceil(math.dist(pos, m.end) / STEP))
            flat = [(pos[0] + (m.end[0] - pos[0]) * k / count, pos[1] + (m.end[1] - pos[1]) * k / count)
                    for k in range(count + 1)]
        n = len(flat) - 1
        pts = [(x, y, pos[2] + (m.end[2] - pos[2]) * k / max(n, 1)) for k, (x, y) in enumerate(flat)]
        out.append((m.kind, pts))
        pos = m.end
    return out


def cutting_points(moves, below: float) -> np.ndarray:
    """(n, 3) feed points at or below ``below``."""
    pts = [p for kind, ps in samples(moves) if kind != RAPID for p in ps]
    arr = np.array(pts)
    return arr[arr[:, 2] <= below + 1e-9]


def gouges(moves, allowed_centre, top: float) -> int:
    """Cutting points (below ``top``) whose centre lies outside ``allowed_centre`` (the
    region the tool centre may visit, already widened by the tolerance)."""
    pts = cutting_points(moves, top - 1e-6)
    return int((~shapely.contains_xy(allowed_centre, pts[:, 0], pts[:, 1])).sum())


class Swept:
    """The area swept by a tool of ``radius`` along polylines (exact distances)."""

    def __init__(self, lines, radius: float) -> None:
        self.tree = shapely.STRtree(lines)
        self.radius = radius

    def covers(self, xs, ys, slack: float = 0.0) -> np.ndarray:
        """Mask of points within ``radius + slack`` of a polyline."""
        pts = shapely.points(xs, ys)
        hit = np.zeros(len(pts), bool)
        if len(self.tree.geometries):
            idx, _ = self.tree.query_nearest(pts, max_distance=self.radius + slack, return_distance=True)
            hit[idx[0]] = True
        return hit

    def distance(self, xy) -> float:
        p = Point(xy)
        return self.tree.geometries[self.tree.nearest(p)].distance(p)


def _polylines(moves, keep) -> list:
    lines = []
    for kind, ps in samples(moves):
        at = [p[:2] for p in ps if keep(p)]
        if kind != RAPID and at:
            lines.append(LineString(at) if len(at) > 1 else Point(at[0]))
    return lines


def swept(moves, z: float, radius: float) -> Swept:
    """The area the tool sweeps at height ``z`` (feed moves at ``z``)."""
    return Swept(_polylines(moves, lambda p: abs(p[2] - z) < 1e-6), radius)


def coverage(area: Swept, region, grid: float = 0.1) -> float:
    """Share of ``region``'s grid points (``grid`` mm) that ``area`` covers."""
    x0, y0, x1, y1 = region.bounds
    xs, ys = np.meshgrid(np.arange(x0 + grid / 2, x1, grid), np.arange(y0 + grid / 2, y1, grid))
    xs, ys = xs.ravel(), ys.ravel()
    inside = shapely.contains_xy(region, xs, ys)
    return float(area.covers(xs[inside], ys[inside]).mean())


def wall_error(moves, boundary_pts, z: float, radius: float) -> float:
    """Largest distance beyond ``radius`` from a wall point to the cut at ``z``."""
    area = swept(moves, z, radius)
    return max(area.distance(q) - radius for q in boundary_pts)


def _disk_points(xy, radius: float, stock, grid: float = 0.1):
    xs, ys = np.meshgrid(np.arange(-radius, radius, grid), np.arange(-radius, radius, grid))
    keep = xs * xs + ys * ys <= radius * radius
    xs, ys = xs[keep] + xy[0], ys[keep] + xy[1]
    inside = shapely.contains_xy(stock, xs, ys)
    return xs[inside], ys[inside]


def into_stock(moves, stock, radius: float, top: float) -> list[str]:
    """Rapids that end below ``top`` (or move sideways below it) and vertical feeds
    down, whose tool disk meets stock not yet cut at that height."""
    bad, done = [], []
    for kind, ps in samples(moves):
        a, b = ps[0], ps[-1]
        sideways = math.dist(a[:2], b[:2]) > 1e-9
        if kind == RAPID and sideways and min(a[2], b[2]) < top - 1e-9:
            bad.append(f"sideways rapid below the top at {b}")
        elif b[2] < top - 1e-9 and not sideways and b[2] < a[2] - 1e-9 and kind in (RAPID, FEED):
            lows = [[p[:2] for p in seg if p[2] <= b[2] + 1e-9] for seg in done]
            lines = [LineString(low) if len(low) > 1 else Point(low[0]) for low in lows if low]
            cleared = Swept(lines, radius)
            xs, ys = _disk_points(b[:2], radius * 0.98, stock)
            if len(xs) and not cleared.covers(xs, ys, 1e-3).all():
                bad.append(f"{kind} down into stock at {b}")
        if kind != RAPID:
            done.append(ps)
    return bad
