"""Roughing a pocket (rings from the inside out), layer by layer, and the paper's ring
offsets around an island (its rings are cut by ``profile.py``).

A pocket's ring spacing is the stepover, or less where that would leave floor uncut
(``rings.covering_trees``). A pocket layer: every leaf of the ring tree is entered by a
helix at its centre
(a ramp along it where no helix fits), then each ring is cut, children before their
parent, linked by a feed to the parent's nearest point (inside the parent: no gouge).
``ring_offsets``: the paper's H_i, from the stock ``M`` inwards to ``D/2 + U``.
"""

from __future__ import annotations

from shapely.geometry import Point, Polygon

from . import entry, rings
from .cutting import Cutting
from .moves import Path


class Pocket:
    """The tool-centre geometry of one pocket region and its roughing walk."""

    def __init__(self, region: Polygon, cut: Cutting, ccw: bool) -> None:
        self.cut, self.ccw = cut, ccw
        self.allowed = region.buffer(-cut.radius, quad_segs=rings.quad_segs(cut.radius))
        self.trees = rings.covering_trees(region, cut.radius + cut.finish_xy, cut.step, cut.radius)

    def layer(self, path: Path, z_from: float, z: float, note: str) -> None:
        """Clear the whole pocket at ``z``, the level above being cut to ``z_from``."""
        for t, tree in enumerate(self.trees):
            for node in tree.walk():
                path.note = f"{note} area {t + 1}"
                points = rings.ring_points(node.shape, self.ccw)
                if not node.children:
                    self._enter(path, node.shape, points, z_from, z)
                else:
                    near = rings.lap_from(points, path.pos[:2])
                    path.feed(near[0][0], near[0][1], f=self.cut.feed)
                    entry.lap(path, near[1:], self.cut)

    def entry_xy(self) -> tuple[float, float]:
        """Where a layer's first entry goes down (the first leaf of the first tree)."""
        leaf = next(self.trees[0].walk()).shape if self.trees else None
        if leaf is None:
            return rings.centre_of(self.allowed)
        centre, radius, lap = self._entry(leaf, rings.ring_points(leaf, self.ccw))
        return centre if radius >= 0.05 else lap[0]  # a helix about the centre, else down at the lap

    def _entry(self, shape: Polygon, points):
        """(centre, helix radius, lap from the centre) of a leaf ring."""
        centre = rings.centre_of(shape)
        room = self.allowed.boundary.distance(Point(centre)) if not self.allowed.is_empty else 0.0
        radius = min(entry.HELIX_FRACTION * self.cut.tool_diameter, room - 1e-4)
        return centre, radius, rings.lap_from(points, centre)

    def _enter(self, path: Path, shape: Polygon, points, z_from: float, z: float) -> None:
        cut = self.cut
        centre, radius, lap = self._entry(shape, points)
        if radius >= 0.05:
            entry.approach(path, cut, centre, z_from)
            entry.helix(path, centre, radius, lap[0], z, cut, self.ccw)
            path.feed(lap[0][0], lap[0][1], f=cut.feed)
            entry.lap(path, lap[1:], cut)
        elif rings.length(lap) > 0.1:
            entry.approach(path, cut, lap[0], z_from)
            entry.ramp(path, lap, z, cut)
        else:
            entry.approach(path, cut, lap[0], z_from)
            path.feed(z=z, f=cut.plunge_feed)


def ring_offsets(cut: Cutting, stock: float) -> list[float]:
    """The paper's ring offsets (its equation 1 and figure 6): H_1 = M - D/2, then less
    by the stepover B·D/100 each ring while more than D/2 + U; the last ring D/2 + U."""
    last = cut.radius + cut.finish_xy
    offsets, h = [], stock - cut.radius
    while h > last + 1e-9:
        offsets.append(h)
        h -= cut.step
    return offsets + [last]
