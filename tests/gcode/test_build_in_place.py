"""``build_in_place``: a program whose moves are one run but for a short tail after an
event (a CAM footer) gets the Toolpath the copying ``build`` gives, its positions views
of the rows' own columns, and its rows as they were (put back together on first use)."""

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.ops import HANDED
from tests.gcode.scans import SAMPLES

FOOTER = "M5\nG0 Z5\nG0 X0 Y0\nM2\n"
HEADER = "%\n(header)\nG21 G90\nM3 S12000\nG4 P0.5\n"
CUTS = "".join(f"G1 X{10 + k} Y{10 + k % 3} F300\nG2 X{11 + k} Y{10 + k % 3} I0.5 J0\n" for k in range(40))
PROGRAMS = {
    "a Gcodetools footer": HEADER + "G0 Z5\nG0 X10 Y10\nG1 Z-1 F100\n" + CUTS + FOOTER,
    "events between the last moves": "G0 X1 Y1\n" + CUTS + "M5\nG1 X7\nM3 S100\nG1 Y5\nM9\nG1 X1\n"
                                     "G0 Z3\nM30\n",
    "an expanded program": "#1=3\nG0 X#1\n" + CUTS + "M5\nG1 X0\nM2\n",
    "dwells among the moves": "G0 X1\nG4 P1\n" + CUTS + "M5\nG4 P2\nG1 X2\nM2\n",
}
PROGRAMS.update({path.name: path.read_text() + FOOTER for path in sorted(SAMPLES.glob("*.ngc"))[:3]})


def _both(text: str, monkeypatch):
    """(the program loaded, whether it was built in place; the same built by copying)."""
    import app.gcode.program as program

    calls, real = [], program.build_in_place
    with monkeypatch.context() as m:
        m.setattr(program, "closable", lambda ops: None)
        copied = load_text(text)
        m.undo()
        m.setattr(program, "build_in_place", lambda *args: calls.append(args) or real(*args))
        placed = load_text(text)
    return placed, bool(calls), copied


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_toolpath_built_in_place_is_the_copied_one(name, monkeypatch):
    text = PROGRAMS[name]
    placed, in_place, copied = _both(text, monkeypatch)
    assert not placed.errors, placed.errors
    assert in_place
    tp, ops = placed.toolpath, placed.ops
    assert ops.handed_to is tp
    for column in ("start", "end", "kind", "center", "plane", "turn", "source_line", "device_index",
                   "feed", "length", "time"):
        np.testing.assert_array_equal(getattr(tp, column), getattr(copied.toolpath, column), err_msg=column)
    for column in (*HANDED, "kind", "plane", "turn", "value"):
        np.testing.assert_array_equal(getattr(ops, column), getattr(copied.ops, column), err_msg=column)
    assert placed.device_lines == copied.device_lines
    assert [str(d) for d in placed.diagnostics] == [str(d) for d in copied.diagnostics]
    np.testing.assert_array_equal(placed.plan.count, copied.plan.count)


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_check_s_timing_worked_out_before_the_close_up_is_the_copied_one(name, tmp_path, monkeypatch):
    """``cnc-gcode check`` (``plan_ahead``) times the moves on the rows' columns while it
    waits for the plan, events among them included and then left out."""
    import app.gcode.program as program

    path = tmp_path / "job.ngc"
    path.write_text(PROGRAMS[name])
    calls, real = [], program.timed_before_closing
    with monkeypatch.context() as m:
        m.setattr(program, "closable", lambda ops: None)
        copied = program.load(path, plan_ahead=True)
        m.undo()
        m.setattr(program, "timed_before_closing", lambda *args: calls.append(args) or real(*args))
        placed = program.load(path, plan_ahead=True)
    assert calls and not placed.errors
    for column in ("feed", "length", "time", "start", "end", "device_index"):
        np.testing.assert_array_equal(getattr(placed.toolpath, column), getattr(copied.toolpath, column),
                                      err_msg=column)
    assert placed.planned.total == copied.planned.total
    np.testing.assert_array_equal(placed.planned.line_seconds, copied.planned.line_seconds)


def test_the_positions_are_views_of_the_rows_own_columns():
    program = load_text(PROGRAMS["a Gcodetools footer"])
    tp = program.toolpath
    assert tp.center.base is not None  # a view of the rows' column, not a copy of its own
    assert tp.end.base is tp.start.base  # one array of points, as the rows wrote it
    for column in (tp.start, tp.end, tp.center):
        with pytest.raises(ValueError):
            column[0, 0] = 1.0


@pytest.mark.parametrize(("text", "closable"), [
    ("G0 X1\n" + CUTS + "M5\nG1 X2\nM2\n", True),  # one move after the first event among them
    ("G0 X1\n" + CUTS + "G1 X2\nM2\n", False),  # one run already: views as they are
    ("M3 S100\nG0 X1\nM5\n" + CUTS + "M2\n", False),  # most moves after an event
    ("G0 X1\n" + CUTS + "M5\nG1 X2\nM3 S100\nG0 Z5\n" + "M5\nG0 Z4\n" * 70 + "M2\n", False),  # runs
])
def test_which_programs_are_closed_up(text, closable, monkeypatch):
    placed, in_place, _ = _both(text, monkeypatch)
    assert not placed.errors and in_place == closable


def test_a_program_read_again_from_the_machine_s_position_is_built_in_place_the_same(monkeypatch):
    import app.gcode.program as program

    text = "G91\nG0 X1 Y1\nG90\n" + CUTS + "M5\nG1 X2\nM2\n"  # its first move from where the machine is
    with monkeypatch.context() as m:
        m.setattr(program, "closable", lambda ops: None)
        copied = load_text(text).from_start((3.0, 4.0, 0.0))
    placed = load_text(text).from_start((3.0, 4.0, 0.0))
    assert placed.ops.origin == (3.0, 4.0, 0.0) and placed.toolpath.end.base is placed.toolpath.start.base
    for column in ("start", "end", "center", "source_line", "device_index"):
        np.testing.assert_array_equal(getattr(placed.toolpath, column), getattr(copied.toolpath, column))
    assert placed.device_lines == copied.device_lines


def _spindle_every_tenth_line(text: str) -> str:
    """``text`` with a spindle speed change after every tenth line: events all along."""
    lines = text.splitlines()
    return "".join(f"{line}\n" + (f"M3 S{1000 + k}\n" if k % 10 == 9 else "") for k, line in enumerate(lines))


@pytest.mark.parametrize("closed_up", [True, False], ids=["closed up", "copied"])
def test_a_check_s_timing_on_two_threads_is_the_timing_on_first_use(closed_up, tmp_path, monkeypatch):
    """``cnc-gcode check`` times the moves while it waits for the plan, a block at a time
    on two threads once the plan is done (before the close-up, or in ``build``): the bits
    the window's Toolpath works out on first use, on one thread."""
    import app.gcode.program as program
    from app.gcode import toolpath

    monkeypatch.setattr(toolpath, "BLOCK", 7)  # many blocks, shared by the two threads
    closed, real = [], program.closable
    monkeypatch.setattr(program, "closable", lambda ops: closed.append(real(ops) is not None) or real(ops))
    path = tmp_path / "job.ngc"
    for sample in sorted(SAMPLES.glob("*.ngc"))[:3]:
        text = sample.read_text() + FOOTER
        path.write_text(text if closed_up else _spindle_every_tenth_line(text))
        lazy, ahead = program.load(path), program.load(path, plan_ahead=True)
        assert isinstance(ahead.toolpath._timing, list) and not isinstance(lazy.toolpath._timing, list)
        for column in ("feed", "length", "time"):
            np.testing.assert_array_equal(getattr(ahead.toolpath, column), getattr(lazy.toolpath, column),
                                          err_msg=f"{sample.name}: {column}")
    assert closed == [closed_up] * 6
