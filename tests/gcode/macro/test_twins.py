"""Fanuc macro B programs against the rs274 recording of their LinuxCNC twins.

rs274 reads no Fanuc syntax, so each Fanuc program here has a twin under
``tests/oracle/cases`` written with o-words; the twin's recorded canon is the
expected motion, move by move (kind, end point, feed, arc centre and direction).
Source lines differ between the two files and are not compared.
"""

from pathlib import Path

import pytest

from app.gcode import load
from tests.oracle.canon import compare_moves, read_record
from tests.oracle.test_oracle import expected_moves, lines_as_recorded

HERE = Path(__file__).resolve().parent
DATA = HERE.parents[1] / "oracle" / "data"
TWINS = {"twin.nc": "macro_twin_fanuc", "twin2.nc": "macro_twin_fanuc2"}


@pytest.mark.parametrize("name", sorted(TWINS))
def test_fanuc_program_cuts_what_its_linuxcnc_twin_cuts(name):
    program = load(HERE / "fanuc" / name)
    assert not program.errors, [str(d) for d in program.errors]
    theirs = expected_moves(read_record(DATA / f"{TWINS[name]}.canon"))
    ours = lines_as_recorded(program.moves)
    assert len(ours) == len(theirs)
    for mine, other in zip(ours, theirs, strict=True):
        mine["line"] = other["line"]  # two files, two numberings
    problems = compare_moves(ours, theirs)
    assert not problems, "\n".join(problems)


def test_subprogram_moves_name_their_file_and_the_calling_line():
    program = load(HERE / "fanuc" / "twin.nc")
    from_file = [m for m in program.moves if m.get("file")]
    assert {m["file"] for m in from_file} == {"O0200.nc"}
    assert [m["line"] for m in from_file] == [3, 4]
    rows = program.ops.source.file == 1
    assert set(program.ops.source.call_line[rows].tolist()) == {28}  # N20 M98 P200
    names = program.ops.source.names
    assert "O9001" in names and "O0200" in names
