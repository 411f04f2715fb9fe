"""The expander and the interpreter together (docs/architecture.md, the seam): what the
interpreter needs from the expander (end of program, return from a call) and what a
macro reads of the interpreter (#5400 tool, #5420 position)."""

from app.gcode import load_text
from app.gcode.tools import Tool

COMP = "G0 X0 Y-5\nG41.1 D2 G1 X0 Y0 F100\nG1 X{x}\nG1 Y20\n"


def test_compensated_move_held_at_the_end_is_written_without_m2():
    plain = load_text(COMP.format(x="20"))
    expanded = load_text("#1 = 20\n" + COMP.format(x="#1"))
    assert not plain.errors and not expanded.errors
    assert expanded.device_lines == plain.device_lines
    assert expanded.device_lines[-1] == "G01 Y20"
    # the held move keeps the line that programmed it (one line later: the assignment)
    assert list(expanded.toolpath.source_line) == [n + 1 for n in plain.toolpath.source_line]


def test_m73_state_comes_back_when_the_subroutine_returns():
    program = load_text("o100 sub\nM73\nG91\nG0 X1\no100 endsub\nG90 G0 X5\no100 call\nG0 X10\nM2\n")
    assert not program.errors
    assert program.device_lines == ["G00 X5", "G00 X6", "G00 X10", "M02"]


def test_a_macro_reads_the_position_and_the_tool():
    text = ("T3 M6\nG20\nG0 X1 Y0.5\n#1 = #5420\n#2 = #5421\n#3 = #5400\n#4 = #5410\n"
            "G0 X[#1 + #3] Y[#2 + #4]\nM2\n")
    program = load_text(text, tools={3: Tool(3, 12.7)})
    assert not program.errors
    moves = [m for m in program.moves if m["kind"] == "rapid"]
    assert moves[-1]["end"][:2] == [4 * 25.4, 1.0 * 25.4]  # X 1 + tool 3, Y 0.5 + 0.5 inch diameter


def test_numbers_a_macro_computes_are_checked_as_typed_ones_are():
    program = load_text("#1 = [10 ** 20]\nG1 X1 F#1\nS[0 - 5]\nG4 P[10 ** 9]\nM2\n")
    found = {(d.line, d.column): d.message for d in program.errors}
    assert "number too large: F" in found[2, 7]
    assert found[3, 1] == "spindle speed S-5 is negative"
    assert "number too large: P" in found[4, 4]
    assert not any(line.startswith("G01") for line in program.device_lines)  # no wrapped feed sent
