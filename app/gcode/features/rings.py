"""Offset geometry with shapely: erosions of a pocket, dilations of an island, laps.

Offsets are Euclidean (round joins) with chords within ``TOL``. A pocket's rings form
a tree: the erosion at the first offset, then each component eroded by the stepover
again, until nothing is left; a leaf (nothing left at the stepover) is eroded once
more by a step no larger than ``leaf_step`` so that the floor in its middle is cut.
``covering_trees`` narrows the spacing where the stepover would leave floor uncut
(between rings near sharp corners, where a ring ends).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import shapely
from shapely.geometry import LineString, MultiPolygon, Point, Polygon
from shapely.geometry.polygon import orient
from shapely.ops import polylabel

TOL = 0.002  # mm
MIN_AREA = 1e-6  # mm^2: smaller components are numerical dust


def quad_segs(distance: float) -> int:
    """Segments per quarter circle keeping round joins within ``TOL`` of the true arc."""
    if distance <= TOL:
        return 4
    return max(4, math.ceil((math.pi / 2) / (2 * math.acos(1 - TOL / distance))))


def offset(shape: Polygon, distance: float) -> list[Polygon]:
    """Components of ``shape`` grown (``distance`` > 0) or eroded (< 0), largest first."""
    grown = shape.buffer(distance, quad_segs=quad_segs(abs(distance))) if distance else shape
    parts = grown.geoms if isinstance(grown, MultiPolygon) else [grown]
    parts = [p.simplify(TOL / 4) for p in parts if not p.is_empty and p.area > MIN_AREA]
    return sorted((p for p in parts if not p.is_empty), key=lambda p: -p.area)


@dataclass
class Node:
    """A pocket ring (the boundary of ``shape``) and the rings inside it."""

    shape: Polygon
    children: list[Node] = field(default_factory=list)

    def walk(self):
        """Post-order: every child subtree before the node itself (no recursion: a tree
        may be thousands of rings deep)."""
        stack = [(self, False)]
        while stack:
            node, expanded = stack.pop()
            if expanded:
                yield node
                continue
            stack.append((node, True))
            stack.extend((child, False) for child in reversed(node.children))


def pocket_tree(region: Polygon, first: float, step: float, leaf_step: float) -> list[Node]:
    """Ring trees of ``region`` eroded by ``first``, then by ``step`` (see module doc)."""
    return [_grow(p, step, leaf_step) for p in offset(region, -first)]


def uncut(trees: list[Node], first: float, region: Polygon, radius: float) -> float:
    """Area (mm^2, slivers under 0.02 mm wide ignored) of the floor that ``radius`` tools
    on every ring of ``trees`` leave uncut within reach (``region`` eroded by ``first``
    and grown back by ``radius``)."""
    lines = [LineString(node.shape.exterior.coords) for tree in trees for node in tree.walk()]
    if not lines:
        return 0.0
    swept = shapely.union_all(lines).buffer(radius, quad_segs=quad_segs(radius))
    reach = shapely.union_all(offset(region, -first)).buffer(radius, quad_segs=quad_segs(radius))
    return float(reach.difference(swept).buffer(-0.01).area)


def covering_trees(region: Polygon, first: float, step: float, radius: float) -> list[Node]:
    """``pocket_tree`` at the stepover, or at a smaller spacing (15 % less each try, not
    under half the radius) where that would leave part of the floor uncut."""
    while True:
        trees = pocket_tree(region, first, step, min(step, 0.9 * radius))
        if step <= 0.5 * radius or uncut(trees, first, region, radius) <= 0.0:
            return trees
        step *= 0.85


def _grow(shape: Polygon, step: float, leaf_step: float) -> Node:
    """The ring tree of ``shape`` (see the module docstring), built without recursion."""
    root = Node(shape)
    todo = [(root, step)]
    while todo:
        node, spacing = todo.pop()
        inner = offset(node.shape, -spacing)
        if not inner and leaf_step < spacing:
            inner, spacing = offset(node.shape, -leaf_step), leaf_step
        node.children = [Node(p) for p in inner]
        todo.extend((child, spacing) for child in node.children)
    return root


def ring_points(shape: Polygon, ccw: bool) -> list[tuple[float, float]]:
    """The exterior of ``shape`` in the given direction, without the closing point."""
    coords = list(orient(shape, 1.0 if ccw else -1.0).exterior.coords)
    return [(float(x), float(y)) for x, y in coords[:-1]]


def lap_from(points: list[tuple[float, float]], near: tuple[float, float]) -> list[tuple[float, float]]:
    """The closed ring ``points`` as a lap starting and ending at its point nearest ``near``."""
    ring = LineString(points + points[:1])
    along = ring.project(Point(near))
    start = ring.interpolate(along)
    cum, k = 0.0, 0
    for k in range(len(points)):
        seg = math.dist(points[k], points[(k + 1) % len(points)])
        if cum + seg >= along:
            break
        cum += seg
    s = (float(start.x), float(start.y))
    rest = points[k + 1:] + points[: k + 1]
    lap = [s] + [p for p in rest if math.dist(p, s) > 1e-9]
    return lap + [s]


def centre_of(shape: Polygon) -> tuple[float, float]:
    """A point deep inside ``shape`` (its pole of inaccessibility)."""
    p = polylabel(shape, tolerance=0.01)
    return float(p.x), float(p.y)


def length(points) -> float:
    return sum(math.dist(a, b) for a, b in zip(points, points[1:], strict=False))


def inside(shape: Polygon, points, slack: float = 1e-4) -> bool:
    """Whether the polyline ``points`` stays within ``shape`` (grown by ``slack``)."""
    if len(points) == 1:
        return shape.buffer(slack).contains(Point(points[0]))
    return shape.buffer(slack).contains(LineString(points))
