"""The modal interpreter: what each word does, as LinuxCNC's rs274ngc does it."""

import math

import pytest

from app.gcode import load_text


def moves(text):
    program = load_text(text)
    assert not program.errors, program.errors
    return program.moves


def ends(text):
    return [tuple(round(v, 6) for v in m["end"]) for m in moves(text) if "end" in m]


def test_start_at_origin_and_modal_motion():
    got = moves("G1 X10 F100\nY5\nZ-1\nG0 X0\nY1")
    assert [m["kind"] for m in got] == ["feed", "feed", "feed", "rapid", "rapid"]
    assert got[1]["end"] == [10, 5, 0] and got[2]["end"] == [10, 5, -1]
    assert [m["line"] for m in got] == [1, 2, 3, 4, 5]
    assert got[0]["feed"] == 100


def test_motion_word_without_axes_moves_nothing():
    assert moves("G1 F100\nG0\n") == []


def test_inches_become_millimetres_and_feed_units_follow():
    got = moves("G20\nG1 X1 F10\nG21 X5")
    assert got[0]["end"] == pytest.approx([25.4, 0, 0]) and got[0]["feed"] == pytest.approx(254)
    assert got[1]["end"] == pytest.approx([5, 0, 0])


def test_feed_is_read_before_units_of_the_same_line():
    got = moves("G21\nG20 F10 G1 X1")
    assert got[0]["feed"] == pytest.approx(10)  # rs274: SET_FEED_RATE before USE_LENGTH_UNITS


def test_incremental_moves():
    assert ends("G91 G0 X1 Y1\nX1\nG90 X0") == [(1, 1, 0), (2, 1, 0), (0, 1, 0)]


def test_arc_ijk_relative_and_absolute_centre():
    rel = moves("G0 X10 Y0\nG3 X0 Y10 I-10 J0 F50")[-1]
    assert rel["kind"] == "arc" and rel["center"] == pytest.approx([0, 0]) and rel["turn"] == 1
    absolute = moves("G90.1 G0 X10 Y0\nG2 X0 Y-10 I0 J0 F50")[-1]
    assert absolute["center"] == pytest.approx([0, 0]) and absolute["turn"] == -1


@pytest.mark.parametrize("r, center", [(10, (0, 0)), (-10, (10, 10))])
def test_arc_r_format_short_and_long(r, center):
    arc = moves(f"G0 X10 Y0\nG3 X0 Y10 R{r} F50")[-1]
    assert arc["center"] == pytest.approx(center)


def test_full_circle_and_helix():
    got = moves("G0 X10 Y0\nG2 X10 Y0 I-10 J0 Z-2 F50\nG3 I-10")
    assert got[1]["end"] == pytest.approx([10, 0, -2]) and got[1]["center"] == pytest.approx([0, 0])
    assert got[2]["end"] == pytest.approx([10, 0, -2])


def test_arcs_in_g18_and_g19_use_linuxcnc_axis_order():
    xz = moves("G18 G0 X10 Z0\nG2 X0 Z10 I-10 K0 F50")[-1]
    assert xz["plane"] == "XZ" and xz["center"] == pytest.approx([0, 0])  # (Z, X)
    yz = moves("G19 G0 Y10 Z0\nG3 Y0 Z10 J-10 K0 F50")[-1]
    assert yz["plane"] == "YZ" and yz["center"] == pytest.approx([0, 0])


def test_arc_turns_p():
    arc = moves("G0 X10\nG3 X10 Y0 I-10 P2 F50")[-1]
    assert arc["turn"] == 2


def test_dwell_in_seconds():
    assert moves("G4 P0.5") == [{"line": 1, "kind": "dwell", "seconds": 0.5}]


def test_spindle_tool_change_and_stops_are_not_moves():
    program = load_text("M3 S1000\nT1 M6\nG1 X1 F10\nM0\nM4\nM5\nM2\nG0 X5")
    assert not program.errors
    assert [m["line"] for m in program.moves] == [3]
    texts = " ".join(d.message for d in program.warnings)
    assert "one tool" in texts and "M0" in texts and "M4" in texts
    assert "ended at line 7" in texts


def test_program_after_m2_is_ignored_quietly_when_only_comments():
    program = load_text("G0 X1\nM2\n(end)\n%\n")
    assert not program.warnings


def test_refused_line_changes_nothing():
    program = load_text("G1 X1 F10\nG20 G81 X5\nX2")
    assert [d.line for d in program.errors] == [2]
    assert program.moves[-1]["end"] == [2, 0, 0]  # still millimetres: G20 was not applied


ERROR_CASES = [
    ("o100 sub", 1, "never closed"),  # the expander reads o-words and parameters
    ("G1 X#<a>", 1, "#<a> is not set"),
    ("G81 X1 Y1 Z-1 R1", 1, "Cannot feed with zero feed rate"),
    ("G83 X1 F10", 1, "R clearance plane unspecified"),
    ("G41 D1", 1, "Requested tool 1 not found in the tool table"),
    ("G92", 1, "All axes missing with G52 or G92"),
    ("G84 X1 Z-1 R1 F10", 1, "spindle that reverses"),
    ("G7", 1, "lathe code"),
    ("G33 X1 K1", 1, "spindle-synchronised"),
    ("G38.2 X1 F10", 1, "probe"),
    ("G93", 1, "inverse-time"),
    ("G71 X1", 1, "lathe"),
    ("M99", 1, "unknown M-code M99"),
    ("G1 X1 F1 Q5", 1, "Q word with no"),
    ("G0 A10", 1, "axis A"),
    ("G0 G1 X1", 1, "G0 and G1"),
    ("G17 G18", 1, "G17 and G18"),
    ("G20 G21", 1, "G20 and G21"),
    ("M3 M5", 1, "M3 and M5"),
    ("G1 X1 X2 F1", 1, "two X words"),
    ("X5", 1, "no motion mode"),
    ("G80 X5", 1, "no motion mode"),
    ("G1 X1 I1 F1", 1, "I word with no G2, G3"),
    ("G0 X1 R1", 1, "R word with no G2, G3"),
    ("G1 X1 P1 F1", 1, "P word"),
    ("G2 X1 Y1 F1", 1, "R, I, J and K words all missing"),
    ("G2 X1 Y1 R1 I1 F1", 1, "both R and I/J/K"),
    ("G2 X1 Y1 I1 K1 F1", 1, "K word given for arc in XY plane"),
    ("G0 X10\nG2 X0 Y1 I-10 F1", 2, "arc end is not on its circle"),
    ("G0 X10\nG2 X10 Y0 I0 J0 F1", 2, "zero-radius arc"),
    ("G2 X0 Y0 R5 F1", 1, "end is its start"),
    ("G2 X10 Y0 R4 F1", 1, "too small to reach"),
    ("G4", 1, "G4 dwell needs a P word"),
    ("G4 P-1", 1, "must not be negative"),
    ("G3 X0 Y0 I1 P1.5 F1", 1, "whole number"),
    ("G0 X1e9", 1, "E words"),
    ("G0 X10000000", 1, "out of range"),
]


@pytest.mark.parametrize("text, line, fragment", ERROR_CASES, ids=[c[0] for c in ERROR_CASES])
def test_refusals_name_line_and_feature(text, line, fragment):
    program = load_text("G21\n" + text)
    errors = program.errors
    assert [d.line for d in errors] == [line + 1], errors
    assert fragment in errors[0].message
    assert str(errors[0]).startswith(f"line {line + 1}")


def test_linuxcnc_arc_tolerance_mm():
    # T = 0.028284 mm; accepted up to T, or up to 0.1 % of the radius, never past 100 T
    def refused(radius, off):
        x0 = 75.0
        cx = x0 - radius
        ex, ey = cx, radius + off
        text = f"G0 X{x0} Y0\nG3 X{ex:.7f} Y{ey:.7f} I{-radius} J0 F100"
        return bool(load_text(text).errors)

    assert not refused(10, 0.028) and refused(10, 0.029)
    assert not refused(50, 0.0499) and refused(50, 0.0502)
    assert not refused(3000, 2.8) and refused(3000, 2.86)


def test_linuxcnc_arc_tolerance_is_in_inches_for_g20():
    text = "G20 G0 X3 Y0\nG3 X2 Y{:.6f} I-1 J0 F10"
    assert not load_text(text.format(1.0028)).errors
    assert load_text(text.format(1.0029)).errors


def test_envelope_warnings_and_feed_zero_refused():
    """A feed move at feed 0 is refused, as rs274ngc and Fanuc controls refuse it (issue 19)."""
    program = load_text("G21\nG0 X10 Y10\nG1 X152.3 F100\nG1 Y-1\nG1 F0 X5")
    messages = [str(d) for d in program.warnings]
    assert "line 3, column 4: X+ beyond travel (152.300 > 150)" in messages
    assert any(m.startswith("line 4") and "Y- beyond travel" in m for m in messages)
    assert [(d.line, d.message) for d in program.errors] == [
        (5, "Cannot do G1 with zero feed rate (no F word yet, or F0)")]


def test_arc_bulge_beyond_travel_warns():
    program = load_text("G0 X140 Y75\nG3 X140 Y85 I0 J5 F100")  # bulges to X 145
    assert not program.warnings
    program = load_text("G0 X148 Y75\nG3 X148 Y85 I0 J5 F100")
    assert any("X+ beyond travel (153.000 > 150)" in d.message for d in program.warnings)


def test_many_warnings_are_summarised():
    text = "G0 X200\n" + "G0 X200 Y1\nG0 X201\n" * 400
    program = load_text(text)
    assert len(program.warnings) < 300
    assert "more like" in program.warnings[-1].message


def test_circle_length():
    program = load_text("G0 X10\nG2 I-10 F100")
    assert program.toolpath.length[-1] == pytest.approx(2 * math.pi * 10)


def test_refused_line_gives_no_warning():
    program = load_text("M4 G81 X1")
    assert len(program.errors) == 1 and not program.warnings


def test_preflight_with_the_real_work_offset_names_line_axis_direction_and_amount():
    from app.gcode.checks import preflight

    program = load_text("G21 G90\nG0 Z5\nG0 X0 Y0\nG1 Z-1 F600\nG1 X120\nG1 Y20\nG2 X120 Y40 I0 J10\n")
    assert preflight(program.ops, program.profile, program.source_lines, (0.0, 0.0, 20.0)) == []
    (error,) = preflight(program.ops, program.profile, program.source_lines, (50.0, 0.0, 20.0))
    assert (error.line, error.column, error.severity) == (5, 4, "error")
    assert error.message.startswith("X+ leaves the travel by 20.000 mm with the work zero at machine X50.000")
    low = preflight(program.ops, program.profile, program.source_lines, (0.0, 0.0, 0.5))
    assert [(d.line, d.message[:2]) for d in low] == [(4, "Z-")] and "by 0.500 mm" in low[0].message


def test_preflight_reuses_the_loads_envelope_check_only_for_the_same_limits():
    from app.gcode.checks import preflight

    text = "G0 X140 Y5\nG2 X140 Y25 I0 J10 F300\nG1 X-3 Z-25\nG3 X-3 Y5 I0 J-10\nG0 Y160\n"
    program = load_text(text)
    assert program.envelope is not None and program.envelope.found
    default = program.profile.travel.work_offset()
    for offset in (default, (0.0, 0.0, 20.0), (50.0, 10.0, 20.0), (5.0, 0.0, 0.5)):
        fresh = preflight(program.ops, program.profile, program.source_lines, offset)
        reused = preflight(program.ops, program.profile, program.lines, offset, program.envelope)
        assert reused == fresh
    assert preflight(program.ops, program.profile, program.lines, default, program.envelope)


def test_spindle_speed_beyond_the_motor_warns_with_the_maximum():
    program = load_text("M3 S9000\nG0 X1\nM3 S3000\n")
    (warning,) = [d for d in program.warnings if "spindle" in d.message]
    assert (warning.line, warning.column) == (1, 4)
    assert "S9000" in warning.message and "3750 rpm" in warning.message
