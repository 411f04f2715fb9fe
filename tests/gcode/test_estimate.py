"""The planner's time estimate: its passes against the planner's loops, and its totals
against runs of the simulated machine (simulated seconds, exact and load-independent)."""

import math

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.estimate import QUEUE_BLOCKS, estimate
from app.gcode.estimate_passes import entry_speeds_sq, junction_speeds, reached_speeds_sq, trapezoid_times
from bench.bench_estimate import real_run, short_segments

A = 50.0


def backward_loop(length, junction_sq, horizon):
    """The planner's backward pass as it runs: block k's entry is computed with the queue
    ending ``horizon`` blocks after block k-1 (where the path then is), the last stopping."""
    n = len(length)
    out = np.zeros(n)
    for k in range(n):
        tail = min(n - 1, k - 1 + horizon)
        nxt = 0.0
        for j in range(tail, k - 1, -1):
            nxt = min(math.sqrt(junction_sq[j]), math.sqrt(nxt * nxt + 2 * A * length[j]))
        out[k] = nxt * nxt
    return out


def test_the_backward_pass_is_the_planners_loop_with_its_queue_length():
    rng = np.random.default_rng(3)
    length = rng.uniform(0.0, 0.5, 200)
    junction_sq = rng.uniform(0.0, 120.0, 200)
    junction_sq[rng.integers(0, 200, 12)] = 0.0  # barriers and reversals
    junction_sq[rng.integers(0, 200, 12)] = np.inf  # straight on
    for horizon in (1, 4, QUEUE_BLOCKS - 1, 400):
        expected = backward_loop(length, junction_sq, horizon)
        assert np.allclose(entry_speeds_sq(length, junction_sq, A, horizon), expected)


def test_a_short_queue_slows_a_run_of_short_segments():
    length = np.full(100, 0.02)
    straight = np.full(100, np.inf)
    long_queue = entry_speeds_sq(length, straight, A, 99)
    short_queue = entry_speeds_sq(length, straight, A, 15)
    assert short_queue[50] == pytest.approx(2 * A * 0.02 * 15)  # can only stop within 15 blocks
    assert long_queue[50] > 3 * short_queue[50]


def test_the_forward_pass_starts_from_rest_and_accelerates_at_a():
    length = np.array([1.0, 1.0, 0.0, 2.0])
    entry_sq = np.array([50.0, 400.0, 0.0, 9.0])
    f = reached_speeds_sq(length, entry_sq, A)
    expected, prev = [], 0.0
    for k in range(4):  # the loop the planner's online trapezoid amounts to
        prev = 0.0 if k == 0 else min(entry_sq[k], prev + 2 * A * length[k - 1])
        expected.append(prev)
    assert np.allclose(f, expected)
    assert f[1] == pytest.approx(100.0) and f[2] == 0.0


def test_trapezoid_times():
    v = np.array([10.0])
    cruise = trapezoid_times(np.array([10.0]), np.zeros(1), np.zeros(1), v, A)[0]
    assert cruise == pytest.approx(10.0 / 10.0 + 10.0 / A)  # ramps at half speed
    triangle = trapezoid_times(np.array([0.5]), np.zeros(1), np.zeros(1), v, A)[0]
    assert triangle == pytest.approx(2 * math.sqrt(0.5 / A))
    flying = trapezoid_times(np.array([3.0]), v, v, v, A)[0]
    assert flying == pytest.approx(0.3)


def test_junction_speeds_follow_the_deviation_rule():
    x, y = np.array([[1.0, 0, 0]]), np.array([[0.0, 1, 0]])
    assert junction_speeds(x, x, A, 0.02)[0] == math.inf
    assert junction_speeds(x, -x, A, 0.02)[0] == 0.0
    sin_half = math.sqrt(0.5)
    assert junction_speeds(x, y, A, 0.02)[0] == pytest.approx(math.sqrt(A * 0.02 * sin_half / (1 - sin_half)))


NEARLY_STRAIGHT = "G00 X121.703677 Y88.137881 Z2\nG01 Z-0.8 F300\n{} F900\nG01 X110 Y95\nM02\n"  # Gcodetools'
# biarc of radius 56 km: its rounded centre would be too far off, so it is sent as one G01
STRAIGHT_ARC = "G03 X117.562241 Y95.365318 Z-0.8 I-48314.248092 J-27680.037918"
PROGRAMS = {
    "corners": "M03 S3000\nG00 Z2\nG00 X10 Y10\nG01 Z-0.5 F120\n"
               + "".join(f"G01 X{10 + 30 * (k % 2)} Y{10 + 3 * k} F500\n" for k in range(12)) + "M05\nM02\n",
    "arcs": "G00 X20 Y20 Z2\nG01 Z0 F200\nG02 X40 Y20 I10 J0 F400\nG03 X60 Y20 I10 J0\n"
            "G02 X60 Y20 I-5 J0\nG03 X50 Y30 Z-1 I-10 J0 F600\nM02\n",
    "short segments": short_segments(0.025, 600),  # 0.025 mm chords: the look-ahead is short
    "dwell and spindle": "M03 S2000\nG04 P1.5\nG00 X30 Y30 Z2\nM03 S4000\nG01 X40 F300\nG04 P0.25\n"
                         "G01 X50\nM05\nG00 Z5\nM02\n",
    # arcs the normaliser sends as G01 chords: outside the XY plane, of several turns
    "XZ and YZ arcs": "G00 X20 Y20 Z2\nF800\n"
                      + "".join(f"G18 G02 X{24 + 4 * k} Z2 I2 K0\n" for k in range(20))
                      + "G19 G03 Y60 Z2 J20 K0 F2000\nG02 Y20 Z2 J-20 K0\nG17 G01 X30\nM02\n",
    "three turns": "G00 X60 Y50 Z0\nG17 G03 X60 Y50 Z-3 I-10 J0 P3 F400\nG01 X70\nM02\n",
    "a nearly straight arc": NEARLY_STRAIGHT.format(STRAIGHT_ARC),
}


@pytest.mark.parametrize("name", list(PROGRAMS))
def test_the_estimate_agrees_with_the_simulated_machine(name):
    program = load_text(PROGRAMS[name])
    assert not program.errors
    real, start = real_run(list(program.device_lines), program.profile)
    est = estimate(program.toolpath, program.device_lines, program.profile, start=start, plan=program.plan)
    assert est.stops == 0 and est.stop_seconds == 0.0
    assert est.total == pytest.approx(real, rel=0.02)
    assert est.line_seconds.sum() == pytest.approx(est.total)
    assert est.row_seconds.sum() == pytest.approx(est.total)
    assert est.remaining(len(program.device_lines)) == pytest.approx(0.0, abs=1e-9)


def test_a_tool_change_and_a_stop_are_excluded_and_reported_apart():
    program = load_text("M03 S3000\nG00 X20 Y20 Z2\nG01 Z-1 F200\nG01 X40 F400\n"
                        "M06 T2\nG01 X60 F400\nM00\nG01 Y30\nG00 Z5\nM05\nM02\n")
    assert not program.errors
    real, start = real_run(list(program.device_lines), program.profile)
    est = estimate(program.toolpath, program.device_lines, program.profile, start=start)
    assert (est.stops, est.tool_changes) == (2, 1)
    assert est.stop_seconds > 1.0  # lift to the top of Z and back, spindle off and back up
    assert est.total + est.stop_seconds == pytest.approx(real, rel=0.02)
    assert est.total < real - 1.0
    for k, text in enumerate(program.device_lines):
        if text.startswith(("M06", "M00")):
            assert est.line_seconds[k] == 0.0


def test_the_queue_trails_the_path_by_the_moving_average():
    from app.gcode.estimate_passes import queue_horizons

    length = np.full(50, 0.1)
    still, queue_end = queue_horizons(length, np.zeros(50), 0.05, 16)
    assert still[10] == 15  # at most the queue less the block running
    moving, queue_end = queue_horizons(length, np.full(50, 10.0), 0.05, 16)  # trails 0.5 mm: 5 blocks
    assert moving[10] == 11 and queue_end[10] == pytest.approx(0.1 * 21)  # blocks 5..20 queued
    assert queue_horizons(length, np.full(50, 100.0), 0.05, 16)[0].min() == 1  # never below one


def test_the_queue_end_caps_the_entry_speed():
    length = np.full(20, 1.0)
    straight = np.full(20, np.inf)
    capped = entry_speeds_sq(length, straight, A, 15, queue_end=np.arange(20) + 2.5)
    assert capped[5] == pytest.approx(2 * A * 2.5)  # can stop 2.5 mm after block 5's start


def test_the_programs_planned_time_becomes_its_toolpaths():
    program = load_text(PROGRAMS["dwell and spindle"])
    before = program.toolpath.estimated_time
    planned = program.planned
    assert program.toolpath.estimated_time == pytest.approx(planned.total) != pytest.approx(before)
    per_line = np.bincount(program.toolpath.device_index, weights=program.toolpath.time,
                           minlength=program.device_count)
    assert per_line.sum() == pytest.approx(planned.line_seconds.sum())
    assert planned.remaining(3) == pytest.approx(planned.total - planned.line_seconds[:3].sum())


def test_the_look_ahead_binds_only_where_the_path_cannot_stop_in_it():
    from app.gcode.estimate_passes import look_ahead_binds

    straight = np.full(40, np.inf)
    for step, binds in ((1.0, False), (0.01, True)):
        length = np.full(40, step)
        entry = entry_speeds_sq(length, straight, A, 15)
        entry = np.minimum(entry, 100.0)  # 10 mm/s at most
        assert look_ahead_binds(length, entry, A, 5, np.cumsum(length) + 4 * step) is binds


def test_the_programs_own_events_stand_for_its_rendered_lines():
    from app.gcode.estimate_lines import EventLines

    text = PROGRAMS["dwell and spindle"] + "G01 X10 F300\nM01\nM06 T4\nG04 P2\nM30\n"
    program = load_text(text.replace("M02\n", ""))
    lines = EventLines(program.ops, program.plan)
    rendered = program.device_lines
    assert len(lines) == len(rendered)
    for k, line in enumerate(rendered):
        if line[:1] == "M" or line.startswith("G04"):
            assert lines[k].split()[0] == line.split()[0] and _words(lines[k]) == _words(line), (k, line)
    by_events = estimate(program.toolpath, lines, program.profile)
    by_render = estimate(program.toolpath, rendered, program.profile)
    assert by_events.total == pytest.approx(by_render.total)
    assert by_events.stop_seconds == pytest.approx(by_render.stop_seconds) and by_events.stops == 2


def _words(line: str) -> dict:
    return {word[0]: float(word[1:]) for word in line.split()[1:]}


ARCS_AND_STOPS = ("G21 G90 G17\nM3 S3000\nG0 X10 Y10 Z2\nG1 Z-1 F200\n"
                  + "".join(f"G{2 + k % 2} X{10 + 3 * (k + 1)} Y10 I1.5 J{0.2 * (k % 3)} F{300 + 10 * k}\n"
                            "G1 X{0} Y12\n".format(10 + 3 * (k + 1)) for k in range(12))
                  + "G4 P0.5\nM0\nG1 X5 Y5 Z-1.5\nM6 T2\nG2 X9 Y5 I2 J0\nG0 Z5\nM5\nM2\n")


def _same_estimate(a, b) -> None:
    assert np.array_equal(a.row_seconds, b.row_seconds) and np.array_equal(a.line_seconds, b.line_seconds)
    assert (a.motion, a.dwell, a.spin_up, a.stops, a.tool_changes, a.stop_seconds) == \
        (b.motion, b.dwell, b.spin_up, b.stops, b.tool_changes, b.stop_seconds)


def test_the_geometry_in_blocks_gives_the_same_numbers(monkeypatch):
    from app.gcode import estimate as module

    whole = load_text(ARCS_AND_STOPS).planned
    assert whole.stops == 2 and whole.tool_changes == 1 and whole.dwell == pytest.approx(0.5)
    monkeypatch.setattr(module, "BLOCK", 4)  # blocks that cut through arcs, lines and barriers
    _same_estimate(load_text(ARCS_AND_STOPS).planned, whole)


def test_a_load_that_plans_ahead_gives_the_same_estimate(tmp_path):
    from app.gcode import load

    path = tmp_path / "job.ngc"
    path.write_text(ARCS_AND_STOPS)
    later = load(path)
    assert later.planned_if_ready is None  # nothing computes it unasked
    ahead = load(path, plan_ahead=True)
    _same_estimate(ahead.planned, later.planned)
    assert ahead.planned_if_ready is ahead.planned
    assert np.array_equal(ahead.toolpath.time, later.toolpath.time)


@pytest.mark.parametrize("name", ["XZ and YZ arcs", "three turns"])
def test_an_arc_sent_as_chords_is_timed_as_its_chords(name):
    """Each chord is a block of the planner's and a device line of its own: its seconds
    are on its line (a job's progress and remaining time read them), and the arc's row
    holds their sum (a move follows every arc: the row before the end also holds the
    settling before it)."""
    program = load_text(PROGRAMS[name])
    tp, plan, est = program.toolpath, program.plan, program.planned
    chorded = np.flatnonzero(plan.chords)
    assert len(chorded) and (plan.count[chorded] > 10).all()
    for op in chorded:
        lines = est.line_seconds[plan.first[op] : plan.first[op] + plan.count[op]]
        row = int(np.flatnonzero(tp.device_index == plan.first[op])[0])
        assert (lines > 0).all() and lines.max() < 0.2 * lines.sum()
        assert lines.sum() == pytest.approx(est.row_seconds[row])
    assert est.row_seconds.sum() == pytest.approx(est.total) and len(est.row_seconds) == len(tp)
    assert np.array_equal(tp.time, est.row_seconds)


def test_an_arc_sent_as_one_chord_is_timed_as_that_line():
    line_to_its_end = "G01 X117.562241 Y95.365318 Z-0.8"
    arc, line = (load_text(NEARLY_STRAIGHT.format(move)) for move in (STRAIGHT_ARC, line_to_its_end))
    assert arc.plan.chords.sum() == 1 and arc.plan.count.sum() == line.plan.count.sum()
    assert arc.device_lines == line.device_lines
    np.testing.assert_allclose(arc.planned.line_seconds, line.planned.line_seconds, rtol=1e-12)
    assert arc.planned.total == pytest.approx(line.planned.total, rel=1e-12)
