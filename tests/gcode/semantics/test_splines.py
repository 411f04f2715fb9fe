"""G5 / G5.1 splines: chords within the arc tolerance of the Bezier curve.

rs274 -g prints NURBS_FEED without its control points, so these are checked against
the curve's definition instead of a recording."""

from __future__ import annotations

import numpy as np
import pytest

from app.gcode.splines import bezier, chord_count


def _feeds(program):
    return np.array([m["end"] for m in program.moves if m["kind"] == "feed"])


def _distance_to_polyline(points: np.ndarray, poly: np.ndarray) -> np.ndarray:
    a, b = poly[:-1], poly[1:]
    ab = b - a
    t = np.clip(((points[:, None, :] - a) * ab).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-30), 0, 1)
    nearest = a + t[..., None] * ab
    return np.min(np.linalg.norm(points[:, None, :] - nearest, axis=-1), axis=1)


@pytest.mark.parametrize("text, control", [
    ("G5 I10 J20 P-10 Q20 X50 Y0", [(0, 0), (10, 20), (40, 20), (50, 0)]),
    ("G5.1 I20 J30 X40 Y0", [(0, 0), (20, 30), (40, 0)]),
])
def test_chords_stay_within_the_tolerance(run, text, control):
    program = run(f"G0 X0 Y0\nF100 {text}\n")
    assert not program.errors
    chords = np.vstack([[0.0, 0.0], _feeds(program)[:, :2]])
    assert np.allclose(chords[-1], control[-1])
    curve = bezier(control, np.linspace(0, 1, 4001))
    assert _distance_to_polyline(curve, chords).max() <= 0.01 + 1e-9
    assert len(chords) - 1 == chord_count(control, 0.01)


def test_g5_without_i_j_mirrors_the_last_control_point(run):
    program = run("G0 X0 Y0\nF100 G5 I0 J10 P-5 Q10 X10 Y0\nG5 P-5 Q-10 X20 Y0\n")
    first_of_second = [m for m in program.moves if m["line"] == 3][0]["end"]
    curve = bezier([(10, 0), (15, -10), (15, -10), (20, 0)], np.array([1 / chord_count(
        [(10, 0), (15, -10), (15, -10), (20, 0)], 0.01)]))
    assert np.allclose(first_of_second[:2], curve[0])


def test_z_moves_along_and_offsets_apply(run):
    program = run("G10 L2 P1 X100\nG0 X0 Y0\nF100 G5.1 I5 J5 X10 Y0 Z-2\n")
    feeds = _feeds(program)
    assert np.allclose(feeds[-1], [110, 0, -2]) and (np.diff(feeds[:, 2]) < 0).all()


@pytest.mark.parametrize("text, fragment", [
    ("F100 G5.1 I1 X5", "both I and J with G5.1"),
    ("F100 G5 I1 P1 Q1 X5", "both I and J, or neither"),
    ("F100 G5 I1 J1 X5", "both P and Q with G5"),
    ("G5.1 I1 J1 X5", "zero feed rate"),
    ("F100 G18 G5.1 I1 J1 X5", "XY plane"),
    ("F100 G5.2 X1 Y1 P1 L3", "NURBS"),
])
def test_spline_refusals(run, text, fragment):
    program = run(text + "\n")
    assert [d.line for d in program.errors] == [1] and fragment in program.errors[0].message
