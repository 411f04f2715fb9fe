"""Harmless modal codes, M70-M73, and the codes refused with a reason."""

from __future__ import annotations

import pytest

from .conftest import ends


def test_harmless_codes_are_accepted(run):
    program = run("G17 G40 G49 G80 G90 G94 G21 G64 P0.05 Q0.02\nG61\nG61.1\nG8\nG0 X1\n")
    assert not program.errors and ends(program) == [[1, 0, 0]]


def test_m70_m72_restore_units_and_distance(run):
    program = run("F100\nM70\nG20 G91\nG1 X1 F10\nM72\nG1 X3\n")  # M72 restores F100 too
    assert not program.errors and ends(program) == [[25.4, 0, 0], [3, 0, 0]]


def test_m72_restores_the_spindle(run):
    program = run("S1000 M3\nM70\nM5\nM72\n")
    spindle = [int(v) for k, v in zip(program.ops.kind, program.ops.value, strict=True) if k == 5]
    assert spindle == [1000, 0, 1000]


def test_m72_without_a_saved_state(run):
    program = run("M71\nM72\n")
    assert [d.line for d in program.errors] == [2] and "no M70" in program.errors[0].message


@pytest.mark.parametrize("text, fragment", [
    ("G0 A1", "axis A"),
    ("G33 X1 K1", "spindle-synchronised"),
    ("G76 P1 Z-1", "spindle-synchronised"),
    ("G38.2 Z-1 F10", "probe"),
    ("G70", "lathe"),
    ("G7", "lathe"),
    ("G93", "inverse-time"),
    ("G5.2 X1 Y1 P1 L3", "NURBS"),
    ("D1", "D word with no"),
    ("H1", "H word with no G43"),
    ("L2", "L word with no"),
    ("G10 L2 P1 X1 Y1 G1", "both use axis values"),
])
def test_refused_with_the_reason(run, text, fragment):
    program = run(text + "\n")
    assert [d.line for d in program.errors] == [1], program.errors
    assert fragment in program.errors[0].message


def test_coolant_is_a_warning(run):
    program = run("M8\nM7\nM9\n")
    assert not program.errors and len([w for w in program.warnings if "coolant" in w.message]) == 3


def test_m73_restores_when_the_expander_ends_a_call():
    from app.gcode.diagnostics import Report
    from app.gcode.interp import interpret_line
    from app.gcode.lexer import lex_line
    from app.gcode.modal_state import restore_on_return
    from app.gcode.ops import OpBuffer
    from app.gcode.state import State

    state, ops = State(), OpBuffer()
    for text in ("M73", "G20 G91"):
        state, refused = interpret_line(state, lex_line(text, 1).words, 1, ops, Report())
        assert not refused
    assert state.inch and not state.absolute
    assert restore_on_return(state, 3, ops) and not state.inch and state.absolute
    assert not restore_on_return(state, 4, ops)  # nothing saved any more
