"""Issue 19: every hostile program is refused with an error naming a line, never a
traceback, never a run that goes on. The budgets are made smaller here so that the
suite stays quick; ``python -m bench bench_hostile`` runs them at full size through
``cnc-gcode check`` and prints the time and memory each takes."""

import pytest

from app.gcode import limits, load
from app.gcode.macro import walker
from tests.fuzz.hostile import PROGRAMS, REFUSED, write


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_hostile_program_is_refused_naming_a_line(monkeypatch, tmp_path, name):
    monkeypatch.setattr(walker, "WORK_LIMIT", 300_000)
    monkeypatch.setattr(walker, "MOVE_LIMIT", 50_000)
    monkeypatch.setattr(limits, "MAX_MOVES", 20_000)
    path = write(tmp_path, name)
    program = load(path)
    lines = len(path.read_text().splitlines())
    assert bool(program.errors) == (name in REFUSED), [str(d) for d in program.errors[:3]]
    assert all(1 <= d.line <= lines + 1 and d.message for d in program.errors)
