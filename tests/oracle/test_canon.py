"""Unit tests of the canon reader and of record.py's pure helpers (no rs274 needed)."""

from __future__ import annotations

import pytest

from tests.oracle import record
from tests.oracle.canon import (
    CanonError,
    canon_to_moves,
    compare_move,
    compare_moves,
    drop_axisless_moves,
    has_axis_word,
    parse_call,
    parse_canon_lines,
    parse_record,
)


def test_parse_call_with_and_without_line_number():
    call = parse_call("   12 N17    STRAIGHT_FEED(10.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)")
    assert (call.seq, call.line, call.name) == (12, 17, "STRAIGHT_FEED")
    assert call.floats()[:3] == [10.0, 2.0, 3.0]
    setup = parse_call("    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)")
    assert setup.line is None and setup.args == ("CANON_UNITS_MM",)


def test_parse_call_long_line_number_glued_to_the_name():
    call = parse_call("    9 N123456STRAIGHT_FEED(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)")
    assert call.line == 123456 and call.name == "STRAIGHT_FEED"


def test_parse_call_comment_keeps_commas_and_parentheses():
    call = parse_call('    7 N2     COMMENT("a, b (c)")')
    assert call.args == ('"a, b (c)"',)
    assert parse_call("    6 N..... ON_RESET()").args == ()


def test_parse_call_rejects_other_text():
    with pytest.raises(CanonError):
        parse_call("Radius to end of arc differs from radius to start")


def _moves(*lines: str) -> list[dict]:
    return canon_to_moves(parse_canon_lines(lines))


def test_moves_in_mm():
    moves = _moves(
        "1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)",
        "2 N3     STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)",
        "3 N4     SET_FEED_RATE(100.0000)",
        "4 N4     STRAIGHT_FEED(10.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)",
        "5 N5     ARC_FEED(20.0000, 2.0000, 15.0000, 2.0000, -1, 1.0000, 0.0000, 0.0000, 0.0000)",
        "6 N6     DWELL(0.5000)",
    )
    assert moves[0] == {"line": 3, "kind": "rapid", "end": [1.0, 2.0, 3.0], "units": "mm"}
    assert moves[1] == {"line": 4, "kind": "feed", "end": [10.0, 2.0, 3.0], "feed": 100.0, "units": "mm"}
    assert moves[2] == {
        "line": 5,
        "kind": "arc",
        "end": [20.0, 2.0, 1.0],
        "center": [15.0, 2.0],
        "plane": "XY",
        "turn": -1,
        "feed": 100.0,
        "units": "mm",
    }
    assert moves[3] == {"line": 6, "kind": "dwell", "seconds": 0.5}


def test_inches_are_converted_and_feed_keeps_the_units_it_was_set_in():
    moves = _moves(
        "1 N1 SET_FEED_RATE(254.0000)",
        "2 N1 USE_LENGTH_UNITS(CANON_UNITS_MM)",
        "3 N2 USE_LENGTH_UNITS(CANON_UNITS_INCHES)",
        "4 N3 STRAIGHT_FEED(1.0000, 0.5000, -0.0200, 0.0000, 0.0000, 0.0000)",
        "5 N4 SET_FEED_RATE(10.0000)",
        "6 N4 ARC_FEED(2.0000, 2.0000, 2.0000, 1.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)",
    )
    assert moves[0]["end"] == pytest.approx([25.4, 12.7, -0.508])
    assert moves[0]["feed"] == pytest.approx(254.0) and moves[0]["units"] == "in"
    assert moves[1]["end"] == pytest.approx([50.8, 50.8, 0.0])
    assert moves[1]["center"] == pytest.approx([50.8, 25.4])
    assert moves[1]["feed"] == pytest.approx(254.0) and moves[1]["turn"] == 1


def test_arc_planes_map_first_and_second_axes():
    # G18: first = Z, second = X, axis_end_point = Y; G19: first = Y, second = Z, end = X
    xz, yz = _moves(
        "1 N1 SELECT_PLANE(CANON_PLANE_XZ)",
        "2 N2 ARC_FEED(-10.0000, 30.0000, 0.0000, 30.0000, -1, 50.0000, 0.0000, 0.0000, 0.0000)",
        "3 N3 SELECT_PLANE(CANON_PLANE_YZ)",
        "4 N4 ARC_FEED(30.0000, -10.0000, 30.0000, 0.0000, 1, 50.0000, 0.0000, 0.0000, 0.0000)",
    )
    assert (xz["plane"], xz["end"], xz["center"], xz["turn"]) == ("XZ", [30.0, 50.0, -10.0], [0.0, 30.0], -1)
    assert (yz["plane"], yz["end"], yz["center"], yz["turn"]) == ("YZ", [50.0, 30.0, -10.0], [30.0, 0.0], 1)


def test_unknown_units_and_unsupported_motion_are_errors():
    with pytest.raises(CanonError):
        _moves("1 N1 USE_LENGTH_UNITS(CANON_UNITS_FURLONGS)")
    with pytest.raises(CanonError):
        _moves("1 N1 STRAIGHT_PROBE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0, 0)")


def test_parse_record_header_and_error():
    rec = parse_record(
        "# rs274: linuxcnc-uspace 2.9; command: rs274 -g -t tool.tbl FILE\n"
        "# source: tests/oracle/cases/x.ngc\n"
        "# exit: 1\n"
        "# error_line: 5\n"
        "# error: Radius to end of arc differs from radius to start: r1=10\n"
        "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
        "    2 N3     STRAIGHT_TRAVERSE(1.0000, 2.0000, 3.0000, 0.0000, 0.0000, 0.0000)\n"
    )
    assert rec.source == "tests/oracle/cases/x.ngc"
    assert rec.error_line == 5 and rec.error_message.startswith("Radius to end")
    assert [m["kind"] for m in rec.moves] == ["rapid"]


def test_number_lines_gives_each_line_its_physical_number():
    text = "%\n(title)\nN10 G1 X1\n/ n20 G1 X2\n/G1 X3\n\nG0 X0\n%\n"
    assert record.number_lines(text) == ("%\nN2 (title)\nN3 G1 X1\n/ N4 G1 X2\n/N5 G1 X3\nN6 \nN7 G0 X0\n%\n")
    assert record.number_lines("G1 X1") == "N1 G1 X1"


def test_strip_n_column_and_stderr_lines():
    out = "    1 N..... ON_RESET()\n    2 N12    DWELL(1.0000)\n    3 N123456DWELL(2.0000)"
    assert record.strip_n_column(out) == "    1 ON_RESET()\n    2 DWELL(1.0000)\n    3 DWELL(2.0000)"
    assert record.stderr_lines("executing\nbad thing\nN5 G2 X1\n") == ["bad thing", "N5 G2 X1"]


def _arc(**kw) -> dict:
    move = {
        "line": 5,
        "kind": "arc",
        "end": [10.0, 0.0, -1.0],
        "center": [5.0, 0.0],
        "plane": "XY",
        "turn": -1,
        "feed": 300.0,
    }
    move.update(kw)
    return move


def test_compare_move_accepts_within_tolerance():
    theirs = dict(_arc(), units="mm")
    assert compare_move(_arc(), theirs) is None
    assert compare_move(_arc(end=[10.00104, 0.0, -1.0]), theirs) is None
    # inch programs: rs274 printed 4 decimals of an inch, so 0.00127 mm more slack
    assert compare_move(_arc(end=[10.0022, 0.0, -1.0]), dict(theirs, units="in")) is None


@pytest.mark.parametrize(
    ("change", "words"),
    [
        ({"end": [10.0012, 0.0, -1.0]}, "end"),
        ({"center": [5.0, 0.002]}, "centre"),
        ({"turn": 1}, "turn"),
        ({"turn": 0}, "turn"),
        ({"plane": "XZ"}, "plane"),
        ({"line": 6}, "line"),
        ({"kind": "feed"}, "kind"),
        ({"feed": 299.0}, "feed"),
        ({"center": None}, "centre"),
    ],
)
def test_compare_move_reports_each_difference(change, words):
    assert words in compare_move(_arc(**change), dict(_arc(), units="mm"))


def test_compare_moves_reports_counts_and_dwells():
    theirs = [{"line": 3, "kind": "dwell", "seconds": 0.5}, dict(_arc(), units="mm")]
    assert compare_moves([theirs[0], _arc()], theirs) == []
    assert "1 moves, rs274 2" in compare_moves([theirs[0]], theirs)[-1]
    assert "dwell" in compare_moves([{"line": 3, "kind": "dwell", "seconds": 0.6}, _arc()], theirs)[0]


def test_has_axis_word_ignores_comments():
    assert has_axis_word("G1 X10 F100")
    assert has_axis_word("g01z-.5f100")
    assert has_axis_word("G00 X 114.0234 Y 62.4844")
    assert not has_axis_word("G1 F300")
    assert not has_axis_word("G1 F300 (move to X10) ; Y5")
    assert not has_axis_word("N40")


def test_drop_axisless_moves_keeps_zero_length_moves_with_axis_words():
    lines = ["G0 X1 Y1", "G1 F300", "G1 X1 Y1", "G4 P1"]
    moves = [
        {"line": 1, "kind": "rapid", "end": [1.0, 1.0, 0.0]},
        {"line": 2, "kind": "feed", "end": [1.0, 1.0, 0.0], "feed": 300.0},
        {"line": 3, "kind": "feed", "end": [1.0, 1.0, 0.0], "feed": 300.0},
        {"line": 4, "kind": "dwell", "seconds": 1.0},
    ]
    assert [m["line"] for m in drop_axisless_moves(moves, lines)] == [1, 3, 4]


def test_offsets_and_rotation_put_moves_in_the_work_frame():
    moves = _moves(
        "1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)",
        "2 N2     SET_G5X_OFFSET(1, 10.0000, 5.0000, -2.0000, 0.0000, 0.0000, 0.0000)",
        "3 N2     SET_XY_ROTATION(90.0000)",
        "4 N3     SET_G92_OFFSET(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
        "5 N4     USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 3.0000, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)",
        "6 N5     STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
        "7 N6     ARC_FEED(0.0000, 2.0000, 0.0000, 1.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)",
    )
    # (1 + G92 1, 0) turned 90 degrees is (0, 2); plus G54 (10, 5, -2) and the tool's 3 in Z
    assert [round(v, 9) for v in moves[0]["end"]] == [10.0, 7.0, 1.0]
    assert [round(v, 9) for v in moves[1]["end"]] == [8.0, 6.0, 1.0]
    assert [round(v, 9) for v in moves[1]["center"]] == [9.0, 6.0]


def test_tool_table_for_the_issue_9_cases_is_in_inches():
    table = record.tool_table_for(record.SEM_PREFIX + "x")
    first = table.splitlines()[0].split()
    assert first[0] == "T1" and abs(float(first[2][1:]) * 25.4 - record.SEM_TOOLS[1][0]) < 1e-12
    assert record.tool_table_for("arc_ijk") == record.TOOL_TABLE
