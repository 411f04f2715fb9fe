"""Compiled loops (``loop.py``): running a loop's passes in one generated function must
mean exactly what running its blocks one at a time means: the same rows, the same
trace of each row, the same errors at the same lines, the same work counted, whatever
happens inside (an error, a call that needs a frame, the loop limit, the work budget,
a batch interpreted mid-pass)."""

import pytest

from app.gcode import load_text
from app.gcode.macro import loop, walker

from .walks import FANUC_GRID, same_walks, walk

LINUXCNC_GRID = """o<hole> sub
  G0 X#1 Y#2
  G1 Z#3 F#4
  G0 Z1
o<hole> endsub
G21 G90 G17
#100 = 0
o1 while [#100 LT 4]
  #101 = 0
  o2 while [#101 LT 5]
    o<hole> call [#101 * 0.25] [#100 * 0.25] [-0.5] [300]
    #101 = [#101 + 1]
  o2 endwhile
  #100 = [#100 + 1]
o1 endwhile
M2
"""
MIXED = """o<deep> sub
  #<k> = [#1 * 2]
  G1 X#<k> F100
o<deep> endsub
#1 = 0
o1 while [#1 LT 6]
  G1 X[#1] Y0 F200

  G1 X[#1 + 1] Y1
  G1 X[#1 + 2] Y2
  #2 = [#1 * #1]
  o<deep> call [#2]
  G0 Z[#1]
  #1 = [#1 + 1]
o1 endwhile
M2
"""
FANUC_M98 = """O1
#1 = 0
WHILE [#1 LT 4] DO 1
  M98 P20 L2
  #1 = #1 + 1
  G1 X#1 F100
END 1
M30
O20
G1 Y#1 F100
M99
"""
ERRORS = [
    "#1 = 0\no1 while [#1 LT 6]\nG1 X#1 F100\n#2 = [1 / [#1 - 3]]\n#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "#1 = 0\no1 while [#1 LT 6]\nG1 X#1 F100\nG1 X[1 / [#1 - 2]]\nG1 Y1\n#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "#1 = 0\no1 while [SQRT[3 - #1] GE 0]\nG1 X#1 F100\n#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "#1 = 0\no1 while [#1 LT 6]\nG1 X#1 F100\no<nowhere> call\n#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "O1\n#1 = 0\nWHILE [#1 LT 6] DO 1\nG1 X#1 F100\nG65 P77 X1\n#1 = #1 + 1\nEND 1\nM30\n",
]
READS = "#1 = 0\no1 while [#1 LT 6]\nG1 X[#1 + #5420] F100\n#2 = #5420\n#1 = [#1 + 1]\no1 endwhile\nM2\n"
ENDLESS = "#1 = 0\no1 while [1]\nG1 X[#1 MOD 7] F100\n#1 = [#1 + 1]\no1 endwhile\nM2\n"
PROGRAMS = [FANUC_GRID, LINUXCNC_GRID, MIXED, FANUC_M98, READS, *ERRORS]


NOT_COMPILED = ((loop, "compile_loop", lambda *args: None),)


def _same(text: str, monkeypatch):
    return same_walks(text, monkeypatch, NOT_COMPILED)


@pytest.mark.parametrize("text", PROGRAMS)
def test_a_compiled_loop_means_what_its_blocks_mean(text, monkeypatch):
    _same(text, monkeypatch)


@pytest.mark.parametrize("text", ERRORS)
def test_an_error_inside_a_compiled_loop_is_reported_at_its_line(text, monkeypatch):
    program = _same(text, monkeypatch)
    assert program.errors and program.errors[0].line > 1


def test_batches_interpreted_mid_pass_change_nothing(monkeypatch):
    monkeypatch.setattr(walker, "MAX_ROWS", 7)
    for text in (FANUC_GRID, LINUXCNC_GRID, MIXED):
        _same(text, monkeypatch)


def test_the_loop_limit_is_kept(monkeypatch):
    monkeypatch.setattr(walker, "LOOP_LIMIT", 50)
    program = _same(ENDLESS, monkeypatch)
    (error,) = program.errors
    assert "more than 50 times" in error.message and error.line == 5


def test_the_work_budget_is_kept(monkeypatch):
    """Both walks check the budget where they can (the walk per block, the compiled loop
    per pass), against work counted the same way: both refuse, at a line of the loop."""
    monkeypatch.setattr(walker, "WORK_LIMIT", 5_000)
    for switched_off in ((), NOT_COMPILED):
        program, _ = walk(ENDLESS, monkeypatch, switched_off)
        (error,) = program.errors
        assert "more work than the limit of 5,000" in error.message and 2 <= error.line <= 5


def test_only_straight_bodies_are_compiled(monkeypatch):
    made = []
    compile_loop = loop.compile_loop
    monkeypatch.setattr(loop, "compile_loop", lambda *a: made.append(compile_loop(*a)) or made[-1])
    load_text(FANUC_GRID)
    assert [m is not None for m in made[:2]] == [False, True]  # the inner loop; the outer holds a loop
    made.clear()
    load_text("#1 = 0\no1 while [#1 LT 3]\no2 if [#1 EQ 1]\nG1 X1 F100\no2 endif\n#1 = [#1 + 1]\n"
              "o1 endwhile\nM2\n")
    assert made and not any(made)
