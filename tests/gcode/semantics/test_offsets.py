"""Work offsets, G92 and G53: the rows are in the machine's work frame."""

from __future__ import annotations

import random

import numpy as np
import pytest

from app.gcode.diagnostics import Report
from app.gcode.interp import interpret_line
from app.gcode.lexer import lex_line
from app.gcode.ops import OpBuffer
from app.gcode.params import Params
from app.gcode.state import State

from .conftest import ends


def _line(state: State, text: str) -> tuple[State, bool, Report]:
    report = Report()
    new, refused = interpret_line(state, lex_line(text, 1).words, 1, OpBuffer(), report)
    return new, refused, report


def test_g54_with_zero_offsets_is_the_work_frame(run):
    program = run("G54 G0 X10 Y5 Z1\nG53 G0 X1 Y2\n")
    assert ends(program) == [[10, 5, 1], [1, 2, 1]]


def test_g10_l2_shifts_the_program_and_g53_ignores_it(run):
    program = run("G10 L2 P1 X10 Y20 Z-5\nG0 X0 Y0 Z0\nG53 G0 X0\nG0 X1\n")
    assert not program.errors
    assert ends(program) == [[10, 20, -5], [0, 20, -5], [11, 20, -5]]


def test_g92_g92_1_g92_2_g92_3(run):
    program = run("G0 X10 Y10\nG92 X0 Y0\nG1 X1 F100\nG92.2\nG1 X1\nG92.3\nG1 X2\nG92.1\nG1 X3\n")
    assert not program.errors
    assert ends(program) == [[10, 10, 0], [11, 10, 0], [1, 10, 0], [12, 10, 0], [3, 10, 0]]


def test_g52_is_a_local_offset_like_linuxcnc(run):
    program = run("G52 X5 Y-2\nG0 X0 Y0\nG52 X0 Y0\nG0 X0 Y0\n")
    assert ends(program) == [[5, -2, 0], [0, 0, 0]]


def test_arc_centres_and_incremental_moves_follow_the_offset(run):
    program = run("G10 L2 P2 X30 Y40\nG55 G0 X0 Y0\nG2 X2 Y0 I1 J0 F100\nG91 G1 X1\n")
    arc = program.moves[1]
    assert arc["center"] == [31.0, 40.0] and arc["end"] == [32.0, 40.0, 0.0]
    assert ends(program)[-1] == [33, 40, 0]


def test_parameters_hold_the_offsets_and_are_shared():
    params = Params()
    state, refused, _ = _line(State(params=params), "G10 L2 P1 X10 Y20")
    assert not refused and params.get(5221) == 10 and params.get(5222) == 20
    state, refused, _ = _line(state, "G92 X1")
    assert params.get(5210) == 1 and params.get(5211) == -11  # the point reads -10 in G54
    params.set(5241, 7.0)  # a macro writes the G55 X offset; selecting G55 reads it
    state, _, _ = _line(state, "G55")
    assert state.offsets.g5x == [7.0, 0.0, 0.0] and params.get(5220) == 2


def test_a_refused_line_writes_no_parameter():
    params = Params()
    _, refused, report = _line(State(params=params), "G10 L2 P1 X10 Q3")
    assert refused and params.get(5221) is None


def test_fast_path_takes_offsets_but_not_compensation_or_cycles():
    state = State()
    assert state.fast_path_ok()
    state, _, _ = _line(state, "G92 X3")
    assert state.fast_path_ok()
    state, _, _ = _line(state, "G81 X1 Y1 Z-1 R1 F10")
    assert not state.fast_path_ok()
    state, _, _ = _line(state, "G80")
    state, _, _ = _line(state, "G41.1 D2")
    assert not state.fast_path_ok()


def test_offsets_are_refused_clearly(run):
    cases = {
        "G10 L2 P10 X1": "P value out of range (0-9)",
        "G10 L20 P1 R1": "R not allowed in G10 L20",
        "G10 L3 P1": "does not have L1, L10, L11, L12, L13, L2, or L20",
        "G91 G53 G0 X1": "Cannot use G53 incremental",
        "G53 G2 X1 I1": "Must use G0 or G1 with G53",
        "G92 G1 X1": "both use axis values",
    }
    for text, fragment in cases.items():
        program = run(f"G0 X1\n{text}\n")
        assert [d.line for d in program.errors] == [2], text
        assert fragment in program.errors[0].message, (text, program.errors)


def _general_only(text: str, tools=None):
    """Rows of ``text`` interpreted line by line (no fast path), as ``Ops``."""
    from app.gcode.runner import _general

    state, ops, report = State(tools=dict(tools or {})), OpBuffer(), Report()
    for i, line in enumerate(text.splitlines()):
        state, _ = _general(state, line, i + 1, ops, report)
    return ops.finish()


@pytest.mark.parametrize("seed", range(6))
def test_fast_path_with_offsets_equals_the_general_path(run, seed):
    rng = random.Random(seed)
    lines = [rng.choice(["G10 L2 P1 X5 Y-3 Z2", "G92 X1 Y2", "G52 X-4", "G92.1", "G43.1 Z3", "G49"])]
    for i in range(3000):
        if i % 500 == 250:
            lines.append(rng.choice(["G92 X0 Y0", "G10 L2 P2 X7 Y1\nG55", "G54", "G92.2", "G91", "G90"]))
        x, y = rng.uniform(-50, 50), rng.uniform(-50, 50)
        z = rng.uniform(-3, 3)
        lines.append(rng.choice([f"G1 X{x:.3f} Y{y:.3f} F300", f"G0 X{x:.3f}", f"G1 Z{z:.3f}",
                                 f"G2 X{x:.3f} Y{y:.3f} I{x / 2:.3f} J{y / 2:.3f}", f"X{x:.3f} Y{y:.3f}"]))
    text = "\n".join(lines) + "\n"
    fast = run(text).ops
    slow = _general_only(text)
    assert len(fast) == len(slow) > 1000
    for name in ("line", "kind", "turn"):
        assert (getattr(fast, name) == getattr(slow, name)).all(), name
    assert np.allclose(fast.end, slow.end, atol=1e-9)
    assert np.allclose(fast.center, slow.center, atol=1e-9, equal_nan=True)


def test_rotated_work_offset(run):
    program = run("G10 L2 P1 X10 R90\nG0 X5 Y0\nG91 G1 X0 Y2 F100\nG18 G2 X1 Z1 I1\n")
    assert ends(program)[:2] == [[10, 5, 0], [8, 5, 0]]
    assert [d.line for d in program.errors] == [4] and "rotated" in program.errors[0].message


def test_rotation_is_a_parameter():
    params = Params()
    state, _, _ = _line(State(params=params), "G10 L2 P2 R15")
    assert params.get(5250) == 15 and state.offsets.rotation == 0
    state, _, _ = _line(state, "G55")
    assert state.offsets.rotation == 15 and not state.fast_path_ok()
