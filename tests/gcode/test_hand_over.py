"""``Ops.hand_over``: a program whose events stand between its moves keeps the moves'
positions once (the Toolpath's), and every use of the interpreted rows reads the same
numbers as before they were handed over."""

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.ops import DWELL, Ops

PROGRAMS = [
    # Gcodetools' footer: a move between two events
    "G21\nG0 Z5\nG0 X10 Y10\nM3 S1000\nG1 Z-1 F100\nG2 X20 Y10 I5 J0 F400\nG3 X10 Y10 I-5 J0\n"
    "G0 Z5\nM5\nG0 X0 Y0\nM2\n",
    # stops, tool changes, dwells and spindle changes between moves, far outside the travel
    "G0 X1\nM0\nG0 X200 Y-300\nT1 M6\nG4 P1\nM3 S500\nG1 Y3 F100\nG2 X210 Y3 I5 J0\nS20000\n"
    "G1 X-400\nM1\nG0 Z400\nM5\nM30\n",
    # a subprogram: its rows' lines are in the subprogram, the main program's kept apart
    "o100 sub\nG1 X#1 Y2 F200\nM5\no100 endsub\nM3 S800\no100 call [300]\nG0 X1\no100 call [5]\nM2\n",
]


def _kept(monkeypatch, text):
    """The program loaded as before: nothing handed over."""
    with monkeypatch.context() as m:
        m.setattr(Ops, "hand_over", lambda self, moves: None)
        return load_text(text)


@pytest.mark.parametrize("text", PROGRAMS)
def test_rows_read_the_same_after_the_hand_over(monkeypatch, text):
    kept, program = _kept(monkeypatch, text), load_text(text)
    ops = program.ops
    assert "_handed" in ops.__dict__ and "end" not in ops.__dict__ and "center" not in ops.__dict__
    assert [str(d) for d in program.diagnostics] == [str(d) for d in kept.diagnostics]
    assert program.envelope.found == kept.envelope.found  # rows of the interpreted program
    np.testing.assert_array_equal(program.toolpath.start, kept.toolpath.start)
    np.testing.assert_array_equal(program.toolpath.center, kept.toolpath.center)
    assert program.device_lines == kept.device_lines  # rendering puts the columns back
    for name in ("line", "end", "center", "kind", "value"):
        np.testing.assert_array_equal(getattr(ops, name), getattr(kept.ops, name))
    np.testing.assert_array_equal(ops.starts(), kept.ops.starts())
    assert ops.end.base is not None and ops.end.base.shape == (len(ops) + 1, 3)  # starts: a view
    assert program.moves == kept.moves
    assert program.planned.total == kept.planned.total


def test_the_toolpath_holds_the_positions_and_they_cannot_change():
    program = load_text(PROGRAMS[0])
    tp, ops = program.toolpath, program.ops
    assert "line" not in ops.__dict__  # a plain program's lines are the toolpath's too
    for column in (tp.end, tp.center, tp.source_line):
        with pytest.raises(ValueError):
            column[0] = 1  # the interpreted rows are put back together from them
    rows = np.flatnonzero(ops.kind <= DWELL)
    np.testing.assert_array_equal(ops.end[rows], tp.end)


def test_a_toolpath_of_views_keeps_the_rows_as_they_are():
    program = load_text("M3 S1000\nG0 X10 Y5\nG1 X20 F300\nG2 X30 Y5 I5 J0\nM5\nM2\n")
    assert "_handed" not in program.ops.__dict__ and "end" in program.ops.__dict__
    assert np.shares_memory(program.toolpath.center, program.ops.center)


def test_the_command_line_puts_its_threads_on_one_heap_before_loading(monkeypatch, tmp_path, capsys):
    from app.gcode import cli, heap

    calls = []

    def glibc(name):
        return None if name != "mallopt" else (lambda param, value: calls.append((param, value, len(loads))))

    loads = []
    real_load = cli.load
    monkeypatch.setattr(heap, "_glibc", glibc)
    monkeypatch.setattr(cli, "load", lambda *a, **k: loads.append(1) or real_load(*a, **k))
    path = tmp_path / "a.ngc"
    path.write_text(PROGRAMS[0])
    assert cli.main(["check", str(path)]) == 0
    assert calls == [(param, value, 0) for param, value in heap.ONE_SHOT_HEAP]  # before the load began
    assert (heap.M_ARENA_MAX, 1, 0) in calls  # its threads on the main heap
    assert "moves: " in capsys.readouterr().out


def test_the_preflight_reads_the_moves_from_the_toolpath(monkeypatch):
    from app.gcode.checks import preflight

    kept, program = _kept(monkeypatch, PROGRAMS[1]), load_text(PROGRAMS[1])
    for offset in (program.profile.travel.work_offset(), (5.0, -7.0, -40.0)):
        got = preflight(program.ops, program.profile, program.lines, offset, program.envelope)
        assert got and got == preflight(kept.ops, kept.profile, kept.lines, offset, kept.envelope)
        fresh = preflight(kept.ops, kept.profile, kept.lines, offset)  # not the load's envelope
        assert [d.line for d in got] == [d.line for d in fresh]
    assert "end" not in program.ops.__dict__ and "center" not in program.ops.__dict__  # nothing put back


@pytest.mark.parametrize("text", PROGRAMS)
def test_checks_on_the_toolpath_beside_the_estimate_find_the_same(monkeypatch, tmp_path, text):
    from app.gcode import load

    path = tmp_path / "p.ngc"
    path.write_text(text)
    kept, program = _kept(monkeypatch, text), load(path, plan_ahead=True)  # cnc-gcode check's load
    assert "_handed" in program.ops.__dict__
    assert [str(d) for d in program.diagnostics] == [str(d) for d in kept.diagnostics]
    assert program.envelope.found == kept.envelope.found
    np.testing.assert_array_equal(np.array(program.toolpath.bounds), np.array(kept.toolpath.bounds))
    assert program.planned.total == kept.planned.total
