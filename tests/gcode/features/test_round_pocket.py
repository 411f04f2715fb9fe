"""Rectangular and round pockets and wide slots as parametric programs (issue 19): the
rings of a rounded rectangle computed from its sizes and the ring's index in a loop,
one subprogram per ring kind, the layers in a loop; expanded by the loader they give the
plain program's moves (0.001 mm)."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.gcode import load_text
from app.gcode.features import (
    Cutting,
    Face,
    PocketCircle,
    PocketRect,
    Slot,
    holes_circle,
    holes_row,
    program_moves,
    write_plain,
)
from app.gcode.features.cli import main as feature_main
from app.gcode.features.fanuc import write_fanuc
from app.gcode.features.round_pocket import pocket_form

from .test_machining import SETTINGS, _accepted, cuttings
from .test_macro_roundtrip import _same

CUT = Cutting(tool_diameter=6, depth=3, stepdown=1, finish_xy=0.2, finish_z=0.2)
WIDE = Cutting(tool_diameter=4, depth=2.5, stepdown=0.8, stepover=100, clearance=0.3, top=2, climb=False)
FLAT = Cutting(tool_diameter=3, depth=1, stepdown=1, stepover=25, finish_xy=1.5)
POCKETS = [
    PocketRect(20, 20, 40, 25, CUT),
    PocketRect(20, 20, 40, 25, CUT, corner_radius=4, angle=15),
    PocketRect(30, 30, 50, 20, WIDE, corner_radius=10, angle=-30),  # a stadium: r is half a side
    PocketRect(10, 10, 30, 30, FLAT, corner_radius=2.5),  # rings change from sharp to round
    PocketCircle(60, 60, 30, CUT),
    PocketCircle(60, 60, 30, WIDE),
    PocketCircle(40, 40, 9, FLAT),
    Slot(20, 20, 60, 40, 8, CUT),
    Slot(20, 20, 20, 60, 12, WIDE),
    PocketRect(40, 40, 10, 10, Cutting(tool_diameter=4, depth=0.5, stepdown=0.4, stepover=60, climb=False)),
    PocketCircle(60, 60, 26, Cutting(tool_diameter=6, depth=1)),  # the lead's point 1 is the centre
]  # the second last: the helix ends where the first ring starts


def _motion(text: str) -> list[str]:
    return [line for line in text.splitlines() if line[:3] in ("G00", "G01", "G02", "G03")]


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
@pytest.mark.parametrize("feature", POCKETS, ids=lambda f: f.kind)
def test_a_pocket_is_loops_over_layers_and_computed_rings(feature, dialect):
    assert pocket_form(feature, feature.cut.climb) is not None
    moves = program_moves([feature])
    text = write_fanuc(moves, dialect)
    plain = load_text(write_plain(moves), "plain.nc")
    macro = load_text(text, "macro.nc")
    assert plain.errors == [] and macro.errors == []
    _same(plain.moves, macro.moves)
    ring = "WHILE [#134 LT" if dialect == "fanuc31" else "IF [#134 GE"
    assert ring in text and "#135 = [" in text and "#128 = [" in text  # each ring from its index
    layers = "WHILE [#102 LE" if dialect == "fanuc31" else "IF [#102 GT"
    assert layers in text
    subs = text.split("M30\n", 1)[1]
    rings = [block for block in subs.split("\nO")[1:] if block.startswith(("1002", "1003"))]
    assert rings and all("one ring" in block for block in rings)
    for block in rings:  # no point of a ring is written: every X and Y is computed
        for line in _motion(block):
            assert re.search(r"[XY]-?\d", line) is None, line


def test_the_program_does_not_grow_with_the_rings_or_the_layers():
    small = PocketCircle(60, 60, 30, CUT)
    deep = Cutting(tool_diameter=6, depth=12, stepdown=1, finish_xy=0.2, finish_z=0.2)
    big = PocketCircle(75, 75, 140, deep)
    for dialect in ("fanuc21", "fanuc31"):
        a, b = (write_fanuc(program_moves([f]), dialect) for f in (small, big))
        assert len(_motion(a)) == len(_motion(b)) < 40
        assert len(program_moves([big])) > 20 * len(_motion(b))


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_a_pocket_with_no_room_for_a_helix_keeps_its_points(dialect):
    """Too narrow for the helix (0.05 mm): the offset outlines and a ramp, written as in
    the plain program with the layers folded; still the same moves."""
    feature = PocketCircle(30, 30, 6.09, Cutting(tool_diameter=6, depth=1, stepdown=0.5))
    assert pocket_form(feature, True) is None
    moves = program_moves([feature])
    _same(load_text(write_plain(moves)).moves, load_text(write_fanuc(moves, dialect)).moves)


def test_the_command_writes_a_parametric_circle_pocket(capsys):
    args = ["pocket-circle", "--x", "60", "--y", "60", "--diameter", "50", "--tool-diameter", "3",
            "--depth", "6", "--macro", "fanuc31"]
    assert feature_main(args) == 0
    text = capsys.readouterr().out
    assert len(_motion(text)) < 40 and ("G65 P1002" in text or "G65 P1003" in text)
    assert load_text(text).errors == []


FACES = [Face(10, 10, 50, 30, CUT), Face(10, 10, 50, 28.2, WIDE), Face(10, 10, 40, 5, FLAT),
         Face(5, 5, 30, 20, Cutting(tool_diameter=4, depth=1, stepdown=1, stepover=30))]


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
@pytest.mark.parametrize("feature", FACES, ids=lambda f: f"{f.height:g}")
def test_a_face_is_loops_over_layers_and_computed_rows(feature, dialect):
    moves = program_moves([feature])
    text = write_fanuc(moves, dialect)
    _same(load_text(write_plain(moves)).moves, load_text(text).moves)
    rows = sum(m.kind == "feed" and m.end[1] != p.end[1] for p, m in zip(moves, moves[1:], strict=False))
    if rows > 3:  # two or more pairs of rows beyond the first: a loop computing each row's Y
        assert ("WHILE [#141 LE" if dialect == "fanuc31" else "IF [#141 GT") in text
        assert "Y[" in text and len(_motion(text)) < 16


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
@pytest.mark.parametrize("depth", [3.0, 20.0, 20.3])
def test_a_holes_pecks_are_a_loop_computing_each_depth(dialect, depth):
    cut = Cutting(tool_diameter=3, depth=depth, top=1)
    patterns = (holes_circle(60, 60, 40, 7, cut, peck=0.5, dwell=0.2), holes_row(20, 20, 5, 9, cut, peck=1.5))
    for feature in patterns:
        moves = program_moves([feature])
        text = write_fanuc(moves, dialect)
        _same(load_text(write_plain(moves)).moves, load_text(text).moves)
        assert len(_motion(text)) < 14
        if depth / feature.peck > 2:  # pecks between the first and the last
            assert ("WHILE [#113 LT" if dialect == "fanuc31" else "IF [#113 GE") in text
            assert "G01 Z[1 - #113*" in text


@SETTINGS
@given(cuttings(), st.sampled_from(["rect", "circle", "slot", "face"]), st.floats(10, 40), st.floats(10, 30),
       st.floats(0, 1), st.floats(-40, 40), st.sampled_from(["fanuc21", "fanuc31"]))
def test_any_pocket_or_face_expands_to_its_plain_moves(cut, kind, width, height, share, angle, dialect):
    """Whatever the sizes, corner, angle and cutting options: the parametric program gives
    the plain program's moves."""
    make = {"rect": lambda: PocketRect(40, 40, width, height, cut, share * min(width, height) / 2, angle),
            "circle": lambda: PocketCircle(60, 60, width, cut),
            "slot": lambda: Slot(60, 60, 60 + height * math.cos(math.radians(angle)),
                                 60 + height * math.sin(math.radians(angle)), width / 3, cut),
            "face": lambda: Face(20, 20, width, height, cut)}[kind]
    feature = _accepted(make)
    if feature is None:
        return
    moves = program_moves([feature])
    plain, macro = load_text(write_plain(moves)), load_text(write_fanuc(moves, dialect))
    assert plain.errors == [] and macro.errors == []
    _same(plain.moves, macro.moves)


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_hundreds_of_folded_layers_keep_their_depth(dialect):
    """A slot as wide as the tool, 567 layers of 0.03 mm (0.0299.. each): each layer's
    depth is computed from its index, never summed from a rounded step (0.01 mm off at
    the bottom before)."""
    feature = Slot(20, 20, 60, 40, 6, Cutting(tool_diameter=6, depth=17, stepdown=0.03))
    moves = program_moves([feature])
    text = write_fanuc(moves, dialect)
    assert "[#102 - 1]/566]" in text
    _same(load_text(write_plain(moves)).moves, load_text(text).moves)
