"""Toolpath arrays, lengths, time estimate, chords for drawing, bounds."""

import math

import numpy as np
import pytest

from app.gcode import ARC_CW, DWELL, FEED, RAPID, load_text
from app.gcode.toolpath import move_times
from app.profile import MachineProfile


def toolpath(text):
    program = load_text(text)
    assert not program.errors, program.errors
    return program.toolpath


def test_arrays_and_fields():
    tp = toolpath("G0 X10 Y0\nG1 X20 F300\nG2 X30 Y0 I5 J0\nG4 P2")
    assert tp.kind.tolist() == [RAPID, FEED, ARC_CW, DWELL]
    assert tp.start.shape == tp.end.shape == tp.center.shape == (4, 3)
    assert tp.start[1].tolist() == [10, 0, 0] and tp.end[1].tolist() == [20, 0, 0]
    assert tp.center[2].tolist() == [25, 0, 0] and np.isnan(tp.center[0]).all()
    assert tp.source_line.tolist() == [1, 2, 3, 4]
    assert tp.device_index.tolist() == [0, 1, 2, 3]
    assert tp.length[:3] == pytest.approx([10, 10, 5 * math.pi])
    assert tp.cut_length == pytest.approx(10 + 5 * math.pi)
    assert tp.rapid_length == pytest.approx(10)
    assert tp.time[3] == 2
    assert tp.feed.tolist()[:3] == [600, 300, 300]


def test_trapezoid_and_triangle_times():
    accel = 50.0
    v = 600 / 60  # 10 mm/s reaches full speed in 0.2 s over 1 mm
    t_long, t_short = move_times([100.0, 1.0], [600.0, 600.0], accel)
    assert t_long == pytest.approx(100 / v + v / accel)
    assert t_short == pytest.approx(2 * math.sqrt(1.0 / accel))


def test_estimated_time_includes_dwells_and_uses_profile():
    tp = toolpath("G1 X60 F600\nG4 P3")
    assert tp.estimated_time == pytest.approx(6.2 + 3)
    profile = MachineProfile()
    assert tp.feed[0] <= profile.motion.max_feed_mm_min


def test_feeds_are_capped_at_the_profile_maximum():
    tp = toolpath("G1 X10 F5000")
    assert tp.feed[0] == 600


def test_polyline_arcs_as_chords_within_tolerance():
    tp = toolpath("G0 X10\nG3 I-10 F100")
    for tol in (0.1, 0.01):
        pts, index = tp.polyline(tol)
        assert len(pts) == len(index)
        arc_pts = pts[index == 1]
        r = np.hypot(arc_pts[:, 0], arc_pts[:, 1])
        assert np.allclose(r, 10)
        mid = (arc_pts[1:] + arc_pts[:-1]) / 2  # chord midpoints sag at most tol
        assert (10 - np.hypot(mid[:, 0], mid[:, 1])).max() <= tol + 1e-9
    assert len(tp.polyline(0.01)[0]) > len(tp.polyline(0.1)[0])


def test_bounds_include_arc_bulge_exactly():
    low, high = toolpath("G0 X10\nG3 I-10 F100").bounds
    assert low[:2] == pytest.approx([-10, -10], abs=1e-12)
    assert high[:2] == pytest.approx([10, 10], abs=1e-12)
    low, high = toolpath("G0 X10 Y0\nG3 X0 Y10 I-10 F100").bounds  # a quarter: no other bulge
    assert low.tolist() == [0, 0, 0] and high[:2] == pytest.approx([10, 10])
    low, high = toolpath("G0 X0 Y0 Z0\nG18 G2 X10 Z0 I5 K0 F100").bounds  # XZ plane: Z bulges
    assert max(abs(low[2]), abs(high[2])) == pytest.approx(5) and min(abs(low[2]), abs(high[2])) == 0


def test_bounds_of_arcs_in_several_planes_at_once():
    text = "G0 X0 Y0 Z0\nG18 G2 X10 Z0 I5 K0 F100\nG17 G3 X10 Y0 I0 J-4\nG19 G2 Y0 Z0 J3 K0\n"
    low, high = toolpath(text).bounds
    assert low.tolist() == pytest.approx([0, -8, -5]) and high.tolist() == pytest.approx([14, 6, 3])


def test_helix_length():
    tp = toolpath("G0 X10\nG2 I-10 Z-5 F100")
    assert tp.length[1] == pytest.approx(math.hypot(2 * math.pi * 10, 5))


def test_empty_program():
    tp = toolpath("(nothing)\n")
    assert len(tp) == 0 and tp.estimated_time == 0 and tp.cut_length == 0
    assert tp.bounds[0].tolist() == [0, 0, 0]
    assert tp.polyline()[0].shape == (0, 3)


def test_chords_on_two_threads_equal_chords_on_one(monkeypatch):
    from app.gcode import toolpath as toolpath_module

    text = "".join(f"G0 X{20 + k} Y{k % 5}\nG2 X{20 + k} Y{k % 5} I-{1 + k % 4} F100\n" for k in range(40))
    one = toolpath(text).polyline(0.01)
    monkeypatch.setattr(toolpath_module, "PARALLEL_ARCS", 4)
    two = toolpath(text).polyline(0.01)
    np.testing.assert_array_equal(one[0], two[0])
    np.testing.assert_array_equal(one[1], two[1])


def test_chord_points_of_many_arcs_equal_those_of_each_arc_alone():
    """Arcs of one chord and of many, in every plane, helices and full turns: a batch
    gives exactly the points each arc gives alone (one-chord arcs take a shortcut)."""
    from app.gcode.arcs import chord_points
    from app.gcode.ops import PLANE_AXES

    rng = np.random.default_rng(9)
    n = 300
    c = rng.uniform(-50, 50, (n, 3))
    r = rng.uniform(0.01, 40, n)
    a0, a1 = rng.uniform(-4, 4, n), rng.uniform(-4, 4, n)
    axes = np.array(PLANE_AXES)[rng.integers(0, 3, n)]
    s, e, rows = c.copy(), c.copy(), np.arange(n)
    s[rows, axes[:, 0]] += r * np.cos(a0)
    s[rows, axes[:, 1]] += r * np.sin(a0)
    e[rows, axes[:, 0]] += r * np.cos(a1)
    e[rows, axes[:, 1]] += r * np.sin(a1)
    e[rows, axes[:, 2]] += rng.uniform(-3, 3, n) * (rng.random(n) < 0.3)
    e[::17] = s[::17]  # full circles
    turn = rng.choice([-2, -1, 1, 2], n)
    for tolerance in (0.01, 2.0, 30.0):
        points, owner = chord_points(s, e, c, axes, turn, tolerance)
        assert 0 < np.count_nonzero(np.bincount(owner, minlength=n) == 1) < n or tolerance == 0.01
        for i in range(n):
            one = slice(i, i + 1)
            alone, _ = chord_points(s[one], e[one], c[one], axes[one], turn[one], tolerance)
            np.testing.assert_array_equal(points[owner == i], alone)


@pytest.mark.parametrize("text", [
    "M3 S1000\nG0 X10 Y5\nG1 X20 F300\nM5\nG0 X0 Y0\nM2",  # events between the moves
    "G0 X10 Y5\nG1 X20 F300\nG2 X30 Y5 I5 J0\nM2",  # the moves one run
    "G0 X1\nM0\nG0 X2\nT1 M6\nG4 P1\nM3 S500\nG1 Y3 F100\nM5\nM30",  # stops and tool changes between
])
def test_starts_and_ends_are_the_rows_and_cannot_be_changed(text):
    program = load_text(text)
    tp, ops = program.toolpath, program.ops
    rows = np.flatnonzero(ops.kind <= DWELL)
    np.testing.assert_array_equal(tp.start, ops.starts()[rows])
    np.testing.assert_array_equal(tp.end, ops.end[rows])
    np.testing.assert_array_equal(tp.center, ops.center[rows])
    one_run = rows[-1] - rows[0] < len(rows)
    shared = [tp.start, tp.end] + ([tp.center, tp.kind, tp.source_line] if one_run else [])
    for column in shared:
        with pytest.raises(ValueError):
            column[0] = 1  # shared with the interpreted rows or with each other


def _every_arc_chorded(tp, tolerance):
    """The polyline as it was built before arcs were counted first: every arc through
    ``chord_points``, its points put in its rows."""
    from app.gcode.arcs import chord_points
    from app.gcode.ops import ARC_CCW, PLANE_AXES

    moves = np.flatnonzero(tp.kind != DWELL)
    arc = (tp.kind[moves] == ARC_CW) | (tp.kind[moves] == ARC_CCW)
    rows = moves[arc]
    pts_arc, owner = chord_points(tp.start[rows], tp.end[rows], tp.center[rows],
                                  np.array(PLANE_AXES)[tp.plane[rows]], tp.turn[rows], tolerance)
    count = np.ones(len(moves), np.int64)
    count[arc] = np.bincount(owner, minlength=len(rows))
    index = np.repeat(moves, count)
    pts = tp.end[index]
    pts[np.repeat(arc, count)] = pts_arc
    return np.concatenate([tp.start[moves[:1]], pts]), np.concatenate([moves[:1], index])


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("tolerance", [0.001, 0.05, 0.6, 5.0])
def test_arcs_counted_first_give_the_same_polyline(monkeypatch, tolerance, threads):
    from app.gcode import toolpath as module

    monkeypatch.setattr(module, "PARALLEL_ARCS", 2)  # the two-thread split, even for a few arcs
    monkeypatch.setattr(module, "PIECE_ARCS", 3)  # pieces that cut between one- and many-chord arcs
    arcs, x = [], 0.0
    for k in range(9):  # half circles of radius 0.3 to 9.3 mm, either way, some helical
        radius = 0.3 + 3 * (k % 4)
        arcs.append(f"G{2 + k % 2} X{x + 2 * radius:.4f} Y0 Z{-1 - 0.1 * (k % 2):.1f} I{radius:.4f} J0\n"
                    f"G1 X{x + 2 * radius + 0.2:.4f}\n")
        x += 2 * radius + 0.2
        arcs.append(f"G{3 - k % 2} X{x + 0.5 + k:.4f} R{1 + 4 * k}\n")  # short sweeps: one chord when coarse
        x += 0.5 + k
    text = ("G0 X0 Y0 Z1\nG1 Z-1 F300\n" + "".join(arcs)
            + f"G18 G2 X{x + 5:.4f} Z-1 I2.5 K0\nG19 G3 Y5 Z-1 J2.5 K0\nG17 G4 P1\n"
            + f"G3 X{x + 5:.4f} Y5 I-3 J0\nG2 X{x + 5.02:.4f} Y5 I0.01 J0\nM2\n")
    tp = toolpath(text)
    expected = _every_arc_chorded(tp, tolerance)
    pts, index = tp.polyline(tolerance, threads)
    assert np.array_equal(pts, expected[0]) and np.array_equal(index, expected[1])


def test_the_timing_is_worked_out_once_whichever_threads_ask():
    """The feeds, lengths and times are worked out on first use (the window's loader asks
    on one thread while another may ask too): once, and every thread gets the same."""
    import threading

    tp = toolpath("G0 X10 Y0\nG1 X20 F300\nG2 X30 Y0 I5 J0\nG4 P2")
    work, calls, entered, release = tp._timing, [], threading.Event(), threading.Event()

    def slow():
        calls.append(1)
        entered.set()
        release.wait(10)
        return work()

    tp._timing = slow
    seen = []
    first = threading.Thread(target=lambda: seen.append(tp.feed))
    first.start()
    entered.wait(10)  # the first thread is inside the work; a second one asks now
    second = threading.Thread(target=lambda: seen.append(tp.length))
    second.start()
    release.set()
    first.join(10)
    second.join(10)
    assert len(calls) == 1 and len(seen) == 2
    assert seen[0] is tp.feed and seen[1] is tp.length
    assert tp.length.tolist() == pytest.approx([10.0, 10.0, 5 * math.pi, 0.0])


@pytest.mark.parametrize("text", [
    "G0 X0 Y0\nG1 X5 F300\nG3 X6 Y1 I0 J1\nG1 Y4\nM2",  # the moves one run: the rows' own points
    "M3 S1000\nG0 X1 Y1\nG1 X5 F300\nG2 X6 Y0 I0 J-1\nM5\nG0 X0 Y0\nM2",  # an event between the moves
    "G0 X1\nG3 X2 Y1 I0 J1 F200\nG4 P1\nG1 Y3 F100\nM30",  # a dwell: it has no point of its own
])
def test_a_polyline_of_one_chord_arcs_is_the_toolpath_s_points(text):
    """When every move ends a segment (lines, and arcs of one chord at this tolerance)
    and the moves' starts and ends are one array, the polyline is that array, read-only."""
    tp = toolpath(text)
    pts, index = tp.polyline(1.0)
    expected = _every_arc_chorded(tp, 1.0)
    np.testing.assert_array_equal(pts, expected[0])
    np.testing.assert_array_equal(index, expected[1])
    if not (tp.kind == DWELL).any():
        assert np.shares_memory(pts, tp.end) and np.shares_memory(pts, tp.start)
    with pytest.raises(ValueError):
        pts[0, 0] = 1.0  # cached and shared: nobody changes it


def test_unrelated_starts_and_ends_give_no_shared_points():
    from app.gcode.toolpath import _points

    points = np.arange(30.0).reshape(10, 3)
    assert np.array_equal(_points(points[:-1], points[1:]), points)
    assert _points(points[:-2], points[2:]) is None  # two rows apart
    assert _points(points[:-1].copy(), points[1:]) is None
    assert _points(points[1:][::-1], points[:-1][::-1]) is None  # not contiguous
