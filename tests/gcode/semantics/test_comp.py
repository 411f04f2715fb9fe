"""Cutter radius compensation: the path, the held move, the exits and the refusals
(the rs274 recordings in tests/oracle check the same geometry move by move)."""

from __future__ import annotations

import math

import pytest

from app.gcode.ops import DWELL, SPINDLE

from .conftest import ends

SQUARE = "G0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nX20\nY20\nX0\nY0\nG40 G1 X-10 Y-10\nM2\n"


def test_square_inside_on_the_left(run):
    """The square runs counter-clockwise: G41 keeps the tool inside, concave corners."""
    program = run(SQUARE)
    assert not program.errors
    pts = ends(program)
    assert math.isclose(math.hypot(*pts[1][:2]), 3.0, abs_tol=1e-4)  # entry: radius off (0, 0)
    assert program.moves[2]["kind"] == "arc" and pts[2] == [0, 3, 0]  # around the entry corner
    assert pts[3:6] == [[17, 3, 0], [17, 17, 0], [3, 17, 0]]  # concave: the ends meet inside
    assert pts[6] == [3, 0, 0]  # G40 writes the last move as it was held
    assert [m["line"] for m in program.moves] == [1, 2, 3, 3, 4, 5, 6, 7]


def test_square_outside_on_the_right_rounds_the_corners(run):
    program = run(SQUARE.replace("G41", "G42"))
    assert not program.errors
    pts = ends(program)
    assert [20, -3, 0] in pts and [23, 20, 0] in pts and [0, 23, 0] in pts
    arcs = [m for m in program.moves if m["kind"] == "arc"]
    assert len(arcs) == 3 and all(m["turn"] == 1 for m in arcs)
    assert [m["center"] for m in arcs] == [[20, 0], [20, 20], [0, 20]]


def test_rows_are_continuous(run):
    program = run(SQUARE.replace("G41", "G42"))
    starts = program.ops.starts()
    assert (starts[1:] == program.ops.end[:-1]).all()
    assert [m["line"] for m in program.moves] == [1, 2, 3, 4, 4, 5, 5, 6, 6, 7]


def test_events_wait_behind_the_held_move(run):
    program = run("G0 X-10\nM3 S1000\nG41 D1 G1 X0 Y0 F100\nG4 P1\nM5\nG1 X10\nG40 G1 X20 Y-10\n")
    kinds = list(program.ops.kind)
    dwell, stop = kinds.index(DWELL), len(kinds) - 1 - kinds[::-1].index(SPINDLE)
    assert dwell < stop and kinds[dwell - 1] == 1  # the entry feed first, then the dwell
    entry_end = program.ops.end[dwell - 1]
    assert (program.ops.end[dwell] == entry_end).all() and (program.ops.end[stop] == entry_end).all()


def test_end_of_file_writes_the_held_move(run):
    program = run("G0 X-10\nG41 D1 G1 X0 Y0 F100\nG1 X10\n")
    assert len(program.moves) == 3 and ends(program)[-1] == [10, 3, 0]


def test_g41_1_takes_a_diameter(run):
    program = run("G0 X-10\nG41.1 D8 G1 X0 F100\nG40 G1 X0 Y-10\n")
    assert ends(program)[1] == [0, 4, 0]


def test_comp_leaves_the_fast_path_and_g40_returns_to_it(run):
    body = "".join(f"G1 X{10 + i} Y0\n" for i in range(40))
    program = run(f"G0 X-10\nG41 D1 G1 X0 Y0 F100\n{body}G40 G1 X60 Y-10\n{body}")
    assert not program.errors
    assert ends(program)[2][1] == 3.0 and ends(program)[-1] == [49, 0, 0]


@pytest.mark.parametrize("text, line, fragment", [
    ("G41 D1 G1 X-8 F100", 2, "entry move is not greater than the tool radius"),
    ("G41 D1 G1 X0 F100\nG3 X4 I2", 3, "Tool radius not less than arc radius"),
    ("G41 D1 G1 X0 F100\nX20\nY1\nX40", 5, "concave corner cannot be reached"),
    ("G41 D1 G1 X0 F100\nG41 X5", 3, "comp on when on"),
    ("G41 D1 G1 X0 F100\nG18", 3, "Cannot change planes"),
    ("G41 D1 G1 X0 F100\nG92 X0", 3, "cannot change axis offsets"),
    ("G41 D1 G1 X0 F100\nG55", 3, "cannot change coordinate systems"),
    ("G41 D1 G1 X0 F100\nG81 X1 Z-1 R1", 3, "canned cycles with cutter compensation"),
    ("G41 D1 G1 X0 F100\nG53 G1 X5", 3, "G53 with cutter radius compensation"),
    ("G41 D1 G1 X0 F100\nT2 M6", 3, "change tools"),
    ("G41 D1 G1 X0 F100\nX20\nG40\nG2 X30 R5", 5, "must be straight"),
    ("G41 D1.5 G1 X0 F100", 2, "whole number"),
    ("G41.1 G1 X0 F100", 2, "with no D word"),
    ("G18 G41 D1 G1 X0 F100", 2, "only in XY plane"),
    ("G41 D1 G3 X-10 Y4 R2 F100", 2, "Tool radius not less than arc radius"),
])
def test_refusals_name_the_line(run, text, line, fragment):
    program = run(f"G0 X-10 Y0\n{text}\n")
    assert [d.line for d in program.errors] == [line], program.errors
    assert fragment.lower() in program.errors[0].message.lower()


def test_find_turn_is_rs274s_signed_sweep():
    from app.gcode.comp_corners import find_turn

    assert math.isclose(find_turn(1, 0, 0, 0, 1, 0, 1), math.pi / 2)
    assert math.isclose(find_turn(1, 0, 0, 0, -1, 0, 1), -3 * math.pi / 2)
    assert math.isclose(find_turn(1, 0, 0, 0, 2, 0, 1), math.pi / 2 + 2 * math.pi)
    assert math.isclose(find_turn(1, 0, 0, 0, 1, 1, 0), 2 * math.pi)  # a full circle
    assert find_turn(1, 0, 0, 0, 0, 0, 1) == 0.0
