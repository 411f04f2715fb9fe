"""Straight runs of moves (``runs.py``): one dispatch for several blocks must mean
exactly what running them one by one means."""

from app.gcode import load_text
from app.gcode.macro.runs import RUN_LIMIT

BODY = "G1 X[#1] Y0 F100\nG1 X[#1 + 1] Y1\n\nG1 X[#1 + 2] Y2\nG1 X[#1 + 3] Y3\n"


def _feed_xs(program) -> list[str]:
    """The X word of each feed line the program sends."""
    return [w for line in program.device_lines if line.startswith("G01") for w in line.split() if w[0] == "X"]


def _plain(text: str) -> list[str]:
    """``text`` with its parameter #1 fixed at 10 and no macro left: the fast path's lines."""
    return load_text(text.replace("[#1]", "[10]").replace("#1 +", "10 +")).device_lines


def test_a_run_makes_the_lines_and_source_lines_of_its_blocks():
    program = load_text("#1 = 10\n" + BODY + "M2\n")
    assert not program.errors
    assert program.device_lines == _plain(BODY + "M2\n")
    assert list(program.toolpath.source_line[-4:]) == [2, 3, 5, 6]


def test_a_jump_into_the_middle_of_a_run_starts_there():
    text = "#1 = 10\nGOTO 5\nG1 X1 F100\nG1 X2\nN5 G1 X3 F100\nG1 X4\nG1 X5\nM30\n"
    program = load_text(text)
    assert not program.errors
    assert _feed_xs(program) == ["X3", "X4", "X5"]


def test_an_error_inside_a_run_keeps_the_moves_before_it_and_names_its_line():
    program = load_text("#1 = 10\nG1 X[#1] F100\nG1 X[#1 + 1]\nG1 X[SQRT[0 - #1]]\nG1 X[#1 + 3]\nM2\n")
    assert [(e.line, e.column) for e in program.errors] == [(4, 6)]
    assert _feed_xs(program) == ["X10", "X11"]


def test_a_block_reading_the_position_sees_every_move_before_it():
    text = "#1 = 10\nG1 X[#1] F100\nG1 Y[#1]\nG1 X[#5420 + 1]\nG1 Y[#5421 + 1]\nM2\n"
    program = load_text(text)
    assert not program.errors
    assert program.device_lines[-3:-1] == ["G01 X11", "G01 Y11"]


def test_runs_longer_than_the_limit_are_cut_and_go_on():
    moves = "".join(f"G1 X[#1 + {i}] F100\n" for i in range(3 * RUN_LIMIT + 1))
    program = load_text("#1 = 0\n" + moves + "M2\n")
    assert not program.errors
    assert _feed_xs(program) == [f"X{i}" for i in range(3 * RUN_LIMIT + 1)]
