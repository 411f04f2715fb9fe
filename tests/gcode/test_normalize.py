"""The normaliser: the machine's dialect, modal omissions, chords, the line map."""

import math
import re

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.numbers import fmt

INKSCAPE = """%
(Header)
M3
G21 (All units in mm)
G00 Z5.000000
G00 X29.412 Y73.263
G01 Z-0.125000 F100.0(Penetrate)
G02 X35.000000 Y73.263000 Z-0.125000 I2.794000 J0.000000 F400.000000
G01 X40 Y80 Z-0.125000 F400.000000
G00 Z5.000000
M5
G00 X0.0000 Y0.0000
M2
%
"""

DIALECT = re.compile(
    r"^(G0[01]( [XYZ]-?\d+(\.\d+)?)+( F\d+(\.\d+)?)?"
    r"|G0[23] X-?[\d.]+ Y-?[\d.]+( Z-?[\d.]+)? I-?[\d.]+ J-?[\d.]+( F[\d.]+)?"
    r"|G04 P[\d.]+|M03 S[\d.]+|M05|M02)$"
)


def device(text):
    program = load_text(text)
    assert not program.errors, program.errors
    return program.device_lines


@pytest.mark.parametrize(
    "k, text", [(10000, "10"), (1500, "1.5"), (-250, "-0.25"), (0, "0"), (-1, "-0.001"), (123456, "123.456")]
)
def test_number_format(k, text):
    assert fmt(k) == text


def test_inkscape_sample():
    program = load_text(INKSCAPE)
    assert program.device_lines == [
        "M03 S4500",
        "G00 Z5",  # X and Y stay where the machine stands until the program sets them
        "G00 X29.412 Y73.263",
        "G01 Z-0.125 F100",
        "G02 X35 Y73.263 I2.794 J0 F400",
        "G01 X40 Y80",
        "G00 Z5",
        "M05",
        "G00 X0 Y0",
        "M02",
    ]
    assert program.line_map.tolist() == [3, 5, 6, 7, 8, 9, 10, 11, 12, 13]


def test_inches_relative_r_format_lowercase_become_absolute_mm():
    lines = device("g20 g91\ng0x1y1z.5\nx1\ng90 g3 x1 y2 r1 f10\ng4 p0.25\nm4 s1200")
    assert lines == [
        "G00 X25.4 Y25.4 Z12.7",
        "G00 X50.8",
        "G03 X25.4 Y50.8 I-25.4 J0 F254",
        "G04 P0.25",
        "M03 S1200",
    ]


def test_never_minus_zero_and_rounding():
    assert device("G0 X-0.0001 Y1.23449 Z-0.0004") == ["G00 X0 Y1.234 Z0"]


def test_zero_length_move_is_still_a_line():
    assert device("G0 X1 Y2 Z3\nG0 X1") == ["G00 X1 Y2 Z3", "G00 X1"]


def test_arcs_outside_xy_become_chords_within_tolerance():
    program = load_text("G18 G0 X10 Z0\nG2 X0 Z10 I-10 K0 F50")
    lines = program.device_lines
    assert len(lines) > 10 and all(line.startswith("G01") or line.startswith("G00") for line in lines)
    assert set(program.line_map.tolist()[1:]) == {2}
    again = load_text("\n".join(lines))
    for m in again.moves[1:]:
        x, _, z = m["end"]
        assert abs((x * x + z * z) ** 0.5 - 10) < 0.002
    assert again.moves[-1]["end"] == [0, 0, 10]


def test_tiny_arc_whose_ends_round_together_becomes_chords():
    # sent as G02 with end == start, the device would cut a full circle
    lines = device("G0 X1 Y1\nG2 X1.0004 Y1 I0.0002 J0.002 F100")
    assert not any(line.startswith("G02") for line in lines)


def test_an_arc_wider_than_the_firmware_can_place_becomes_chords_within_tolerance():
    """docs/protocol.md: no arc of radius over 1000 mm goes to the machine (Gcodetools
    writes nearly straight biarcs of tens of km); one just inside stays an arc."""
    flat = device("G0 X91.417 Y71.484\nG2 X91.945 Y71.279 I20955.51 J55147.675 F100")  # r 59 km
    assert flat[-1] == "G01 X91.945 Y71.279"
    wide = load_text("G0 X0 Y0\nG2 X100 Y0 I50 J-4993.746 F100")  # r 4994 mm: sagitta 0.25 mm
    lines = wide.device_lines
    assert len(lines) > 3 and not any(line.startswith(("G02", "G03")) for line in lines)
    for m in load_text("\n".join(lines)).moves[1:]:
        x, y, _ = m["end"]
        assert abs(((x - 50) ** 2 + (y + 4993.746) ** 2) ** 0.5 - 4993.996) < 0.01
    assert device("G0 X0 Y0\nG3 X10 Y0 I5 J999.9 F100")[-1].startswith("G03")  # r 999.91 mm


def test_a_helix_sent_as_chords_descends_along_it_and_never_plunges_at_the_end():
    """Each chord end of a two-turn helix (sent as chords) lies on the helix: Z falls
    with the angle travelled (it stayed at the start's Z and plunged 5 mm on the last
    chord, the normal axis read from the centre instead of the end); the preview's
    polyline is the same path."""
    program = load_text("G0 X10 Y0 Z0\nG3 X10 Y0 Z-5 I-10 J0 P2 F100")
    chords = load_text("\n".join(program.device_lines)).moves[1:]
    assert len(chords) > 20
    travelled = 0.0
    before = (10.0, 0.0)
    for m in chords:
        x, y, z = m["end"]
        step = math.atan2(before[0] * y - before[1] * x, before[0] * x + before[1] * y)
        travelled, before = travelled + step, (x, y)
        assert abs(z - (-5 * travelled / (4 * math.pi))) < 0.002, (travelled, z)
    points, _ = program.toolpath.polyline(0.01)
    assert np.all(np.diff(points[1:, 2]) <= 1e-12) and points[-1, 2] == -5


def test_multi_turn_arc_becomes_chords():
    lines = device("G0 X10\nG3 X10 I-10 P2 F100")
    assert len(lines) > 20 and all(line.startswith("G0") for line in lines)


def test_pauses_are_stop_lines_the_machine_holds_at():
    program = load_text("G0 X1\nT2 M6\nG0 X2\nM0\nG0 X3\nM1\nM6\nM60")
    # a bare M6 changes to the selected tool (LinuxCNC): T2 again
    assert program.device_lines == ["G00 X1", "M06 T2", "G00 X2", "M00", "G00 X3", "M01",
                                    "M06 T2", "M00"]
    assert [i for i, _ in program.pauses] == [1, 3, 5, 6, 7]
    assert "T2" in program.pauses[0][1]
    assert list(program.line_map) == [1, 2, 3, 4, 5, 6, 7, 8]


def test_every_line_is_dialect_and_short():
    text = INKSCAPE + "G20\nG0 X-3937 Y-3937 Z-3937\nG2 X-3937 Y-3917 I0 J10 F787401\n"
    for line in device(text):
        assert len(line) <= 80 and DIALECT.match(line), line


def test_idempotent_on_sample():
    once = device(INKSCAPE)
    assert device("\n".join(once)) == once


def test_normalising_the_dialect_changes_nothing():
    lines = ["G00 X0 Y0 Z5", "G01 Z-1 F100", "G02 X10 Y0 I5 J0", "G04 P1.5", "M03 S1000", "M05", "M02"]
    assert device("\n".join(lines)) == lines


def test_the_plan_in_blocks_of_arcs_on_two_threads_is_the_same(monkeypatch):
    from app.gcode import normalize

    rows, x = [], 10.0
    for k in range(40):  # half circles; every fourth one and a half turns (P2: chords)
        r = 0.5 + k % 7
        rows.append(f"G{2 + k % 2} X{x + 2 * r} Y10 I{r} J0{' P2' if k % 4 == 0 else ''}\n")
        x += 2 * r
    text = "G21 G90 F300\nG0 X10 Y10\n" + "".join(rows) + f"G18 G2 X{x + 2} Z0 I1 K0\nM2\n"
    whole = load_text(text)
    monkeypatch.setattr(normalize, "BLOCK", 3)  # 14 blocks, checked on two threads
    blocks = load_text(text)
    assert whole.plan.chords.any() and not whole.plan.chords.all()
    assert blocks.plan.count.tolist() == whole.plan.count.tolist()
    assert blocks.plan.chords.tolist() == whole.plan.chords.tolist()
    assert blocks.device_lines == whole.device_lines
