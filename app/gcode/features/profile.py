"""A profile feature in the paper's form (``paper.PaperForm``), its lead fitted.

An island (outside): roughing phases at the paper's ring offsets H_i on every level
down to the floor + W (and the floor when W > 0), then the finish at D/2 on every
level. A pocket of the contour (inside): the finish at D/2 only (its area is roughed by
``clearing.Pocket``). The lead radius starts at the clearance R and is halved (each
with the paper's point 1, then with point 1 over point 2: ``PaperForm.shift``) until
the compensated moves keep the tool out of the island (or inside the pocket) and the
descent point is over open or roughed area; none fitting down to 0.05 mm is a
``FeatureError`` (the compensation's own refusal when it refused every lead).
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import Point

from app.i18n import msg

from .clearing import ring_offsets
from .contour import Segment
from .errors import FeatureError
from .moves import ARC, RAPID, Move
from .paper import PaperForm, Phase, form_moves, oriented, split_first

SLACK = 0.005  # mm a checked tool centre may come nearer the wall than its radius
MIN_LEAD = 0.05  # mm


def _normal(t, left: bool) -> tuple[float, float]:
    return (-t[1], t[0]) if left else (t[1], -t[0])


def _centres(moves: list[Move], below: float) -> np.ndarray:
    """Tool-centre XY points (every 0.2 mm) of the cutting moves below ``below``."""
    pts, pos = [], None
    for m in moves:
        if pos is not None and m.kind != RAPID and min(pos[2], m.end[2]) < below:
            if m.kind == ARC:
                flat = [pos[:2]] + Segment(pos[:2], m.end[:2], m.center, m.cw).points(0.002)
            else:
                count = max(1, math.ceil(math.dist(pos[:2], m.end[:2]) / 0.2))
                flat = [(pos[0] + (m.end[0] - pos[0]) * k / count, pos[1] + (m.end[1] - pos[1]) * k / count)
                        for k in range(count + 1)]
            pts += flat
        pos = m.end
    return np.array(pts) if pts else np.zeros((0, 2))


def _fits(form: PaperForm, moves: list[Move], shape, inside: bool) -> bool:
    r = form.cut.radius
    pts = _centres(moves, form.cut.top - 1e-6)
    if inside:
        allowed = shape.buffer(-(r - SLACK))
        roughed = shape.buffer(-(r + form.cut.finish_xy) + 1e-4)
        down = [form.descent(p) for p in form.phases]
        ok = all(roughed.contains(Point(d)) for d in down)
        return ok and bool(shapely.contains_xy(allowed, pts[:, 0], pts[:, 1]).all())
    banned = shape.buffer(r - SLACK)
    return not bool(shapely.contains_xy(banned, pts[:, 0], pts[:, 1]).any())


def _form(feature, phases, lead: float, shift: float, inside: bool) -> PaperForm:
    cut = feature.cut
    ccw = inside == cut.climb
    path, t = split_first(oriented(feature.contour.segments, ccw))
    open_at = 0.0 if inside else feature.removed_stock + cut.radius + 1.0
    return PaperForm(feature.contour.name, tuple(path), t, _normal(t, cut.climb), cut.climb, max(cut.tool, 1),
                     lead, open_at, shift, tuple(phases), cut)


def profile_moves(feature, inside: bool) -> list[Move]:
    """The moves of the paper's program for ``feature`` (see the module docstring)."""
    cut = feature.cut
    finish = Phase(tuple(cut.layers(cut.floor)), (cut.radius,),
                   "pocket finish wall layer" if inside else "island finish wall layer")
    phases = [finish]
    if not inside:
        levels = cut.layers(cut.floor + cut.finish_z) + ([cut.floor] if cut.finish_z > 0 else [])
        phases.insert(0, Phase(tuple(levels), tuple(ring_offsets(cut, feature.removed_stock)), "layer"))
    shape = feature.region()
    lead, refused, loaded = cut.clearance, None, False
    while lead >= MIN_LEAD:
        for shift in (0.0, -1.0):
            form = _form(feature, phases, lead, shift, inside)
            try:
                moves = form_moves(form)
            except FeatureError as exc:
                refused = refused or exc  # the first: at the largest lead
            else:
                if _fits(form, moves, shape, inside):
                    return moves
                loaded = True
        lead /= 2
    if refused is not None and not loaded:  # refused whatever the lead: the rings themselves
        raise refused
    raise FeatureError("clearance", msg("no tangent lead of radius {low:g} to {high:g} mm onto the first "
                                        "segment of {name} keeps the tool clear of the contour",
                                        low=MIN_LEAD, high=cut.clearance, name=feature.contour.name))
