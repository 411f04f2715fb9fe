"""One frozen dataclass per feature kind, validated on construction.

Positions in work millimetres, angles in degrees about X+ (counter-clockwise).
``region()`` is the area the tool may cut (its edge may touch the boundary);
``hint()`` where the finishing pass joins the wall (a profile's: the middle of its first
segment, ``paper.split_first``). Errors are ``FeatureError`` naming
the field: a tool wider than the pocket or slot, a size <= 0, a hole count < 1.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box

from app.i18n import msg

from .contour import CHORD_TOL, Contour
from .cutting import Cutting
from .errors import FeatureError, require
from .ranges import MAX_HOLES, MAX_MOVES, check_count, check_work, round_points, whole, within
from .rings import MIN_AREA, centre_of, quad_segs

ENTRY_ROOM = 0.05  # mm: the least width of roughing area a ramp needs (clearing.Pocket._enter)
ROUND_CORNER = 1e-6  # mm: a corner radius below this is a sharp corner (GEOS refuses smaller buffers)


def _roughable(region, cut: Cutting) -> None:
    """Refuse a pocket whose roughing area (``region`` eroded by D/2 + U) is empty or too
    small to enter by a ramp: naming ``finish_xy`` when the allowance is what leaves
    nothing to rough, else ``tool_diameter``."""
    rough = region.buffer(-(cut.radius + cut.finish_xy))
    if not rough.is_empty and rough.area > MIN_AREA and rough.length > 2 * ENTRY_ROOM:
        return
    deepest = region.boundary.distance(Point(centre_of(region)))  # the largest tool radius that fits
    if cut.finish_xy > 0 and deepest - cut.radius > ENTRY_ROOM:
        raise FeatureError("finish_xy", msg(
            "leaves nothing to rough in this {what}: with this tool it must be below {most:.3f} "
            "(got {finish_xy:g})", what=msg("pocket"), most=float(deepest - cut.radius - ENTRY_ROOM),
            finish_xy=float(cut.finish_xy)))
    raise FeatureError("tool_diameter", msg(
        "the tool ({tool:g} mm) leaves no room to enter this pocket by a ramp or a helix: "
        "use one below {most:.3f} mm", tool=float(cut.tool_diameter),
        most=float(2 * (deepest - ENTRY_ROOM))))


def _narrower(cut: Cutting, width: float, what: str) -> None:
    require(cut.tool_diameter < width, "tool_diameter",
            msg("the tool ({tool:g} mm) must be narrower than the {what} ({width:g} mm)",
                tool=float(cut.tool_diameter), what=what, width=float(width)))


@dataclass(frozen=True)
class Face:
    """Face the rectangle ``x, y, width, height`` (lower-left corner) down by ``depth``."""

    kind: ClassVar[str] = "face"
    x: float
    y: float
    width: float
    height: float
    cut: Cutting

    def __post_init__(self) -> None:
        _numbers(self, "x", "y", "width", "height")
        rows = self.height / self.cut.step + 1
        check_work(self.cut, rows, 2)


def _numbers(feature, *names: str) -> None:
    """Every option in ``names`` a finite number in its range (``ranges.RANGES``)."""
    for name in names:
        within(getattr(feature, name), name)


@dataclass(frozen=True)
class PocketRect:
    """A rectangular pocket from its lower-left corner, rotated ``angle`` about it."""

    kind: ClassVar[str] = "pocket-rect"
    x: float
    y: float
    width: float
    height: float
    cut: Cutting
    corner_radius: float = 0.0
    angle: float = 0.0

    def __post_init__(self) -> None:
        _numbers(self, "x", "y", "width", "height", "corner_radius", "angle")
        require(0 <= self.corner_radius <= min(self.width, self.height) / 2, "corner_radius",
                msg("must be between 0 and half the smaller side, {half:g} (got {radius:g})",
                    half=float(min(self.width, self.height) / 2), radius=float(self.corner_radius)))
        _narrower(self.cut, min(self.width, self.height), msg("pocket"))
        check_work(self.cut, min(self.width, self.height) / 2 / self.cut.step,
                   round_points(self.corner_radius * 2) + 4)
        _roughable(self.region(), self.cut)

    def region(self) -> Polygon:
        r, w, h = self.corner_radius, self.width, self.height
        if r > ROUND_CORNER:  # the rectangle's core grown by r: a line or a point when r is half a side
            lo, hi = (r, r), (max(w - r, r), max(h - r, r))
            core = box(*lo, *hi) if hi[0] > lo[0] and hi[1] > lo[1] else \
                LineString([lo, hi]) if hi != lo else Point(lo)
            shape = core.buffer(r, quad_segs=quad_segs(r))
        else:
            shape = box(0, 0, w, h)
        shape = affinity.rotate(shape, self.angle, origin=(0, 0))
        return affinity.translate(shape, self.x, self.y)

    def hint(self):
        a = math.radians(self.angle)
        return (self.x + self.width / 2 * math.cos(a), self.y + self.width / 2 * math.sin(a))


@dataclass(frozen=True)
class PocketCircle:
    """A round pocket of ``diameter`` about its centre ``x, y``."""

    kind: ClassVar[str] = "pocket-circle"
    x: float
    y: float
    diameter: float
    cut: Cutting

    def __post_init__(self) -> None:
        _numbers(self, "x", "y", "diameter")
        _narrower(self.cut, self.diameter, msg("pocket"))
        check_work(self.cut, self.diameter / 2 / self.cut.step, round_points(self.diameter))
        _roughable(self.region(), self.cut)

    def region(self) -> Polygon:
        r = self.diameter / 2
        return Point(self.x, self.y).buffer(r, quad_segs=quad_segs(r))

    def hint(self):
        return (self.x + self.diameter / 2, self.y)


@dataclass(frozen=True)
class Slot:
    """A straight slot of ``width`` with round ends, centre line from (x1, y1) to (x2, y2)."""

    kind: ClassVar[str] = "slot"
    x1: float
    y1: float
    x2: float
    y2: float
    width: float
    cut: Cutting

    def __post_init__(self) -> None:
        _numbers(self, "x1", "y1", "x2", "y2", "width")
        require(math.dist((self.x1, self.y1), (self.x2, self.y2)) > 0, "x2",
                msg("the slot's ends must differ (use pocket-circle for a round hole)"))
        require(self.cut.tool_diameter <= self.width, "tool_diameter",
                msg("the tool ({tool:g} mm) is wider than the slot ({width:g} mm)",
                    tool=float(self.cut.tool_diameter), width=float(self.width)))
        check_work(self.cut, self.width / 2 / self.cut.step, round_points(self.width) + 4)
        if not self.exact:
            _roughable(self.region(), self.cut)

    def region(self) -> Polygon:
        r = self.width / 2
        return LineString([(self.x1, self.y1), (self.x2, self.y2)]).buffer(r, quad_segs=quad_segs(r))

    def hint(self):
        dx, dy = self.x2 - self.x1, self.y2 - self.y1
        norm = math.hypot(dx, dy)
        half = self.width / 2 / norm
        return ((self.x1 + self.x2) / 2 - dy * half, (self.y1 + self.y2) / 2 + dx * half)

    @property
    def exact(self) -> bool:
        """The tool is as wide as the slot: one cut along the centre line."""
        return self.width - self.cut.tool_diameter < 1e-6


@dataclass(frozen=True)
class Profile:
    """An island (``side`` outside: stock up to ``stock`` mm around it is removed) or a
    pocket of the contour's shape (``side`` inside)."""

    kind: ClassVar[str] = "profile"
    contour: Contour
    side: str
    cut: Cutting
    stock: float = 0.0

    def __post_init__(self) -> None:
        require(self.side in ("inside", "outside"), "side",
                msg("must be inside or outside (got {side!r})", side=self.side))
        within(self.stock, "stock")
        points = len(self.region().exterior.coords)
        if self.side == "outside":
            check_work(self.cut, self.removed_stock / self.cut.step + 1, points)
            return
        x0, y0, x1, y1 = self.region().bounds
        check_work(self.cut, min(x1 - x0, y1 - y0) / 2 / self.cut.step, points)
        if self.region().buffer(-self.cut.radius).is_empty:
            said = msg("the tool ({tool:g} mm) does not fit inside the contour {name}",
                       tool=float(self.cut.tool_diameter), name=self.contour.name)
            raise FeatureError("tool_diameter", said)
        _roughable(self.region(), self.cut)

    def region(self) -> Polygon:
        return self.contour.polygon(CHORD_TOL)

    @property
    def removed_stock(self) -> float:
        """The stock M around an island: given, or one tool diameter."""
        return self.stock or self.cut.tool_diameter


@dataclass(frozen=True)
class Holes:
    """Holes drilled to ``depth`` at ``centres``; ``peck`` > 0: G83-style pecks of that
    depth, ``dwell`` seconds at the bottom."""

    kind: ClassVar[str] = "holes"
    centres: tuple[tuple[float, float], ...]
    cut: Cutting
    peck: float = 0.0
    dwell: float = 0.0
    layout: tuple = ()  # ("circle", x, y, r, start) or ("row", x, y, pitch, angle): the macro's formula

    def __post_init__(self) -> None:
        require(1 <= len(self.centres) <= MAX_HOLES, "count",
                msg("must be from 1 to {most:,} (got {count:,})", most=MAX_HOLES, count=len(self.centres)))
        for x, y in self.centres:
            within(x, "x"), within(y, "y")
        _numbers(self, "peck", "dwell")
        pecks = math.ceil(self.cut.depth / self.peck) if self.peck > 0 else 1
        check_count("peck", 3 * pecks * len(self.centres), MAX_MOVES, msg("moves"))



def holes_circle(x: float, y: float, diameter: float, count: int, cut: Cutting,
                 start_angle: float = 0.0, peck: float = 0.0, dwell: float = 0.0) -> Holes:
    """``count`` holes evenly on a circle of ``diameter`` about (x, y)."""
    count = whole(count, "count")
    x, y, diameter, start_angle = (within(v, n) for v, n in ((x, "x"), (y, "y"), (diameter, "diameter"),
                                                              (start_angle, "start_angle")))
    r = diameter / 2
    angles = [math.radians(start_angle + 360.0 * k / count) for k in range(count)]
    return Holes(tuple((x + r * math.cos(a), y + r * math.sin(a)) for a in angles), cut, peck, dwell,
                 ("circle", x, y, r, start_angle))


def holes_row(x: float, y: float, count: int, pitch: float, cut: Cutting,
              angle: float = 0.0, peck: float = 0.0, dwell: float = 0.0) -> Holes:
    """``count`` holes ``pitch`` apart from (x, y) along ``angle``."""
    count = whole(count, "count")
    x, y, angle = (within(v, n) for v, n in ((x, "x"), (y, "y"), (angle, "angle")))
    pitch = within(pitch, "pitch") if count > 1 else 0.0
    a = math.radians(angle)
    return Holes(tuple((x + k * pitch * math.cos(a), y + k * pitch * math.sin(a)) for k in range(count)),
                 cut, peck, dwell, ("row", x, y, pitch, angle))
