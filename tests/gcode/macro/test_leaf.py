"""Leaf calls (``leaf.py``): a call of a subprogram of plain moves, made without a frame,
must mean exactly what pushing the frame and running its blocks means: the same rows,
the same trace of each row, the same errors and the same work counted."""

import pytest

from app.gcode import load_text
from app.gcode.macro import leaf

from .walks import FANUC_GRID, same_walks

FANUC_M98 = "O1\n#1 = 3\nM98 P20\n#1 = 4\nM98 P20 L2\nM98 P20\nM30\nO20\nG1 X#1 Y#1 F100\nG0 Z1\nM99\n"
LINUXCNC = """o<hole> sub
  G0 X#1 Y#2
  G1 Z#3 F#4
  G0 Z1
o<hole> endsub
o<outer> sub
  o<hole> call [#1] [#1 + 1] [-1] [200]
o<outer> endsub
#1 = 0
o1 while [#1 LT 4]
  o<hole> call [#1 * 3] [2] [-0.5] [300]
  o<outer> call [#1]
  #1 = [#1 + 1]
o1 endwhile
(debug, #<_value_returned>)
M2
"""
REPEATS = ("O1\n#1 = 0\nWHILE [#1 LT 4] DO 1\nG65 P20 L#1 X[#1 * 2] Y#7\n#1 = #1 + 1\nEND 1\n"
           "G65 P20 L1 X9\nG65 P20 L0 X8\nM30\nO20\nG1 X#24 Y#25 F100\nG0 Z1\nM99\n")  # L 0..3, vacant Y
FAILING = "O1\nG65 P20 X1\nG65 P20 X0\nM30\nO20\nG1 X[1 / #24] F100\nG0 Z1\nM99\n"
NOT_LEAVES = [
    "O1\nG65 P20 X1\nM30\nO20\n#1 = 2\nG1 X#1 F100\nM99\n",  # an assignment
    "O1\nG65 P20 X1\nM30\nO20\nG1 X[#5420 + 1] F100\nM99\n",  # a read of the machine's state
    "O1\nG65 P20 X1\nM30\nO20\nG1 X#24 F100\nM99 P5\nN5 G0 Z2\nM30\n",  # a return to a label
    "o<s> sub\nG1 X#1 F100\no<s> endsub [2]\no<s> call [1]\n(debug, #<_value>)\nM2\n",  # a value
]


NO_LEAVES = ((leaf, "find", lambda unit, start: None),)


@pytest.mark.parametrize("text", [FANUC_GRID, FANUC_M98, LINUXCNC, REPEATS, FAILING, *NOT_LEAVES])
def test_a_leaf_call_means_what_running_its_frame_means(text, monkeypatch):
    same_walks(text, monkeypatch, NO_LEAVES)


def test_the_leaf_path_is_taken_for_plain_bodies_only(monkeypatch):
    found = []
    find = leaf.find
    monkeypatch.setattr(leaf, "find", lambda unit, start: found.append(find(unit, start)) or found[-1])
    for text in (FANUC_GRID, LINUXCNC):
        load_text(text)
    assert any(f is not None and len(f.members) == 3 for f in found)
    found.clear()
    for text in NOT_LEAVES:
        load_text(text)
    assert found and all(f is None for f in found)


def test_a_failing_leaf_names_the_subprograms_line():
    program = load_text(FAILING)
    (error,) = program.errors
    assert error.line == 6 and "division by zero" in error.message
    assert len(program.moves) == 2  # the first call's rows stay
