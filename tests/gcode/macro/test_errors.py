"""Every refusal of the expander names the file, the line and (where it has one) the
column, and stops the walk without hanging or eating memory (issue 9, point 9)."""

import pytest

from app.gcode import load, load_text
from app.gcode.macro import walker


def errors(text, folder=None):
    return [(d.file, d.line, d.column, d.message) for d in load_text(text, folder=folder).errors]


@pytest.mark.parametrize(("text", "line", "column", "words"), [
    ("G1 X1 F100\nG1 X[1/0]\n", 2, 7, "division by zero"),
    ("G1 X1 F100\n#1 = [2 MOD 0]\n", 2, 9, "MOD by zero"),
    ("G1 X[SQRT[-4]] F100\n", 1, 6, "SQRT of -4: square root of a negative number"),
    ("G1 X[ACOS[2]] F100\n", 1, 6, "ACOS of 2: out of the range -1..1"),
    ("G1 X[ASIN[-1.5]] F100\n", 1, 6, "ASIN of -1.5"),
    ("G1 X[LN[0]] F100\n", 1, 6, "LN of 0"),
    ("G1 X[[-8] ** 0.5] F100\n", 1, 11, "non-integer power"),
    ("G1 X#<depth> F100\n", 1, 5, "#<depth> is not set"),
    ("G1 X[ATAN[1]] F100\n", 1, 13, "ATAN[a]/[b]"),
    ("G1 X[1 + ] F100\n", 1, 10, "a value was expected"),
    ("G1 X[1 + 2 F100\n", 1, 12, "expected ']'"),
    ("G1 X[FOO[1]] F100\n", 1, 6, "unknown function"),
    ("#2 = [1/0]\n", 1, 8, "division by zero"),
])
def test_expression_errors_name_line_and_column(text, line, column, words):
    (file, got_line, got_column, message), = errors(text)
    assert (file, got_line, got_column) == ("", line, column) and words in message


def test_division_by_zero_only_when_the_line_runs():
    assert errors("o1 if [0]\n  G1 X[1/0]\no1 endif\nG1 X1 F100\nM2\n") == []


@pytest.mark.parametrize(("text", "line", "words"), [
    ("WHILE [1] DO 1\nG1 X1 F100\nM30\n", 1, "DO 1 has no END 1"),
    ("G1 X1 F100\nEND 1\nM30\n", 2, "END 1 without its DO 1"),
    ("WHILE [1] DO 1\nWHILE [1] DO 2\nEND 1\nEND 2\nM30\n", 3, "the open loop is DO 2"),
    ("WHILE [1] DO 4\nEND 4\nM30\n", 1, "1, 2 or 3"),
    ("GOTO 50\nM30\n", 1, "GOTO 50: no block N50"),
    ("#1 = 1\nIF [#1 EQ 1] GOTO 7\nM30\n", 2, "no block N7"),
    ("O0001\nM98 P1234\nM30\n", 2, "subprogram O1234 is not defined"),
    ("O0001\nG65 P1234 A1\nM30\n", 2, "subprogram O1234 is not defined"),
    ("O0001\nM99\n", 2, "M99 ends the main program"),
    ("o<nowhere> call\nM2\n", 1, "subroutine o<nowhere> is not defined"),
    ("o1 if [1]\nG1 X1 F100\nM2\n", 1, "'if' is never closed"),
    ("o1 endwhile\nM2\n", 1, "o1 endwhile without o1 while"),
    ("o1 while [1]\no2 endwhile\nM2\n", 2, "o2 endwhile without o2 while"),
    ("o1 break\nM2\n", 1, "outside a loop"),
    ("o1 else\nM2\n", 1, "without o1 if"),
    ("o1 sub\no1 return\n", 1, "never closed"),
    ("o1 frobnicate\nM2\n", 1, "unknown o-word statement"),
])
def test_control_flow_errors_name_the_line(text, line, words):
    found = errors(text)
    assert any(f[1] == line and words in f[3] for f in found), found


def test_missing_subprogram_beside_a_file_names_the_file_looked_for(tmp_path):
    (tmp_path / "main.nc").write_text("O0001\nM98 P77\nM30\n")
    (error,) = load(tmp_path / "main.nc").errors
    assert error.line == 2 and "O0077.nc" in error.message


def test_an_error_in_a_subprogram_file_names_that_file(tmp_path):
    (tmp_path / "main.ngc").write_text("G1 X1 F100\no<bad> call\nM2\n")
    (tmp_path / "bad.ngc").write_text("o<bad> sub\n  G1 X[SQRT[-1]]\no<bad> endsub\n")
    (error,) = load(tmp_path / "main.ngc").errors
    assert (error.file.endswith("bad.ngc"), error.line, error.column) == (True, 2, 8)
    assert str(error).startswith(str(tmp_path / "bad.ngc") + " line 2, column 8: SQRT")


def test_a_loop_past_the_limit_stops_naming_its_line(monkeypatch):
    assert walker.LOOP_LIMIT == 1_000_000
    monkeypatch.setattr(walker, "LOOP_LIMIT", 1000)
    (error,) = load_text("#1 = 0\nWHILE [1] DO 1\n#1 = #1 + 1\nEND 1\nM30\n").errors
    assert error.line == 4 and "more than 1,000 times" in error.message and "line 2" in error.message
    (error,) = load_text("o1 do\nG1 X1 F100\no1 while [1]\nM2\n").errors
    assert error.line == 3 and "more than 1,000 times" in error.message
    (error,) = load_text("N1 G1 X1 F100\nGOTO 1\nM30\n").errors
    assert error.line == 2 and "more than 1,000 times" in error.message


def test_recursion_past_64_levels_stops_naming_the_call():
    program = load_text("o1 sub\n  o1 call\no1 endsub\nG1 X1 F100\no1 call\nM2\n")
    (error,) = program.errors
    assert error.line == 2 and "deeper than 64" in error.message
    assert len(program.moves) == 1  # what came before stays


def test_an_expansion_past_the_move_limit_stops(monkeypatch):
    assert walker.MOVE_LIMIT == 2_000_000
    monkeypatch.setattr(walker, "MOVE_LIMIT", 500)
    program = load_text("#1 = 0\no1 while [#1 LT 100000]\n  G1 X[#1 MOD 7] F100\n  #1 = [#1 + 1]\n"
                        "o1 endwhile\nM2\n")
    (error,) = program.errors
    assert "more than 500 moves" in error.message and error.line in (2, 3, 4, 5)
    assert len(program.moves) == 0  # a refused program of millions of rows keeps none (memory)


def test_errors_of_several_lines_are_all_listed_before_running():
    found = errors("G1 X[1 +] F100\nG1 Y[2 *] F100\nM2\n")
    assert [f[1] for f in found] == [1, 2]


def test_the_moves_before_an_error_stay():
    program = load_text("#1 = 0\no1 while [#1 LT 5]\n  G1 X#1 F100\n  #1 = [#1 + 1]\no1 endwhile\n"
                        "G1 X[1/0]\nG1 X9\nM2\n")
    assert [m["end"][0] for m in program.moves] == [0.0, 1.0, 2.0, 3.0, 4.0]
    assert [(d.line, d.column) for d in program.errors] == [(6, 7)]


def test_a_computed_g65_on_a_motion_line_is_a_call_and_is_refused_there():
    text = "O1000\n#1 = 65\nG1 X0 F100\nG#1 X1\nG1 X2\nM30\n"
    assert errors(text) == [("", 4, 1, "G65 needs P (the program number)")]


def test_an_ini_value_is_read_only():
    (error,) = load_text("G21 F100\nG1 X1\n#<_ini[axis_x]max_limit> = 3\nG1 X2\nM2\n").errors
    assert error.line == 3 and "ini file: it can be read, not set" in error.message


def test_abort_stops_with_its_text_where_the_flow_reaches_it():
    text = ("G21 F100\n#1 = 7\no1 if [#1 GT 9]\n(ABORT, never)\no1 endif\nG1 X1\n(Abort, #1 is #<_x>)\n"
            "G1 X2\nM2\n")
    program = load_text(text)
    assert [(d.line, d.message) for d in program.errors] == [
        (7, "(ABORT) the program stops here: 7.000000 is 1.000000")]
    assert [m["end"][0] for m in program.moves] == [1.0]
    plain = load_text("G21 F100\nG1 X1\n ( abort , stop ) \nG1 X2\nM2\n")
    assert [(d.line, d.message) for d in plain.errors] == [(3, "(ABORT) the program stops here: stop")]
    assert [m["end"][0] for m in plain.moves] == [1.0]


def test_a_loop_repeating_an_interpreter_error_stops_at_its_second_pass():
    """Issue 19: a refused G38.3 in a loop of a million passes is one error, and the walk
    ends there (the lines after a first refusal are still checked, issue 20)."""
    text = ("G21 F100\n#1 = 0\no1 while [#1 LT 1000000]\nG1 X[#1 + 1]\nG38.3 Z-1\n#1 = [#1 + 1]\n"
            "o1 endwhile\nM2\n")
    program = load_text(text)
    assert [(d.line, d.column) for d in program.errors] == [(5, 1)]
    assert len(program.moves) == 2  # the first pass's move, the second pass's, then the stop
