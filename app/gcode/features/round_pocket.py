"""Pockets of a rounded rectangle (rectangle, circle, slot), their rings computed from a
few numbers, as the CAPP paper's macro programs compute them.

A ``RoundRect`` is a centre, half sizes ``a`` x ``b`` along its own axes (turned
``angle`` degrees) and a corner radius ``rc`` <= min(a, b): a rectangle (sharp or round
corners), a circle (a = b = rc), a slot (b = rc). Its ring at offset ``h`` (the tool
centre ``h`` inside the wall) is the same shape with half sizes ``a - h``, ``b - h`` and
corner radius ``rc - h`` (sharp once ``h`` >= ``rc``), started at its point on the +a
axis and cut round with true arcs at the corners.

``PocketForm`` is the whole pocket: ``n`` rings a layer ``spacing`` apart (the stepover,
at most sqrt(2)·R so that the corners between two rings are cut), the innermost of half
width ``spacing / 2`` (its middle within the tool's reach), entered by a helix of radius
``rho`` about the centre, cut from the inside out; the roughing layers down to the floor
+ W, a floor pass, then the wall (the ring at R) on every layer with the paper's
tangent lead (``finish.plan_lead``). ``moves()`` gives its moves (the plain program);
``round_macro.py`` writes the same moves as loops over the layers and the rings.
``pocket_form(feature)`` is None where no helix fits (the points of ``clearing.Pocket``
are used there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from shapely.geometry import Polygon

from . import entry, rings
from .cutting import Cutting
from .finish import Lead, each_wall_layer, plan_lead
from .kinds import ROUND_CORNER, PocketCircle, PocketRect, Slot
from .macro_text import Levels, levels_of
from .moves import RAPID, Move, Path

ROUND = ROUND_CORNER  # mm: a corner radius below this is a sharp corner
MIN_HELIX = 0.05  # mm: the least helix radius (as clearing.Pocket)


@dataclass(frozen=True)
class RoundRect:
    """A rounded rectangle (see the module docstring); ``angle`` in degrees."""

    cx: float
    cy: float
    a: float
    b: float
    rc: float
    angle: float = 0.0

    @cached_property
    def axes(self) -> tuple[float, float]:
        t = math.radians(self.angle)
        return math.cos(t), math.sin(t)

    def world(self, x: float, y: float) -> tuple[float, float]:
        c, s = self.axes
        return self.cx + x * c - y * s, self.cy + x * s + y * c

    def corner(self, h: float) -> float:
        """The corner radius of the ring at offset ``h`` (0: sharp)."""
        r = self.rc - h
        return r if r > ROUND else 0.0

    def ring(self, h: float, ccw: bool) -> list[tuple]:
        """The ring at offset ``h`` from its start (a - h, 0), in the shape's own axes
        (``ring_steps``)."""
        a, b, r = self.a - h, self.b - h, self.corner(h)
        ka, kb = a - r, b - r
        sides = (kb > 1e-9, ka > 1e-9) if r > 0 else (True, True)
        return ring_steps(a, b, ka, kb, r > 0, sides, ccw, 0.0)

    def polyline(self, h: float, ccw: bool, step_deg: float = 5.0) -> list[tuple[float, float]]:
        """The ring at ``h`` as world points from its start round to it (arcs as chords)."""
        points = [self.world(self.a - h, 0.0)]
        last = (self.a - h, 0.0)
        for step in self.ring(h, ccw):
            if step[0] == "arc":
                cx, cy = step[3], step[4]
                a0 = math.atan2(last[1] - cy, last[0] - cx)
                a1 = math.atan2(step[2] - cy, step[1] - cx)
                sweep = (a1 - a0) % (2 * math.pi) if ccw else -((a0 - a1) % (2 * math.pi))
                r = math.hypot(last[0] - cx, last[1] - cy)
                count = max(2, math.ceil(abs(math.degrees(sweep)) / step_deg))
                points += [self.world(cx + r * math.cos(a0 + sweep * k / count),
                                      cy + r * math.sin(a0 + sweep * k / count)) for k in range(1, count)]
            points.append(self.world(step[1], step[2]))
            last = (step[1], step[2])
        return points


def ring_steps(a, b, ka, kb, corners: bool, sides: tuple[bool, bool], ccw: bool, zero) -> list[tuple]:
    """A ring of half sizes ``a`` x ``b`` from (a, 0) round to it: ``("line", x, y)`` and
    ``("arc", x, y, cx, cy)`` steps; ``corners``: round corners about (±ka, ±kb) (else
    ka = a, kb = b); ``sides``: whether its straight parts along b and along a have a
    length. The values need only unary minus: numbers, or the macro writer's expressions."""
    steps: list[tuple] = []
    along_b, along_a = sides
    for qx, qy in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        fx = (lambda v: v) if qx > 0 else (lambda v: -v)
        fy = (lambda v: v) if qy > 0 else (lambda v: -v)
        if qx == qy:  # up (or down) the b side, then round to the a side
            if along_b:
                steps.append(("line", fx(a), fy(kb)))
            if corners:
                steps.append(("arc", fx(ka), fy(b), fx(ka), fy(kb)))
        else:
            if along_a:
                steps.append(("line", fx(ka), fy(b)))
            if corners:
                steps.append(("arc", fx(a), fy(kb), fx(ka), fy(kb)))
    if along_b:
        steps.append(("line", a, zero))
    if ccw:
        return steps
    return [(s[0], s[1], -s[2], *((s[3], -s[4]) if s[0] == "arc" else ())) for s in steps]


def shape_of(feature) -> RoundRect | None:
    """The rounded rectangle of a rectangular or round pocket or a slot, else None."""
    if isinstance(feature, PocketCircle):
        r = feature.diameter / 2
        return RoundRect(feature.x, feature.y, r, r, r)
    if isinstance(feature, PocketRect):
        w, h = feature.width / 2, feature.height / 2
        t = math.radians(feature.angle)
        cx = feature.x + w * math.cos(t) - h * math.sin(t)
        cy = feature.y + w * math.sin(t) + h * math.cos(t)
        return RoundRect(cx, cy, w, h, feature.corner_radius, feature.angle)
    if isinstance(feature, Slot) and not feature.exact:
        half = feature.width / 2
        dx, dy = feature.x2 - feature.x1, feature.y2 - feature.y1
        return RoundRect((feature.x1 + feature.x2) / 2, (feature.y1 + feature.y2) / 2,
                         math.hypot(dx, dy) / 2 + half, half, half, math.degrees(math.atan2(dy, dx)))
    return None


@dataclass(frozen=True)
class PocketForm:
    """One pocket's parametric program (see the module docstring)."""

    shape: RoundRect
    cut: Cutting
    ccw: bool
    n: int  # rings a layer
    spacing: float
    rho: float  # helix radius
    lead: Lead | None

    @property
    def h_out(self) -> float:
        """The offset of the outermost roughing ring: R + U."""
        return self.cut.radius + self.cut.finish_xy

    def offset(self, j: int) -> float:
        """The offset of ring ``j`` (0: the innermost)."""
        return self.h_out + (self.n - 1 - j) * self.spacing

    def first_round(self) -> int:
        """The first ring with round corners (``n``: none); the rings inside it are sharp."""
        return next((j for j in range(self.n) if self.shape.corner(self.offset(j)) > 0), self.n)

    @property
    def rough(self) -> Levels:
        return levels_of(self.cut, self.cut.floor + self.cut.finish_z)

    @property
    def walls(self) -> Levels:
        return levels_of(self.cut, self.cut.floor)

    def pairs(self, drop: float) -> int:
        """Helix turns (pairs of half circles) for a descent of ``drop`` at the ramp slope."""
        return max(1, math.ceil(drop / (2 * math.pi * self.rho * entry.RAMP_SLOPE)))

    @property
    def low(self) -> float:
        """Where a rapid down stops over cut area: ``GAP`` above the top (``entry.approach``)."""
        return min(self.cut.safe_z, self.cut.top + entry.GAP)

    def wall_start(self) -> tuple[float, float]:
        return self.shape.world(self.shape.a - self.cut.radius, 0.0)

    def moves(self) -> list[Move]:
        """The pocket's moves, from and back to the safe height, each carrying the form."""
        cut, shape = self.cut, self.shape
        path = Path((shape.cx, shape.cy, cut.safe_z))
        path.moves.append(Move(RAPID, path.pos))
        rough = self.rough
        z_from = cut.top
        for k in range(1, rough.count + 1):
            z = rough.depth(k, cut.top)
            self._layer(path, z_from, z, f"layer {k}/{rough.count} z {z:.3f}")
            z_from = z
        if cut.finish_z > 0:
            self._layer(path, z_from, cut.floor, f"floor z {cut.floor:.3f}")
        start = self.lead.p1 if self.lead else self.wall_start()
        lap = lambda: self._ring(path, cut.radius)  # noqa: E731
        each_wall_layer(path, cut, self.lead, start, lap, "finish wall")
        path.note = ""
        entry.retract(path, cut)
        return [Move(m.kind, m.end, m.feed, m.center, m.cw, m.value, m.note, self) for m in path.moves]

    def _layer(self, path: Path, z_from: float, z: float, note: str) -> None:
        cut, shape = self.cut, self.shape
        path.note = note
        centre = (shape.cx, shape.cy)
        entry.approach(path, cut, centre, z_from)
        entry.helix(path, centre, self.rho, shape.world(1.0, 0.0), z, cut, self.ccw,
                    halves=2 * self.pairs(z_from - z))
        for j in range(self.n):
            h = self.offset(j)
            path.feed(*shape.world(shape.a - h, 0.0), f=cut.feed)
            self._ring(path, h)
        entry.retract(path, cut)
        path.rapid(*centre)

    def _ring(self, path: Path, h: float) -> None:
        shape, feed = self.shape, self.cut.feed
        for step in shape.ring(h, self.ccw):
            x, y = shape.world(step[1], step[2])
            if step[0] == "line":
                path.feed(x, y, f=feed)
            else:
                path.arc(x, y, shape.world(step[3], step[4]), not self.ccw, f=feed)


def ring_spacing(reach: float, cut: Cutting) -> tuple[int, float]:
    """(rings, spacing) across ``reach`` (the outermost ring's smaller half size): the
    innermost ring half a spacing from the middle, the spacing at most the stepover and
    sqrt(2)·R."""
    most = min(cut.step, math.sqrt(2.0) * cut.radius)
    n = max(1, math.ceil(reach / most + 0.5 - 1e-9))
    return n, reach / (n - 0.5)


def pocket_form(feature, ccw: bool) -> PocketForm | None:
    """The parametric form of a rectangular or round pocket or a wide slot (None: another
    kind, or no helix fits)."""
    shape = shape_of(feature)
    if shape is None:
        return None
    cut = feature.cut
    half = min(shape.a, shape.b)
    rho = min(entry.HELIX_FRACTION * cut.tool_diameter, half - cut.radius - 1e-4)
    reach = half - cut.radius - cut.finish_xy
    if rho < MIN_HELIX or reach <= 1e-6:
        return None
    n, spacing = ring_spacing(reach, cut)
    wall = Polygon(shape.polyline(cut.radius, ccw, 1.0)).buffer(rings.TOL / 2)  # chords inside the arcs
    roughed = feature.region().buffer(-(cut.radius + cut.finish_xy))
    start = shape.world(shape.a - cut.radius, 0.0)
    lead = plan_lead([start], wall, cut.clearance, True, roughed, _tangent(shape, ccw))
    return PocketForm(shape, cut, ccw, n, spacing, rho, lead)


def _tangent(shape: RoundRect, ccw: bool) -> tuple[float, float]:
    """The direction a ring leaves its start in (world): along +b (ccw) or -b."""
    c, s = shape.axes
    sy = 1.0 if ccw else -1.0
    return -sy * s, sy * c

