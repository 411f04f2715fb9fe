"""Issue 21, "Trace the outline": the outline program of a job (rectangle, convex hull)."""

from __future__ import annotations

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.outline import convex_hull, outline_lines, visited

JOB = """G21 G90
G00 Z5
G00 X10 Y10
G01 Z-1 F200
G01 X40 Y10 F600
G03 X40 Y30 I0 J10
G01 X10 Y30
G01 X10 Y10
G00 Z5
M30
"""


def test_the_rectangle_is_traced_spindle_off_at_the_job_s_top_and_is_a_valid_program():
    program = load_text(JOB, name="job")
    lines = outline_lines(program.toolpath, 900)
    assert lines[:4] == ["G21 G90", "M05", "G00 Z5", "G00 X10 Y10"]
    corners = ["G01 X50 Y10 F900", "G01 X50 Y30 F900", "G01 X10 Y30 F900", "G01 X10 Y10 F900"]
    assert lines[4:] == [*corners, "M30"]
    traced = load_text("\n".join(lines), name="outline")
    assert not traced.errors
    reached = visited(traced.toolpath)
    assert reached.min(axis=0).tolist() == [10, 10, 5] and reached.max(axis=0).tolist() == [50, 30, 5]
    # the arc's bulge (X50) is inside, and the whole trace runs at Z5


def test_the_hull_follows_the_arc_and_stays_inside_the_rectangle():
    program = load_text(JOB, name="job")
    lines = outline_lines(program.toolpath, 900, hull=True)
    traced = load_text("\n".join(lines), name="outline")
    assert not traced.errors
    xy = np.array([[float(w[1:]) for w in line.split()[1:3]] for line in lines if line.startswith("G01")])
    assert len(xy) > 5 and xy[:, 0].max() == pytest.approx(50, abs=0.02) and xy[:, 0].min() == 10
    assert (xy[:, 1] >= 10 - 1e-9).all() and (xy[:, 1] <= 30 + 1e-9).all()


def test_convex_hull_drops_inner_and_collinear_points():
    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2], [1, 1], [1, 0], [0, 0]])
    assert convex_hull(square) == [(0, 0), (2, 0), (2, 2), (0, 2)]


def test_a_job_that_moves_nowhere_in_xy_or_a_bad_feed_is_refused():
    with pytest.raises(ValueError, match="nowhere"):
        outline_lines(load_text("G00 Z5\nG01 Z-1 F100\n", name="z").toolpath, 900)
    with pytest.raises(ValueError, match="feed"):
        outline_lines(load_text(JOB, name="job").toolpath, 0)
