"""Where a job starts: the machine's own position, never an assumed origin (issue 19).

Unit tests of ``start.py`` and the device lines of first moves, then an end-to-end run on
the simulator: after a jog to X143.7 Y64.3, ``G00 Z-5`` and ``G91 G00 Z-2`` move Z only.
"""

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.start import NEVER
from tests.comm.simlink import FAST_HOMING, SimLink


def lines(text, **kw):
    program = load_text(text, **kw)
    assert not program.errors, program.errors
    return program.device_lines


@pytest.mark.parametrize("text, device", [
    ("G00 Z-5\n", ["G00 Z-5"]),
    ("G0 X0 Z-5\nG0 Y3\n", ["G00 X0 Z-5", "G00 Y3"]),  # X0 named: sent, though it equals the origin
    ("G0 Z5\nG0 X0 Y0\n", ["G00 Z5", "G00 X0 Y0"]),
    ("M3 S1000\nG0 Z0\n", ["M03 S1000", "G00 Z0"]),
    ("G0 X1 Y2 Z3\nG1 X4 F10\n", ["G00 X1 Y2 Z3", "G01 X4 F10"]),
    ("G91 G0 X0\nG90 G0 Z1\nG0 Z1\n", ["G04 P0", "G00 Z1", "G00 Z1"]),  # nothing set: a no-op line
    ("G20 G0 Z1\n", ["G00 Z25.4"]),
    ("G55 G0 Z1\n", ["G00 Z1"]),
])
def test_first_moves_name_only_the_axes_the_program_sets(text, device):
    assert lines(text) == device


def test_a_relative_first_move_depends_on_the_start_and_is_read_again_from_it():
    program = load_text("G91 G00 Z-2\nG90 G0 X1\n")
    assert program.start.relative == (False, False, True)
    assert program.start.relative_line == (0, 0, 1)
    assert program.device_lines == ["G00 Z-2", "G00 X1"]  # from the assumed origin
    job = program.from_start((143.7, 64.3, 5.0))
    assert job is not program and job.start.origin == (143.7, 64.3, 5.0)
    assert job.device_lines == ["G00 Z3", "G00 X1"]
    assert job.toolpath.start[0].tolist() == [143.7, 64.3, 5.0]
    assert job.from_start((143.7, 64.3, 5.0)) is job  # already read from there
    assert "Z moves relative to where the machine stands from line 1" in program.start.note()


def test_a_relative_move_back_to_the_origin_is_still_sent():
    job = load_text("G91 G0 Z-2\nG0 Z2\nG0 Z2\n").from_start((0.0, 0.0, 7.0))
    assert job.device_lines == ["G00 Z5", "G00 Z7", "G00 Z9"]


def test_absolute_programs_do_not_depend_on_the_start():
    program = load_text("G0 Z5\nG0 X10 Y10\nG1 Z-1 F100\nG2 X20 Y10 I5 J0\n")
    assert not program.start.depends
    assert program.from_start((143.7, 64.3, 5.0)) is program
    assert program.start.known_from == (1, 1, 0)  # rows
    assert program.start.known_line == (2, 2, 1)
    assert "X stays where the machine stands until line 2" in program.start.note()


def test_an_axis_never_set_is_never_sent():
    program = load_text("G0 Z5\nG1 Z-1 F100\n")
    assert program.start.known_from[:2] == (NEVER, NEVER)
    assert "X stays where the machine stands (the program never sets it)" in program.start.note()
    assert program.device_lines == ["G00 Z5", "G01 Z-1 F100"]


def test_an_arc_from_where_the_tool_stands_is_relative():
    program = load_text("G2 X10 Y0 I5 J0 F100\n")
    assert program.start.relative[:2] == (True, True)


@pytest.mark.parametrize("text", [
    "G91 G81 X5 Y5 R2 Z-3 F100\nG80\n",  # a cycle from where the tool stands
    "#1 = -2\nG91 G0 Z#1\n",  # the expander
    "o100 repeat [3]\nG91 G0 Z-1\no100 endrepeat\n",
])
def test_relative_starts_are_found_whichever_path_reads_them(text):
    program = load_text(text)
    assert program.start.relative[2], program.start
    job = program.from_start((1.0, 2.0, 3.0))
    assert not job.errors
    assert np.allclose(job.toolpath.start[0], (1.0, 2.0, 3.0))


def test_the_probe_reads_more_until_every_axis_is_set():
    text = "G0 Z5\n" + "G1 Z4 F100\n" * 3000 + "G0 X1 Y2\n"
    program = load_text(text)
    assert program.start.known_from == (3001, 3001, 0)
    assert program.device_lines[-1] == "G00 X1 Y2"


def test_a_long_relative_program_is_relative_to_the_end():
    program = load_text("G91\n" + "G1 X1 F100\n" * 5000)
    assert program.start.relative[0] and program.start.known_from[0] == NEVER
    job = program.from_start((10.0, 0.0, 0.0))
    assert job.device_lines[-1] == "G01 X5010"


# -- on the simulator: the tool stands at X143.7 Y64.3 after a jog ------------------------


def _jogged_link():
    link = SimLink(check=False, profile=FAST_HOMING)
    link.home()
    link.command_ok("JOG", "X", "143.7", "900", timeout=60.0)
    link.command_ok("JOG", "Y", "64.3", "900", timeout=60.0)
    link.command_ok("SET", "AFTERJOB", "0")  # Z stays where the job leaves it
    link.run_for(0.2)
    return link


def _position(link):
    status = link.rec.last("on_status")
    return status.x, status.y, status.z


@pytest.mark.parametrize("text", ["G00 Z-5\n", "G91 G00 Z-2\n"])
def test_a_first_z_move_on_the_simulator_moves_z_only(text):
    link = _jogged_link()
    x, y, z = _position(link)
    assert (x, y) == pytest.approx((143.7, 64.3), abs=0.01)
    program = load_text(text)
    job = program.from_start((x, y, z))
    assert all("X" not in line and "Y" not in line for line in job.device_lines), job.device_lines
    link.run_job(job.device_lines)
    link.run_until(lambda: link.rec.last("on_status").state == "IDLE", 30.0)
    link.run_for(0.5)
    want_z = -5.0 if "G91" not in text else z - 2.0
    assert [line for _, line in link.executed()] == job.device_lines
    assert _position(link) == pytest.approx((143.7, 64.3, want_z), abs=0.02)
    assert job.toolpath.end[-1][2] == pytest.approx(want_z, abs=1e-6)


def test_past_the_probe_limit_an_axis_still_moving_with_the_start_is_relative():
    from app.gcode.start import PROBE_MAX

    text = "G0 Z1\n" * (PROBE_MAX + 10) + "G0 X3\n"
    program = load_text(text)
    assert program.start.relative == (True, True, False)  # X, Y undecided after PROBE_MAX rows
    assert program.device_lines[-1] == "G00 X3"
    job = program.from_start((0.0, 7.0, 1.0))
    assert job.device_lines[-1] == "G00 X3" and "G00 Z1 Y7" not in job.device_lines
    assert not any("Y" in line for line in job.device_lines[: PROBE_MAX - 1])


def test_the_probe_reads_rows_not_lines_of_a_plain_program(monkeypatch):
    """A line may make thousands of rows (a spline's chords): the first-move probe stops at
    the rows it asked for, never reading on by lines."""
    import math

    from app.gcode import motion
    from app.gcode.start import PROBE_MAX, PROBE_ROWS

    calls = []
    real = motion.run_spline
    monkeypatch.setattr(motion, "run_spline", lambda *a, **k: calls.append(1) or real(*a, **k))
    lines = 40
    heavy = "G5 I100000 J100000 P-100000 Q100000 X{x} Y1\n"
    text = "G21 G90 F100\nG0 X0 Y0\n" + "".join(heavy.format(x=k % 2) for k in range(lines)) + "M2\n"
    program = load_text(text)
    per_line = (len(program.ops) - 1) / lines
    caps, cap = [], PROBE_ROWS
    while cap <= PROBE_MAX:
        caps.append(cap)
        cap *= 8
    probed = len(calls) - lines  # the main reading calls it once a line
    assert 0 < probed <= 2 * sum(math.ceil(c / per_line) for c in caps) < 2 * lines, (probed, per_line)
    job = program.from_start((1.0, 2.0, 7.0))  # Z, never set, undecided past the probe's rows:
    z_words = {word for line in job.device_lines for word in line.split() if word.startswith("Z")}
    assert z_words <= {"Z7"}  # read from the machine's Z, never moved
