"""Every accepted feature roughs its whole area, enters material by a ramp or a helix,
never rapids below the stock top, and cuts its shape to depth without gouging it
(issue 19), checked on a height map of the stock (``stock.py``) over all kinds with
parameters drawn by hypothesis; an allowance that leaves nothing to rough is refused
naming the field."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from shapely.geometry import Point, box

from app.gcode.features import (
    Cutting,
    Face,
    FeatureError,
    PocketCircle,
    PocketRect,
    Profile,
    Slot,
    holes_circle,
    holes_row,
    parse_contour,
    toolpath,
)

from .stock import GRID, Stock

SETTINGS = settings(max_examples=8, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
PAPER = ("G00 X10 Y10\nG01 X5 Y25\nG02 X15 Y35 R10\nG03 X40 Y35 R30\nG02 X50 Y25 R10\nG01 Y20\n"
         "G01 X45 Y10\nG01 X30 Y7\nG01 X10 Y10\n")
CIRCLE = "G00 X30 Y20\nG02 X30 Y20 I-12 J0\n"  # a single full circle is a contour
LEVEL = 1e-3  # mm: the floor as cut


@st.composite
def cuttings(draw, tool_max: float = 8.0) -> Cutting:
    tool = draw(st.sampled_from([2.0, 3.0, 4.0, 6.0, tool_max]))
    depth = draw(st.sampled_from([0.5, 1.0, 2.5, 3.0]))
    stepdown = draw(st.sampled_from([0.4, 1.0, 1.5, 4.0]))
    return Cutting(tool_diameter=tool, depth=depth, stepdown=stepdown,
                   stepover=draw(st.sampled_from([25.0, 40.0, 60.0, 100.0])),
                   finish_xy=draw(st.sampled_from([0.0, 0.2, tool / 2])),
                   finish_z=min(draw(st.sampled_from([0.0, 0.1, 0.3])), stepdown, depth / 2),
                   top=draw(st.sampled_from([0.0, 2.0])), climb=draw(st.booleans()))


def _accepted(make):
    try:
        feature = make()
    except FeatureError as exc:
        event(f"refused: {exc.field}")
        return None  # a refusal is checked by the tests of refusals
    event("accepted")
    return feature


def _cut(feature, moves, solid=None, drilling=False):
    cut = feature.cut
    x0, y0, x1, y1 = (solid or feature.region()).bounds
    margin = cut.tool_diameter + cut.clearance + 2
    stock = Stock((x0 - margin, y0 - margin, x1 + margin, y1 + margin), cut.top, cut.radius, solid)
    bad = stock.run(moves, moves[0].end, drilling)
    assert not bad, bad[:5]
    return stock


def _pocket_checks(feature):
    cut, region = feature.cut, feature.region()
    moves = toolpath(feature)
    first_finish = next(k for k, m in enumerate(moves) if "finish" in m.note)
    rough = moves[:first_finish]
    roughed = _cut(feature, rough)
    reach = region.buffer(-(cut.radius + cut.finish_xy)).buffer(cut.radius - 2 * GRID)  # the tool's reach
    assert roughed.cells(reach).any()
    assert roughed.left_above(reach, cut.floor + LEVEL) == 0, "roughing leaves stock inside the allowance"
    done = _cut(feature, moves)
    whole = region.buffer(-cut.radius).buffer(cut.radius - 2 * GRID)  # all a round tool reaches
    assert done.left_above(whole, cut.floor + LEVEL) == 0, "not cut to depth"
    outside = done.heights(region.buffer(2 * GRID).envelope.buffer(cut.tool_diameter).difference(
        region.buffer(2 * GRID)))
    assert (outside == cut.top).all(), "gouges the wall"


@SETTINGS
@given(cuttings(), st.floats(10, 40), st.floats(10, 30), st.floats(0, 5), st.floats(-30, 30))
def test_rect_pockets(cut, width, height, corner, angle):
    feature = _accepted(lambda: PocketRect(20, 20, width, height, cut, min(corner, height / 2), angle))
    if feature is not None:
        _pocket_checks(feature)


@SETTINGS
@given(cuttings(), st.floats(9, 40))
def test_circle_pockets(cut, diameter):
    feature = _accepted(lambda: PocketCircle(40, 40, diameter, cut))
    if feature is not None:
        _pocket_checks(feature)


@SETTINGS
@given(cuttings(), st.floats(5, 30), st.floats(-20, 20), st.floats(4, 14))
def test_slots(cut, dx, dy, width):
    feature = _accepted(lambda: Slot(20, 30, 20 + dx, 30 + dy, width, cut))
    if feature is not None:
        _pocket_checks(feature)


@SETTINGS
@given(cuttings(tool_max=6.0), st.sampled_from([PAPER, CIRCLE]))
def test_contour_pockets(cut, text):
    feature = _accepted(lambda: Profile(parse_contour(text, "c.nc"), "inside", cut))
    if feature is not None:
        _pocket_checks(feature)


@SETTINGS
@given(cuttings(tool_max=6.0), st.sampled_from([PAPER, CIRCLE]), st.sampled_from([0.0, 4.0, 9.0]))
def test_islands(cut, text, stock):
    feature = _accepted(lambda: Profile(parse_contour(text, "c.nc"), "outside", cut, stock))
    if feature is None:
        return
    island = feature.region()
    solid = island.buffer(feature.removed_stock)
    done = _cut(feature, toolpath(feature), solid)
    assert done.left_above(solid.difference(island.buffer(2 * GRID)), cut.floor + LEVEL) == 0, "stock left"
    assert (done.heights(island.buffer(-2 * GRID)) == cut.top).all(), "gouges the island"


@SETTINGS
@given(cuttings(), st.floats(5, 40), st.floats(5, 30))
def test_faces(cut, width, height):
    feature = _accepted(lambda: Face(10, 10, width, height, cut))
    if feature is None:
        return
    solid = box(10, 10, 10 + width, 10 + height)
    done = _cut(feature, toolpath(feature), solid)
    assert done.left_above(solid, cut.floor + LEVEL) == 0


@SETTINGS
@given(cuttings(), st.integers(1, 7), st.sampled_from([0.0, 0.7]), st.booleans())
def test_holes(cut, count, peck, on_circle):
    make = (lambda: holes_circle(40, 40, 30, count, cut, 10, peck)) if on_circle else \
        (lambda: holes_row(10, 10, count, 9, cut, 20, peck))
    feature = _accepted(make)
    if feature is None:
        return
    done = _cut(feature, toolpath(feature), box(0, 0, 80, 80), drilling=True)
    for x, y in feature.centres:
        assert done.left_above(Point(x, y).buffer(cut.radius - 2 * GRID), cut.floor + LEVEL) == 0


def test_a_pocket_with_an_allowance_that_leaves_nothing_to_rough_is_refused():
    cut = Cutting(tool_diameter=6, depth=3, finish_xy=3)
    with pytest.raises(FeatureError) as caught:
        PocketRect(20, 20, 12, 25, cut)
    assert caught.value.field == "finish_xy" and "leaves nothing to rough" in str(caught.value)
    with pytest.raises(FeatureError) as caught:
        PocketRect(20, 20, 40, 25, Cutting(tool_diameter=6, depth=3, finish_xy=10))
    assert caught.value.field == "finish_xy" and "at most the tool's radius 3" in str(caught.value)


def test_the_issue_pocket_is_roughed_now():
    feature = PocketRect(20, 20, 40, 25, Cutting(tool_diameter=6, depth=3, finish_xy=3))
    _pocket_checks(feature)
    assert np.isclose(min(m.end[2] for m in toolpath(feature)), -3)


TYPICAL_CUT = Cutting(tool_diameter=6, depth=3, stepdown=1, finish_xy=0.2, finish_z=0.2)


@pytest.mark.parametrize("make", [
    lambda: PocketRect(20, 20, 40, 25, TYPICAL_CUT, corner_radius=4, angle=15),
    lambda: PocketCircle(60, 60, 30, TYPICAL_CUT),
    lambda: Slot(20, 20, 60, 40, 8, TYPICAL_CUT),
    lambda: Profile(parse_contour(PAPER, "c.nc"), "inside", TYPICAL_CUT),
], ids=["rect", "circle", "slot", "contour"])
def test_typical_pockets_are_accepted_and_checked(make):
    """The property tests skip what the validator refuses: here a typical feature of each
    kind must be accepted and pass the same checks, so they can never check nothing."""
    _pocket_checks(make())
