"""The Fanuc 21 / 31 programs expand, through the loader, to the same moves as the
plain program (0.001 mm), through the expander of issue 9 (``app.gcode.macro``).

A profile's macro program sets radius registers (``G10 L12``) and compensates with
``G41 D``/``G42 D``: it is loaded with a tool table holding that register, as the
control that runs it has one."""

from __future__ import annotations

import pytest

from app.gcode import load_text
from app.gcode.features import (
    Cutting,
    Face,
    PocketCircle,
    PocketRect,
    Profile,
    Slot,
    holes_circle,
    holes_row,
    parse_contour,
    program_moves,
    write_plain,
)
from app.gcode.features.fanuc import write_fanuc
from app.gcode.features.generate import toolpath
from app.gcode.tools import Tool

from .test_geometry import PAPER
from .test_program import PAPER_MOVED

CUT = Cutting(tool_diameter=6, depth=3, stepdown=1, finish_xy=0.2, finish_z=0.2)
ISLAND = Cutting(tool_diameter=12, depth=5, stepdown=1, stepover=75, finish_xy=0.5, clearance=2, feed=150,
                 rpm=1000, tool=2)
FEATURES = [
    PocketRect(20, 20, 40, 25, CUT, corner_radius=4, angle=15),
    PocketCircle(60, 60, 30, CUT),
    Slot(20, 20, 60, 40, 8, CUT),
    Slot(20, 20, 60, 20, 6, CUT),
    Face(10, 10, 50, 30, CUT),
    holes_circle(70, 70, 40, 6, CUT, peck=1, dwell=0.5),
    holes_row(20, 100, 4, 12, CUT),
    Profile(parse_contour(PAPER_MOVED, "paper"), "outside", ISLAND, stock=15),
    Profile(parse_contour(PAPER_MOVED, "paper"), "inside", CUT),
]


TOOLS = {1: Tool(1, 6), 2: Tool(2, 12)}


def _same(plain: list[dict], macro: list[dict]) -> None:
    assert len(macro) == len(plain)
    for a, b in zip(plain, macro, strict=True):
        assert a["kind"] == b["kind"]
        for key in ("end", "center"):
            if key in a:
                assert max(abs(u - v) for u, v in zip(a[key], b[key], strict=True)) <= 0.001, (a, b)
        for key in ("feed", "seconds", "turn"):
            assert a.get(key) == b.get(key)


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
@pytest.mark.parametrize("feature", FEATURES, ids=lambda f: f"{f.kind}")
def test_macro_program_expands_to_the_plain_moves(feature, dialect):
    moves = program_moves([feature])
    plain = load_text(write_plain(moves), "plain.nc")
    text = write_fanuc(moves, dialect)
    macro = load_text(text, "macro.nc", tools=TOOLS)
    assert plain.errors == [] and macro.errors == []
    _same(plain.moves, macro.moves)


def test_the_dialects_keep_to_what_each_control_has():
    moves = program_moves([FEATURES[1], FEATURES[5]])
    f21, f31 = write_fanuc(moves, "fanuc21"), write_fanuc(moves, "fanuc31")
    assert "WHILE" not in f21 and "G65" not in f21 and "M98 P1001" in f21 and "GOTO" in f21
    assert "WHILE [#102 LE" in f31 and "G65 P1001 Z#101" in f31 and "M98" not in f31
    assert f21.count("O1001") == 1 and "M99" in f21


def test_a_job_of_several_features_with_a_tool_change():
    job = [FEATURES[0], FEATURES[7], FEATURES[4]]
    moves = program_moves(job)
    plain = load_text(write_plain(moves))
    for dialect in ("fanuc21", "fanuc31"):
        macro = load_text(write_fanuc(moves, dialect), tools=TOOLS)
        assert macro.errors == []
        _same(plain.moves, macro.moves)
        assert len(macro.pauses) == len(plain.pauses) == 2  # T2 for the island, T1 again for the face


def _round_trip(moves, dialect: str, tools=None) -> str:
    plain = load_text(write_plain(moves), "plain.nc")
    text = write_fanuc(moves, dialect)
    macro = load_text(text, "macro.nc", tools=tools or TOOLS)
    assert plain.errors == [] and macro.errors == []
    _same(plain.moves, macro.moves)
    return text


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_the_papers_worked_example_as_the_paper_programs_it(dialect):
    """The issue's contour where the paper has it (N5 G104 Z-5 K5 H12 D12 E0 T02, N6 G105 P7
    Q15 B75 C1 R2 M15 U0.5 W0 S1000 F150): the contour once, rings by the radius register."""
    island = Profile(parse_contour(PAPER, "paper"), "outside", ISLAND, stock=15)
    text = _round_trip(toolpath(island), dialect)
    assert text.count("G03 X40 Y35") == 1  # the contour is written once
    assert "G10 L12 P2 R" in text and "G41 D2" in text and "G40" in text and "M98 P1001" in text
    if dialect == "fanuc31":
        assert "G65 P1002 H#103" in text and "G65 P1002 H6.5" in text and "G65 P1002 H6\n" in text
        assert "WHILE [#102 LE 5] DO 1" in text and "M98 P1002" not in text
    else:
        assert "WHILE" not in text and "G65" not in text and "IF [#102 GT 5] GOTO" in text
        assert "#105 = 9" in text and "#105 = 6.5" in text and "#105 = 6\n" in text


SQUARE_ARC_FIRST = """G00 X60 Y40
G02 X40 Y60 R20
G01 X20 Y60
G01 X20 Y30
G01 X60 Y30
G01 X60 Y40
"""


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
@pytest.mark.parametrize("climb", [True, False], ids=["climb-G41", "conventional-G42"])
@pytest.mark.parametrize("side", ["outside", "inside"])
def test_profiles_both_ways_with_an_arc_first_and_a_floor_pass(dialect, climb, side):
    cut = Cutting(tool_diameter=6, depth=2.5, stepdown=1, stepover=50, finish_xy=0.3, finish_z=0.2,
                  climb=climb, tool=1)
    feature = Profile(parse_contour(SQUARE_ARC_FIRST, "arc-first"), side, cut, stock=8)
    text = _round_trip(program_moves([feature]), dialect)
    assert ("G41 D1" in text) == climb and ("G42 D1" in text) == (not climb)


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_a_narrow_pocket_with_a_small_lead(dialect):
    from .test_geometry import CUT as NARROW_CUT
    from .test_geometry import NARROW, NARROW_SHORT_FIRST

    for text in (NARROW, NARROW_SHORT_FIRST):
        _round_trip(program_moves([Profile(parse_contour(text, "narrow"), "inside", NARROW_CUT)]), dialect)


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_two_profiles_in_one_job_have_their_own_programs_and_labels(dialect):
    job = [FEATURES[7], FEATURES[8]]
    text = _round_trip(program_moves(job), dialect)
    for number in (1001, 1002, 1003, 1004):
        assert text.count(f"\nO{number} ") == 1
    assert "G41 D2" in text and "G41 D1" in text


@pytest.mark.parametrize("feature", [FEATURES[5], FEATURES[6]], ids=["holes-circle", "holes-row"])
@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_a_hole_pattern_is_a_loop_over_its_holes_and_one_subprogram(feature, dialect):
    moves = program_moves([feature])
    text = write_fanuc(moves, dialect)
    assert text.count("O1001") == 2 and text.count("M99") == 1  # called in the loop, defined once
    assert "#110" in text and ("WHILE [#110 LT" in text if dialect == "fanuc31" else "GOTO 7000" in text)
    motion = [line for line in text.splitlines() if line[:3] in ("G00", "G01")]
    assert len(motion) < 12  # not one block per move: the loop makes them
    _same(load_text(write_plain(moves)).moves, load_text(text).moves)


@pytest.mark.parametrize("feature", FEATURES[:5], ids=lambda f: f.kind)
def test_every_layer_of_a_pocket_slot_or_face_is_one_subprogram_in_a_loop(feature):
    moves = program_moves([feature])
    count = lambda text: sum(line[:3] in ("G00", "G01", "G02", "G03") for line in text.splitlines())  # noqa: E731
    plain = count(write_plain(moves))
    for dialect in ("fanuc21", "fanuc31"):
        text = write_fanuc(moves, dialect)
        assert "M99" in text and ("WHILE [" in text if dialect == "fanuc31" else "GOTO" in text)
        assert count(text) <= 0.55 * plain, (dialect, count(text), plain)  # layer 1 is not written out
