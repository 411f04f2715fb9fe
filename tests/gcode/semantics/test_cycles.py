"""Canned cycles: the rows rs274 makes, sticky words, and the refusals."""

from __future__ import annotations

import pytest

from .conftest import ends


def test_g81_moves_as_rs274(run):
    program = run("G0 Z5\nF100\nG81 X10 Y10 Z-2 R1\nX20\n")
    kinds = [m["kind"] for m in program.moves]
    assert kinds == ["rapid", "rapid", "rapid", "feed", "rapid", "rapid", "feed", "rapid"]
    assert ends(program) == [[0, 0, 5], [10, 10, 5], [10, 10, 1], [10, 10, -2], [10, 10, 1],
                             [20, 10, 1], [20, 10, -2], [20, 10, 1]]
    assert all(m["line"] == 3 for m in program.moves[1:5])


def test_g98_returns_to_the_initial_level(run):
    program = run("G0 Z5\nF100\nG98 G81 X1 Y1 Z-1 R2\n")
    assert ends(program)[-1] == [1, 1, 5]


def test_l_repeats_in_g91(run):
    program = run("G0 Z5\nF100\nG91 G81 X5 Z-3 R-3 L3\n")
    holes = [e for m, e in zip(program.moves, ends(program), strict=True) if m["kind"] == "feed"]
    assert holes == [[5, 0, -1], [10, 0, -1], [15, 0, -1]]


def test_peck_and_dwell(run):
    program = run("G0 Z2\nF100\nG83 X0 Y0 Z-3 R1 Q2\nG82 Z-1 R1 P0.5\n")
    feeds = [m["end"][2] for m in program.moves if m["kind"] == "feed"]
    assert feeds == [-1, -3, -1]
    assert any(m["kind"] == "dwell" and m["seconds"] == 0.5 for m in program.moves)


def test_cycle_mode_leaves_the_fast_path(run):
    program = run("G0 Z5\nF100\nG81 X1 Y1 Z-1 R1\n" + "".join(f"X{i} Y1\n" for i in range(2, 40)))
    assert not program.errors
    assert sum(m["kind"] == "feed" for m in program.moves) == 39


@pytest.mark.parametrize("text, fragment", [
    ("G81 X1 Z-1 R1", "zero feed rate"),
    ("F10 G81 X1 Z-1", "R clearance plane unspecified"),
    ("F10 G81 X1 R1", "Z value unspecified"),
    ("F10 G81 X1 Z2 R1", "R less than Z"),
    ("F10 G81 X1 Z-1 R1 L0", "zero repeats"),
    ("F10 G83 X1 Z-1 R1", "Q word missing with G83"),
    ("F10 G83 X1 Z-1 R1 Q-1", "negative or zero Q"),
    ("F10 G82 X1 Z-1 R1", "P word missing with G82"),
    ("F10 G18 G81 X1 Z-1 R1", "Y value unspecified in XZ plane canned cycle"),
    ("F10 G19 G81 Y1 Z-1 R1", "X value unspecified in YZ plane canned cycle"),
    ("F10 G18 G81 X1 Y-1 R-2", "R less than Y in cycle in XZ plane"),
    ("F10 G84 X1 Z-1 R1", "reverses"),
    ("F10 G86 X1 Z-1 R1 P1", "spindle stop"),
    ("F10 G87 X1 Z-1 R1", "orientation"),
])
def test_cycle_refusals(run, text, fragment):
    program = run(f"G0 Z5\n{text}\n")
    assert [d.line for d in program.errors] == [2], program.errors
    assert fragment in program.errors[0].message
