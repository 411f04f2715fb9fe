"""What the expander makes of each construct, beyond what the rs274 recordings cover:
Fanuc's vacant #0, local levels of G65 and M98, M99 Pn, repeat counts, the packed
M98 form, LinuxCNC loops with break/continue in do, and the trace of every row."""

import pytest

from app.gcode import load, load_text


def xs(text, folder=None):
    program = load_text(text, folder=folder)
    assert not program.errors, [str(d) for d in program.errors]
    return [m["end"][0] for m in program.moves]


def test_fanuc_vacant_reads_as_zero_in_arithmetic_and_apart_in_eq_ne():
    text = """O0001
#1 = #0
#2 = #1 + 2
IF [#1 EQ #0] THEN #3 = 1
IF [#1 NE 0] THEN #4 = 1
IF [#1 EQ 0] THEN #5 = 1
#6 = 0
IF [#6 EQ #0] THEN #7 = 1
G1 X#2 F100
G1 X[#3 + #4 * 10]
G1 X[#5 + 1]
G1 X[#7 + 5]
G1 X#1 Y3
M30
"""
    assert xs(text) == [2.0, 11.0, 1.0, 5.0, 5.0]  # the last line: X vacant, left out


def test_linuxcnc_unset_numbered_parameter_reads_zero():
    assert xs("G1 X[#77 + 1] F100\nM2\n") == [1.0]


def test_g65_has_its_own_locals_m98_shares_the_callers():
    text = """O0001
#1 = 5
G65 P10 A1
G1 X#1 F100
M98 P20
G1 X#1
M30
O0010
#1 = #1 + 100
G1 X#1 F100
M99
O0020
#1 = 42
M99
"""
    assert xs(text) == [101.0, 5.0, 42.0]


def test_g65_argument_specification_i_and_unset_arguments_vacant():
    text = "G65 P9 X1 Y2 Z3 A4 B5 R6\nM30\nO0009\nG1 X[#24 + #25 + #26 + #1 + #2 + #18] Y#7 F100\nM99\n"
    program = load_text(text)
    assert [m["end"][:2] for m in program.moves] == [[21.0, 0.0]]


def test_m98_repeats_with_l_and_the_packed_form():
    sub = "O0005\nG91 G1 X1 F100\nG90\nM99\n"
    assert len(xs(f"M98 P5 L3\nM30\n{sub}")) == 3
    assert len(xs(f"M98 P40005\nM30\n{sub}")) == 4
    assert len(xs(f"M98 P0005\nM30\n{sub}")) == 1


def test_m99_p_returns_to_a_label_of_the_caller():
    text = "M98 P7\nG1 X99 F100\nN50 G1 X2 F100\nM30\nO0007\nG1 X1 F100\nM99 P50\n"
    assert xs(text) == [1.0, 2.0]


def test_goto_backward_and_computed():
    text = "#1 = 0\nN10 #1 = #1 + 1\nG1 X#1 F100\nIF [#1 LT 3] GOTO 10\n#2 = 30\nGOTO #2\nG1 X99\nN30 M30\n"
    assert xs(text) == [1.0, 2.0, 3.0]


def test_nested_while_do_end():
    text = ("#1 = 0\nWHILE [#1 LT 2] DO 1\n#2 = 0\nWHILE [#2 LT 2] DO 2\nG1 X[#1 * 10 + #2] F100\n"
            "#2 = #2 + 1\nEND 2\n#1 = #1 + 1\nEND 1\nM30\n")
    assert xs(text) == [0.0, 1.0, 10.0, 11.0]


def test_fanuc_subprogram_files_are_found_by_each_name(tmp_path):
    for name in ("O0100.nc", "o0101.nc", "0102.nc"):
        (tmp_path / name).write_text("G91 G1 X1 F100\nG90\nM99\n")
    assert len(xs("M98 P100\nM98 P101\nM98 P102\nM30\n", folder=tmp_path)) == 3


def test_linuxcnc_break_and_continue_in_do_loops():
    text = ("#1 = 0\no1 do\n  #1 = [#1 + 1]\n  o2 if [#1 EQ 2]\n    o1 continue\n  o2 endif\n"
            "  o3 if [#1 EQ 4]\n    o1 break\n  o3 endif\n  G1 X#1 F100\no1 while [#1 LT 9]\nM2\n")
    assert xs(text) == [1.0, 3.0]


def test_linuxcnc_assignments_take_effect_after_the_line():
    assert xs("#1 = 1\n#1 = 2 G1 X#1 F100\nG1 X#1\nM2\n") == [1.0, 2.0]


def test_rows_carry_the_calling_line_subprogram_and_iteration(tmp_path):
    (tmp_path / "main.ngc").write_text("o<hole> sub\n  G1 Z-1 F100\n  G0 Z1\no<hole> endsub\n"
                                       "#1 = 0\no1 while [#1 LT 3]\n  G0 X#1\n  o<hole> call\n"
                                       "  #1 = [#1 + 1]\no1 endwhile\nM2\n")
    program = load(tmp_path / "main.ngc")
    source = program.ops.source
    assert program.ops.line.tolist()[:3] == [7, 2, 3]
    assert source.call_line.tolist()[:6] == [7, 8, 8, 7, 8, 8]
    assert [source.names[c] for c in source.context.tolist()[:3]] == ["", "o<hole>", "o<hole>"]
    assert source.iteration.tolist()[:7] == [1, 1, 1, 2, 2, 2, 3]  # a call shows its caller's pass
    assert program.line_map.tolist()[:3] == [7, 8, 8]  # the window follows the main program
    assert set(program.toolpath.source_line.tolist()) <= {7, 8, 11}


@pytest.mark.parametrize("text", [
    "G0 X1 Y2\nG1 X3 F200\nM2\n",
    "%\nG21 G90\n(comment # in a comment)\nG0 X1\n%\n",
])
def test_plain_programs_take_the_fast_path(text):
    assert load_text(text).ops.source is None


def test_fix_and_fup_follow_each_dialect():
    assert xs("G1 X[FIX[-1.2]] Y0 F100\nG1 X[FUP[-1.2]]\nM2\n") == [-2.0, -1.0]  # LinuxCNC: floor, ceil
    assert xs("O0001\nG1 X[FIX[-1.2]] Y0 F100\nG1 X[FUP[-1.2]]\nG1 X[FUP[1.2]]\nM30\n") == [-1.0, -2.0, 2.0]


def test_subroutines_may_be_defined_after_m2_and_called_before():
    program = load_text("o100 call [2]\nG1 X#<_value> F100\nM2\no100 sub\n  G1 X#1 F100\no100 endsub [7]\n")
    assert [m["end"][0] for m in program.moves] == [2.0, 7.0] and not program.diagnostics


def test_g65_argument_specification_ii_sets_of_i_j_k():
    text = ("O0001\nG65 P9000 A7 I1 J2 K3 I4 J5 K6 I7\nG65 P9000 I1 K3 J9\nM30\n"
            "O9000\nG0 X#4 Y#5 Z#6\nG0 X#7 Y#8 Z#9\nG0 X#10 Y#1\nM99\n")
    program = load_text(text)
    assert not program.errors
    ends = [m["end"] for m in program.moves]
    assert ends[:3] == [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 7.0, 6.0]]
    # I1 K3 J9: J after K starts the second set (#8), the first set's J stays vacant
    assert ends[3:5] == [[1.0, 7.0, 3.0], [1.0, 9.0, 3.0]]


def test_g65_refuses_more_than_ten_sets_of_i_j_k():
    program = load_text("O0001\nG65 P9000 " + "I1 " * 11 + "\nM30\nO9000\nM99\n")
    assert [(e.line, e.message) for e in program.errors] == [
        (2, "G65 takes at most 10 sets of I J K (argument specification II)")]


def test_linuxcnc_predefined_parameters_are_read_only():
    program = load_text("G21\n#<_x> = 5\nM2\n")
    assert [(e.line, e.message) for e in program.errors] == [
        (2, "#<_x> is a predefined parameter: it can be read, not set")]


def test_linuxcnc_predefined_parameters_follow_the_moves_before_them():
    program = load_text("G21 G90\nG0 X3 Y4\nG1 X[#<_x> + #<_y>] Y#<_line> F100\nM2\n")
    assert not program.errors
    assert program.moves[-1]["end"][:2] == [7.0, 3.0]


def test_fanuc_dwell_is_x_seconds_or_p_milliseconds():
    program = load_text("O0001\n#1 = 250\nG04 X1.5\nG04 P1500\nG4 P#1\nM30\n")
    assert not program.errors
    dwells = [line for line in program.device_lines if line.startswith("G04")]
    assert dwells == ["G04 P1.5", "G04 P1.5", "G04 P0.25"]
    linuxcnc = load_text("#1 = 2\nG4 P#1\nM2\n")
    assert "G04 P2" in linuxcnc.device_lines
