"""Path segments in machine mm: straight lines and XY arcs/helices, parametrised by length.

Contract: ``Segment.from_move(start, move)`` gives a segment whose ``point(d)`` is the
tool position after ``d`` mm of path (0 <= d <= length), ``start_dir``/``end_dir`` the
unit tangents (for junction speeds) and ``radius`` the XY radius of an arc (0 for a
line). ``chords(tolerance)`` splits an arc into points no further than ``tolerance``
from it (the simple firmware and the contour-error check use them).
"""

from __future__ import annotations

import math

from backend_sim.motion.dialect import Move, arc_sweep

Vec3 = tuple[float, float, float]


class Segment:
    """One line or helix; ``coef`` packs what the 1 kHz interpolator needs."""

    __slots__ = ("start", "end", "length", "radius", "start_dir", "end_dir", "arc", "coef")

    def __init__(self, start: Vec3, end: Vec3):
        self.start, self.end = start, end
        dx, dy, dz = (end[0] - start[0], end[1] - start[1], end[2] - start[2])
        self.length = math.sqrt(dx * dx + dy * dy + dz * dz)
        n = self.length or 1.0
        self.start_dir = self.end_dir = (dx / n, dy / n, dz / n)
        self.radius = 0.0
        self.arc = False
        self.coef = (start[0], start[1], start[2], dx / n, dy / n, dz / n, 0.0)

    @classmethod
    def from_move(cls, start: Vec3, move: Move) -> Segment:
        if move.kind != "arc":
            return cls(start, move.target)
        seg = cls(start, move.target)
        r, a0, sweep = arc_sweep(start, move)
        dz = move.target[2] - start[2]
        seg.length = math.hypot(r * sweep, dz)
        seg.radius, seg.arc = r, True
        cx, cy = move.center  # type: ignore[misc]
        # angle(d) = a0 + k_ang d, z(d) = z0 + k_z d
        seg.coef = (cx, cy, start[2], r, a0, sweep / seg.length, dz / seg.length)
        seg.start_dir = seg.tangent(0.0)
        seg.end_dir = seg.tangent(seg.length)
        return seg

    def point(self, d: float) -> Vec3:
        c = self.coef
        if self.arc:
            ang = c[4] + c[5] * d
            return (c[0] + c[3] * math.cos(ang), c[1] + c[3] * math.sin(ang), c[2] + c[6] * d)
        return (c[0] + c[3] * d, c[1] + c[4] * d, c[2] + c[5] * d)

    def tangent(self, d: float) -> Vec3:
        if not self.arc:
            return self.start_dir
        c = self.coef
        ang = c[4] + c[5] * d
        tx, ty = -math.sin(ang) * c[3] * c[5], math.cos(ang) * c[3] * c[5]
        n = math.sqrt(tx * tx + ty * ty + c[6] * c[6]) or 1.0
        return (tx / n, ty / n, c[6] / n)

    def chords(self, tolerance: float) -> list[Vec3]:
        """Points from start to end; arcs split so the sagitta stays below ``tolerance``."""
        if not self.arc or self.length == 0:
            return [self.start, self.end]
        r = self.radius
        sweep = abs(self.coef[5] * self.length)
        step = 2 * math.acos(max(-1.0, 1 - tolerance / r)) if tolerance < r else math.pi / 2
        n = max(1, math.ceil(sweep / max(step, 1e-9)))
        pts = [self.point(self.length * k / n) for k in range(n)]
        return pts + [self.end]


def junction_speed(prev: Segment, nxt: Segment, accel: float, deviation: float) -> float:
    """Largest speed through the corner (grbl's junction deviation), mm/s; inf if straight."""
    a, b = prev.end_dir, nxt.start_dir
    cos_theta = -(a[0] * b[0] + a[1] * b[1] + a[2] * b[2])  # angle between -a and b
    if cos_theta < -0.999999:
        return math.inf  # straight on
    if cos_theta > 0.999999:
        return 0.0  # full reversal
    sin_half = math.sqrt(0.5 * (1 - cos_theta))
    return math.sqrt(accel * deviation * sin_half / (1 - sin_half))
