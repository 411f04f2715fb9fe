"""Geometry of each feature kind, checked on its moves (issue 10's definitions)."""

from __future__ import annotations

import math

import pytest
import shapely

from app.gcode.features import (
    Cutting,
    Face,
    FeatureError,
    PocketCircle,
    PocketRect,
    Profile,
    Slot,
    parse_contour,
    toolpath,
)
from app.gcode.features.clearing import ring_offsets
from app.gcode.features.moves import ARC, FEED, RAPID

from .toolcheck import coverage, gouges, into_stock, swept, wall_error

PAPER = """G00 X10 Y10
G01 X5 Y25
G02 X15 Y35 R10
G03 X40 Y35 R30
G02 X50 Y25 R10
G01 Y20
G01 X45 Y10
G01 X30 Y7
G01 X10 Y10
"""

CUT = Cutting(tool_diameter=6, depth=3, stepdown=1.2, finish_xy=0.3, finish_z=0.2, feed=300, plunge_feed=100)


def _boundary(shape, step=0.25):
    ring = shape.exterior
    return [ring.interpolate(d).coords[0] for d in [k * step for k in range(int(ring.length / step))]]


POCKETS = [
    PocketRect(20, 20, 40, 25, CUT, corner_radius=4, angle=15),
    PocketRect(20, 20, 30, 14, CUT, corner_radius=3),
    PocketCircle(60, 60, 30, CUT),
    Slot(20, 30, 70, 50, 10, CUT),
    Profile(parse_contour(PAPER, "paper"), "inside", CUT),
]


@pytest.mark.parametrize("feature", POCKETS, ids=lambda f: f.kind)
def test_pocket_geometry(feature):
    moves = toolpath(feature)
    region = feature.region()
    r = CUT.radius
    assert gouges(moves, region.buffer(-r + 0.01), CUT.top) == 0
    assert min(m.end[2] for m in moves) == CUT.floor
    floor = swept(moves, CUT.floor, r)
    assert coverage(floor, region) >= 0.995
    reachable = region.buffer(-r).buffer(r)  # corners sharper than the tool stay round
    assert wall_error(moves, _boundary(reachable), CUT.floor, r) <= 0.02
    assert into_stock(moves, region, r, CUT.top) == []


def test_layers_at_most_stepdown_ending_at_the_floor():
    moves = toolpath(POCKETS[2])
    levels = sorted({round(m.end[2], 9) for m in moves if m.kind == ARC and m.end[2] < CUT.top}, reverse=True)
    flat = sorted({round(m.end[2], 9) for m in moves if m.kind == FEED}, reverse=True)
    cut_levels = [z for z in flat if z < CUT.top]
    assert cut_levels[-1] == CUT.floor
    steps = [a - b for a, b in zip([CUT.top] + cut_levels, cut_levels, strict=False)]
    assert max(steps) <= CUT.stepdown + 1e-9
    assert levels  # the centre is entered by a helix (arcs that descend)


def test_pocket_entries_are_helices_or_ramps_at_plunge_feed():
    moves = toolpath(POCKETS[0])
    pos = moves[0].end
    for m in moves[1:]:
        if m.kind in (FEED, ARC) and m.end[2] < pos[2] - 1e-9 and m.end[2] < CUT.top:
            assert m.feed == CUT.plunge_feed
        pos = m.end


def test_island_of_the_paper():
    """N5 G104 Z-5 K5 H12 D12 E0 T02, N6 G105 P7 Q15 B75 C1 R2 M15 U0.5 W0 S1000 F150: the
    paper's simulation shows 5 layers of 2 rings each; ours too, then the finishing pass."""
    cut = Cutting(tool_diameter=12, depth=5, stepdown=1, stepover=75, finish_xy=0.5, clearance=2,
                  feed=150, plunge_feed=80, rpm=1000)
    island = Profile(parse_contour(PAPER, "paper"), "outside", cut, stock=15)
    assert len(ring_offsets(cut, 15)) == 2
    moves = toolpath(island)
    notes = {m.note.split(" z ")[0] for m in moves if m.note.startswith("layer")}
    assert notes == {f"layer {k}/5" for k in range(1, 6)}
    shape = island.region()
    r = cut.radius
    allowed = shapely.geometry.box(-100, -100, 200, 200).difference(shape.buffer(r - 0.01))
    assert gouges(moves, allowed, cut.top) == 0
    ring = shape.buffer(15).difference(shape)
    assert coverage(swept(moves, cut.floor, r), ring) >= 0.995
    assert wall_error(moves, _boundary(shape), cut.floor, r) <= 0.02
    assert into_stock(moves, shape.buffer(15), r, cut.top) == []
    assert min(m.end[2] for m in moves) == cut.floor


def test_face_covers_the_rectangle_in_layers():
    face = Face(10, 10, 50, 30, Cutting(tool_diameter=10, depth=1, stepdown=0.4))
    moves = toolpath(face)
    region = shapely.geometry.box(10, 10, 60, 40)
    assert coverage(swept(moves, -1.0, 5), region) >= 0.995
    assert into_stock(moves, region, 5, 0.0) == []
    assert min(m.end[2] for m in moves) == -1.0


def test_slot_as_wide_as_the_tool_is_ramped_along_its_centre_line():
    slot = Slot(10, 10, 40, 10, 6, CUT)
    moves = toolpath(slot)
    ys = {round(m.end[1], 9) for m in moves}
    assert ys == {10.0}
    assert into_stock(moves, slot.region(), CUT.radius, CUT.top) == []
    assert min(m.end[2] for m in moves) == CUT.floor


@pytest.mark.parametrize(("corner", "cut_radius"), [(5.0, 5.0), (1.0, 3.0), (0.0, 3.0)])
def test_corners_round_as_asked_or_as_far_as_the_tool_reaches(corner, cut_radius):
    """Corner radius >= tool radius: the corner is that arc; smaller: the tool's own radius."""
    moves = toolpath(PocketRect(0, 0, 30, 20, CUT, corner_radius=corner))
    floor = swept(moves, CUT.floor, CUT.radius)
    c = cut_radius
    on_arc = (c - c * math.cos(math.pi / 4), c - c * math.sin(math.pi / 4))
    assert floor.distance(on_arc) - CUT.radius <= 0.02
    assert not floor.covers([on_arc[0] - 0.05], [on_arc[1] - 0.05])[0]


def test_rapids_stay_at_safe_height_when_moving_sideways():
    for feature in POCKETS:
        moves = toolpath(feature)
        pos = moves[0].end
        for m in moves[1:]:
            if m.kind == RAPID and math.dist(pos[:2], m.end[:2]) > 1e-9:
                assert pos[2] >= CUT.safe_z - 1e-9 and m.end[2] >= CUT.safe_z - 1e-9
            pos = m.end


@pytest.mark.parametrize("stepover", [75.0, 100.0])
def test_a_wide_stepover_still_cuts_the_whole_floor(stepover):
    """Between the rings near a sharp corner (and where a ring ends) a wide stepover would
    leave stock: the spacing narrows there, the floor is still cut and nothing rapids into it."""
    cut = Cutting(tool_diameter=6, depth=2, stepdown=1, stepover=stepover, finish_xy=0.3)
    for feature in (PocketRect(20, 20, 40, 25, cut, angle=15), Profile(parse_contour(PAPER), "inside", cut)):
        moves = toolpath(feature)
        region = feature.region()
        reachable = region.buffer(-cut.radius).buffer(cut.radius)  # a round tool leaves sharp corners
        assert coverage(swept(moves, cut.floor, cut.radius), reachable) >= 0.995
        assert into_stock(moves, region, cut.radius, cut.top) == []


def test_island_rings_follow_the_papers_h_i():
    """H_i = M - D/2 - (i-1)·B·D/100 while more than D/2 + U, then D/2 + U."""
    paper = Cutting(tool_diameter=12, depth=5, stepover=75, finish_xy=0.5)
    assert ring_offsets(paper, 15) == [9.0, 6.5]
    other = Cutting(tool_diameter=6, depth=5, stepover=50, finish_xy=0.5)
    assert ring_offsets(other, 20) == pytest.approx([17, 14, 11, 8, 5, 3.5])
    assert ring_offsets(other, 2) == [3.5]  # less stock than a ring: one ring at D/2 + U


ARC_FIRST = """G00 X60 Y40
G02 X40 Y60 R20
G01 X20 Y60
G01 X20 Y30
G01 X60 Y30
G01 X60 Y40
"""


@pytest.mark.parametrize("climb", [True, False], ids=["climb-G41", "conventional-G42"])
@pytest.mark.parametrize("text", [PAPER, ARC_FIRST], ids=["paper", "arc-first"])
def test_island_rings_by_cutter_compensation_keep_the_geometry(text, climb):
    cut = Cutting(tool_diameter=6, depth=2, stepdown=1, stepover=50, finish_xy=0.3, finish_z=0.2, climb=climb)
    island = Profile(parse_contour(text), "outside", cut, stock=8)
    moves = toolpath(island)
    shape, r = island.region(), cut.radius
    allowed = shapely.geometry.box(-100, -100, 200, 200).difference(shape.buffer(r - 0.01))
    assert gouges(moves, allowed, cut.top) == 0
    assert coverage(swept(moves, cut.floor, r), shape.buffer(8).difference(shape)) >= 0.995
    assert wall_error(moves, _boundary(shape), cut.floor, r) <= 0.02
    assert into_stock(moves, shape.buffer(8), r, cut.top) == []
    assert min(m.end[2] for m in moves) == cut.floor


def test_the_finish_goes_round_convex_corners_on_true_arcs():
    """What the compensation computes: an arc of radius D/2 about each convex corner."""
    cut = Cutting(tool_diameter=12, depth=5, stepdown=1, stepover=75, finish_xy=0.5, clearance=2)
    moves = toolpath(Profile(parse_contour(PAPER), "outside", cut, stock=15))
    arcs = [(m, prev) for prev, m in zip(moves, moves[1:], strict=False)
            if m.kind == ARC and m.note.startswith("island finish")]
    for corner in [(50.0, 20.0), (45.0, 10.0), (30.0, 7.0), (10.0, 10.0)]:
        about = [(m, prev) for m, prev in arcs if math.dist(m.center, corner) < 1e-9]
        assert about, corner
        for m, prev in about:
            assert math.dist(m.end[:2], corner) == pytest.approx(6.0, abs=1e-9)
            assert math.dist(prev.end[:2], corner) == pytest.approx(6.0, abs=1e-9)


def test_a_ring_the_compensation_refuses_is_reported_with_its_line():
    """A concave arc tighter than the ring offset: rs274 (and a Fanuc) refuse the ring."""
    dent = "G00 X20 Y20\nG01 Y60\nG01 X35\nG03 X45 Y60 R5\nG01 X60\nG01 Y20\nG01 X20\n"
    cut = Cutting(tool_diameter=12, depth=2, stepover=75, finish_xy=0.5)
    with pytest.raises(FeatureError) as caught:
        toolpath(Profile(parse_contour(dent, "dent.nc"), "outside", cut, stock=15))
    assert caught.value.field == "contour"
    assert "Tool radius not less than arc radius with comp" in str(caught.value)
    assert "dent.nc, line 4: cutter compensation at offset H = 9 mm refuses it" in str(caught.value)


NARROW = "G00 X20 Y20\nG01 X60 Y20\nG01 X60 Y30\nG01 X20 Y30\nG01 X20 Y20\n"
NARROW_SHORT_FIRST = "G00 X60 Y20\nG01 X60 Y30\nG01 X20 Y30\nG01 X20 Y20\nG01 X60 Y20\n"


@pytest.mark.parametrize("text", [NARROW, NARROW_SHORT_FIRST], ids=["long-side-first", "short-side-first"])
def test_a_narrow_contour_pocket_gets_a_smaller_lead_that_fits(text):
    """10 mm wide, a 6 mm tool: the lead shrinks (and point 1 moves over point 2 where rs274
    cannot join the paper's entry line to a small arc) until the finish stays in the pocket."""
    feature = Profile(parse_contour(text, "narrow"), "inside", CUT)
    moves = toolpath(feature)
    forms = {m.block for m in moves if m.block is not None}
    assert len(forms) == 1 and forms.pop().lead < CUT.clearance
    region, r = feature.region(), CUT.radius
    assert gouges(moves, region.buffer(-r + 0.01), CUT.top) == 0
    assert wall_error(moves, _boundary(region.buffer(-r).buffer(r)), CUT.floor, r) <= 0.02
    assert into_stock(moves, region, r, CUT.top) == []
