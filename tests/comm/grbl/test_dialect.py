"""Programs for GRBL: device lines as GRBL takes them, and the preflight with GRBL's
own travel ($130-$132, $23) and the live work offset (WCO)."""

from __future__ import annotations

import pytest

from app.comm.grbl.dialect import MAX_LINE, axis_range, grbl_lines, grbl_travel, line_problems
from app.gcode import load_text
from app.gcode.checks import preflight
from backend_sim.grbl.execute import GcodeState
from backend_sim.grbl.parser import GrblError, parse_block

SETTINGS = {130: "150.000", 131: "150.000", 132: "30.000", 23: "3"}


def test_program_stops_become_host_stops_and_the_rest_passes():
    out = grbl_lines(["G00 X1", "M00", "M01", "M06 T3", "G04 P0.5", "M30"], optional_stop=False)
    assert [(line.index, line.text) for line in out] == [(0, "G00 X1"), (1, None), (3, None), (4, "G04 P0.5"),
                                                       (5, "M30")]
    assert (out[1].stop.code, out[2].stop.code, out[2].stop.tool) == (0, 6, 3)


def test_every_device_line_of_a_macro_and_an_arc_program_is_grbl_gcode():
    text = ("G21 G90\nT2 M6\nG0 X10 Y10 Z5\nM3 S1000\nG1 Z-1 F100\nG2 X30 Y10 R10\nG3 X10 Y10 I-10 J0\n"
            "#1 = 0\no1 while [#1 LT 3]\nG1 X[20 + #1] Y20\n#1 = [#1 + 1]\no1 endwhile\nG4 P0.2\nM5\nM30\n")
    program = load_text(text)
    assert not [d for d in program.diagnostics if d.severity == "error"], program.diagnostics
    state = GcodeState()
    state.position = [10.0, 10.0, 0.0]
    for line in grbl_lines(program.device_lines):
        if line.text is not None:
            try:
                state.execute(parse_block(line.text))
            except GrblError as exc:
                pytest.fail(f"GRBL refuses {line.text!r}: error {exc.code}")
    assert not line_problems(program.device_lines)


def test_long_lines_are_named():
    problems = line_problems(["G1 X1", "G1 X" + "1" * MAX_LINE])
    assert len(problems) == 1 and "device line 1" in problems[0]


def test_machine_space_is_negative_whichever_end_an_axis_homes_to():
    assert axis_range(SETTINGS, 0) == (-150.0, 0.0)  # $23 bit 0: X homes to its negative end
    assert axis_range(SETTINGS, 2) == (-30.0, 0.0)


def test_preflight_with_grbl_travel_and_live_work_offset():
    program = load_text("G0 X10 Y10 Z5\nG1 Z-1 F100\nG1 X140\n")
    profile, offset = grbl_travel(SETTINGS, wco=(-145.0, -145.0, -10.0))
    assert offset == (5.0, 5.0, 20.0)
    assert not preflight(program.ops, profile, program.source_lines, offset)
    profile, offset = grbl_travel(SETTINGS, wco=(-130.0, -145.0, -10.0))  # X140 - 130 > 0
    errors = preflight(program.ops, profile, program.source_lines, offset)
    assert len(errors) == 1 and errors[0].line == 3 and "X" in errors[0].message


def test_travel_not_reported_is_an_error():
    with pytest.raises(ValueError, match=r"\$132"):
        grbl_travel({130: "1", 131: "1"}, (0, 0, 0))
