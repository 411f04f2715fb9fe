"""Finishing the walls at exactly the tool radius, with the paper's lead-in and out.

On every layer down to the floor the tool goes down at point 1 (``2R`` from the wall,
over cut area), feeds to point 2, arcs (radius ``R``) tangentially onto the wall at
point 3 (the wall's point nearest the hint, for a contour the middle of its first
segment), laps the wall, arcs off to point 5 and back to point 1 (equations 2-6).
Where an arc of the clearance ``R`` does not fit, ``R`` is halved until it does; if
none fits the tool comes straight in from the roughed area.
"""

from __future__ import annotations

import math

from shapely.geometry import LineString, Point, Polygon

from . import entry, rings
from .contour import Segment
from .cutting import Cutting
from .moves import Path


def _unit(a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    norm = math.hypot(dx, dy) or 1.0
    return dx / norm, dy / norm


class Lead:
    """Points 1, 2, 3, 5 and the arc centre 4 of one wall's entry and exit."""

    def __init__(self, s, t, n, radius: float) -> None:
        self.radius = radius
        self.p3 = s
        self.p4 = (s[0] + radius * n[0], s[1] + radius * n[1])
        self.p1 = (s[0] + 2 * radius * n[0], s[1] + 2 * radius * n[1])
        self.p2 = (self.p4[0] - radius * t[0], self.p4[1] - radius * t[1])
        self.p5 = (self.p4[0] + radius * t[0], self.p4[1] + radius * t[1])
        self.cw = t[0] * n[1] - t[1] * n[0] < 0

    def polyline(self) -> list[tuple[float, float]]:
        arc_in = Segment(self.p2, self.p3, self.p4, self.cw).points(0.005)
        arc_out = Segment(self.p3, self.p5, self.p4, self.cw).points(0.005)
        return [self.p1, self.p2] + arc_in + arc_out + [self.p1]


def _fits(lead: Lead, wall: Polygon, pocket: bool, roughed: Polygon | None) -> bool:
    line = LineString(lead.polyline())
    if pocket:
        ok = wall.buffer(1e-4).contains(line)
        return ok and (roughed is None or roughed.buffer(1e-4).contains(Point(lead.p1)))
    return not wall.buffer(-1e-4).intersects(line)


def plan_lead(lap, wall: Polygon, radius: float, pocket: bool, roughed: Polygon | None,
              tangent=None) -> Lead | None:
    """The largest lead (``radius``, halved until it fits) onto ``lap[0]``, or None;
    ``tangent``: the wall's direction there (else from ``lap[0]`` to the next point)."""
    s = lap[0]
    t = tangent or _unit(s, next(p for p in lap[1:] if math.dist(p, s) > 1e-3))
    n = (-t[1], t[0])
    probe = Point(s[0] + 0.01 * n[0], s[1] + 0.01 * n[1])
    if wall.contains(probe) != pocket:
        n = (t[1], -t[0])
    while radius >= 0.05:
        lead = Lead(s, t, n, radius)
        if _fits(lead, wall, pocket, roughed):
            return lead
        radius /= 2
    return None


def walls(path: Path, wall: Polygon, hint, cut: Cutting, ccw: bool, pocket: bool,
          roughed: Polygon | None, note: str) -> None:
    """Finish the boundary of ``wall`` (the tool-centre region) on every layer."""
    lap = rings.lap_from(rings.ring_points(wall, ccw), hint)
    lead = plan_lead(lap, wall, cut.clearance, pocket, roughed)
    each_wall_layer(path, cut, lead, lap[0], lambda: entry.lap(path, lap[1:], cut), note)


def each_wall_layer(path: Path, cut: Cutting, lead: Lead | None, start, lap, note: str) -> None:
    """On every layer down to the floor: down at point 1 (``start`` without a lead), the
    lead-in, ``lap()`` (the wall round from point 3 back to it), the lead-out."""
    start = lead.p1 if lead else start
    for k, z in enumerate(cut.layers(cut.floor)):
        path.note = f"{note} finish wall layer {k + 1}"
        entry.approach(path, cut, start, z)
        if lead:
            path.feed(*lead.p2, f=cut.feed)
            path.arc(*lead.p3, lead.p4, lead.cw, f=cut.feed)
        lap()
        if lead:
            path.arc(*lead.p5, lead.p4, lead.cw, f=cut.feed)
            path.feed(*lead.p1, f=cut.feed)
