"""Features -> moves: one pure function per kind, and a program of several features.

Every toolpath starts and ends at the feature's safe height (``top + clearance``).
Pockets: roughing layers of at most C down to the floor + W (rings at D/2 + U), a floor
pass at the floor when W > 0, then the walls at D/2 on every layer; a rectangular or
round pocket or a wide slot by its rings of a rounded rectangle (``round_pocket.py``),
any other shape by the offsets of its outline (``clearing.Pocket``). Profiles (an island,
or the walls of a contour pocket) are the paper's compensated program (``profile.py``).
"""

from __future__ import annotations

from dataclasses import replace

from app.profile import MachineProfile

from . import entry, finish, rings
from .clearing import Pocket
from .cutting import Cutting
from .face_macro import face_form
from .holes_macro import HolePattern, peck_depths
from .kinds import Face, Holes, PocketCircle, PocketRect, Profile, Slot
from .moves import RAPID, SPINDLE, TOOL, Move, Path
from .profile import profile_moves
from .round_pocket import pocket_form
from .travel import check_travel


def _start(cut: Cutting, xy) -> Path:
    """A path whose first move is the rapid over ``xy`` at the safe height."""
    path = Path((xy[0], xy[1], cut.safe_z))
    path.moves.append(Move(RAPID, path.pos))
    return path


def _rough(path: Path, area, cut: Cutting) -> None:
    """Every roughing layer; each ends up at the safe height over where the next begins,
    so all layers are the same moves at their own depth (a macro loops over one)."""
    bottom = cut.floor + cut.finish_z
    levels = cut.layers(bottom) + ([cut.floor] if cut.finish_z > 0 else [])
    z_from = cut.top
    for k, z in enumerate(levels):
        note = f"layer {k + 1}/{len(levels)} z {z:.3f}"
        area.layer(path, z_from, z, note)
        entry.retract(path, cut)  # under the layer's last note: one block per layer
        path.rapid(*area.entry_xy())
        z_from = z


def _pocket(feature, ccw_for_climb: bool = True) -> list[Move]:
    cut = feature.cut
    ccw = cut.climb == ccw_for_climb
    form = pocket_form(feature, ccw)  # rectangle, circle, slot: rings computed from a few numbers
    if form is not None:
        return form.moves()
    region = feature.region()
    pocket = Pocket(region, cut, ccw)
    path = _start(cut, rings.centre_of(region))
    _rough(path, pocket, cut)
    roughed = region.buffer(-(cut.radius + cut.finish_xy))
    for k, wall in enumerate(rings.offset(region, -cut.radius)):
        finish.walls(path, wall, feature.hint(), cut, ccw, True, roughed, f"area {k + 1}")
    path.note = ""
    entry.retract(path, cut)
    return path.moves


def _slot(feature: Slot) -> list[Move]:
    if not feature.exact:
        return _pocket(feature)
    cut = feature.cut
    a, b = (feature.x1, feature.y1), (feature.x2, feature.y2)
    path = _start(cut, a)
    z_from = cut.top
    for k, z in enumerate(cut.layers(cut.floor)):
        path.note = f"layer {k + 1} z {z:.3f}"
        entry.approach(path, cut, a, z_from)
        entry.ramp(path, [a, b, a], z, cut)
        z_from = z
    path.note = ""
    entry.retract(path, cut)
    return path.moves


def _profile(feature: Profile) -> list[Move]:
    """The paper's program (``profile.py``): rings and finish by cutter compensation;
    a pocket of the contour is roughed by ``Pocket`` first."""
    cut = feature.cut
    inside = feature.side == "inside"
    if not inside:
        return profile_moves(feature, inside)
    region = feature.region()
    path = _start(cut, rings.centre_of(region))
    _rough(path, Pocket(region, cut, cut.climb), cut)
    path.note = ""
    entry.retract(path, cut)
    return path.moves + profile_moves(feature, inside)


def _face(feature: Face) -> list[Move]:
    return face_form(feature).moves()


def _holes(feature: Holes) -> list[Move]:
    cut = feature.cut
    path = _start(cut, feature.centres[0])
    for k, xy in enumerate(feature.centres):
        path.note = f"hole {k + 1}/{len(feature.centres)}"
        entry.retract(path, cut)
        entry.approach(path, cut, xy, cut.top)
        for k, target in enumerate(peck_depths(cut, feature.peck)):
            if k:  # a peck: back out above the top, feed down the drilled hole
                path.rapid(z=cut.top + entry.GAP)
            path.feed(z=target, f=cut.plunge_feed)
        if feature.dwell > 0:
            path.dwell(feature.dwell)
        path.rapid(z=cut.safe_z)
    if not feature.layout:
        return path.moves
    form = HolePattern(feature.layout, len(feature.centres), feature.peck)  # the macro's parametric form
    return [replace(m, block=form) for m in path.moves]


GENERATORS = {PocketRect: _pocket, PocketCircle: _pocket, Slot: _slot, Profile: _profile,
              Face: _face, Holes: _holes}


def toolpath(feature) -> list[Move]:
    """The moves of one feature, from and back to its safe height."""
    return GENERATORS[type(feature)](feature)


def program_moves(features, profile: MachineProfile | None = None) -> list[Move]:
    """The moves of several features in order, with a tool change where the tool
    differs and the spindle started at each feature's speed; checked against the
    machine's travel (``FeatureError`` naming the axis and direction)."""
    profile = profile or MachineProfile()
    moves: list[Move] = []
    tool, rpm = None, None
    for feature in features:
        cut = feature.cut
        body = toolpath(feature)
        check_travel(body, cut, profile)
        if tool is not None and cut.tool != tool:
            moves.append(Move(SPINDLE, moves[-1].end, value=0))
            moves.append(Move(TOOL, moves[-1].end, value=cut.tool))
            rpm = None
        if cut.rpm != rpm:
            moves.append(Move(SPINDLE, moves[-1].end if moves else body[0].end, value=cut.rpm))
        tool, rpm = cut.tool, cut.rpm
        moves += body
    return moves
