"""Getting the tool down: approaches, helix and ramp entries, laps.

Rules kept here: no rapid goes below the stock top: the tool rapids down to ``GAP``
above the top (or above the cut level when that is higher) and feeds the rest of the
way at the plunge feed, over area already cut (or open). Uncut stock is entered by a helix (or, where no
helix fits, a ramp along the ring), never by a plunge, at a slope of at most
``RAMP_SLOPE``.
"""

from __future__ import annotations

import math

from .cutting import Cutting
from .moves import Path

GAP = 0.5  # mm above a cut level where a rapid down stops
RAMP_SLOPE = math.tan(math.radians(5.0))
HELIX_FRACTION = 0.25  # helix radius as a share of the tool diameter


def retract(path: Path, cut: Cutting) -> None:
    """Straight up to the safe height (nothing when already there)."""
    if path.pos[2] < cut.safe_z - 1e-9:
        path.rapid(z=cut.safe_z)


def approach(path: Path, cut: Cutting, xy, cut_level: float) -> None:
    """Retract, rapid over ``xy``, rapid down to ``GAP`` above ``cut_level`` but not
    below the stock top, feed down to ``cut_level`` (cut or open there)."""
    low = min(cut.safe_z, max(cut_level, cut.top) + GAP)
    if math.dist(path.pos[:2], xy) > 1e-9 or path.pos[2] > low + 1e-9:
        if math.dist(path.pos[:2], xy) > 1e-9:
            retract(path, cut)
            path.rapid(xy[0], xy[1])
        path.rapid(z=low)
    path.feed(z=cut_level, f=cut.plunge_feed)


def lap(path: Path, points, cut: Cutting) -> None:
    """Feed along ``points`` at the current height."""
    for x, y in points:
        path.feed(x, y, f=cut.feed)


def ramp(path: Path, points, z_to: float, cut: Cutting) -> None:
    """Descend to ``z_to`` along the closed lap ``points`` (repeated as needed),
    then one lap at ``z_to``."""
    ring_len = sum(math.dist(a, b) for a, b in zip(points, points[1:], strict=False))
    drop = path.pos[2] - z_to
    laps = max(1, math.ceil(drop / (max(ring_len, 1e-9) * RAMP_SLOPE)))
    total, done, z0 = ring_len * laps, 0.0, path.pos[2]
    for _ in range(laps):
        for a, b in zip(points, points[1:], strict=False):
            done += math.dist(a, b)
            path.feed(b[0], b[1], z0 - drop * min(1.0, done / total), f=cut.plunge_feed)
    lap(path, points[1:], cut)


def helix(path: Path, centre, radius: float, toward, z_to: float, cut: Cutting, ccw: bool,
          halves: int | None = None) -> None:
    """Helix of ``radius`` about ``centre`` from the current height down to ``z_to`` in
    ``halves`` half circles (None: as few as the ramp slope allows), ending (after a flat
    circle) at the point of the circle towards ``toward``."""
    cx, cy = centre
    dx, dy = toward[0] - cx, toward[1] - cy
    norm = math.hypot(dx, dy)
    ux, uy = (dx / norm, dy / norm) if norm > 1e-9 else (1.0, 0.0)
    start = (cx + radius * ux, cy + radius * uy)
    opposite = (cx - radius * ux, cy - radius * uy)
    path.feed(start[0], start[1], f=cut.plunge_feed)
    drop = path.pos[2] - z_to
    halves = halves or 2 * max(1, math.ceil(drop / (2 * math.pi * radius * RAMP_SLOPE)))
    z0 = path.pos[2]
    for k in range(1, halves + 1):
        x, y = opposite if k % 2 else start
        path.arc(x, y, centre, not ccw, z=z0 - drop * k / halves, f=cut.plunge_feed)
    path.arc(opposite[0], opposite[1], centre, not ccw, f=cut.feed)
    path.arc(start[0], start[1], centre, not ccw, f=cut.feed)
