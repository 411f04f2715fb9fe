"""Accuracy: the encoder-measured tool stays within 0.1 mm of the programmed path.

Inkscape samples (resources/samples) go through ``app.gcode`` (allowed in tests only:
the simulator itself never imports it) to get their device lines, then through a
fresh, homed MotionController at their programmed feeds. ``bench/bench_motion.py``
runs every sample in both modes; here two samples and a hand-made program.
"""

from pathlib import Path

import numpy as np
import pytest

from backend_sim.motion.accuracy import contour_errors, run_lines

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
COUNT = 8.0 / 1980

OWN_LINES = [
    "M03 S3000", "G00 X10 Y10", "G00 Z1", "G01 Z-1 F100",
    "G01 X40 Y10 F400", "G01 X40 Y40", "G02 X10 Y40 I-15 J0", "G01 X10 Y10",
    "G03 X20 Y10 I5 J0 Z-2 F300",  # helix
    "G02 X20 Y10 I5 J5 F500",  # full circle
    "G01 X21 Y11 F600", "G01 X22 Y10", "G01 X23 Y11", "G01 X24 Y10",  # zig-zag corners
    "G00 Z5", "M05", "M30",
]


def sample_lines(name: str) -> list[str]:
    gcode = pytest.importorskip("app.gcode")
    path = SAMPLES / name
    if not path.exists():
        pytest.skip(f"{path} not there yet")
    return gcode.load(path).device_lines


def check(result, limit_mm=0.1):
    assert not result.alarms
    assert result.contour_max_mm <= limit_mm, result
    assert result.final_error_counts <= 1.0 + 1e-6, result
    assert result.final_error_mm <= 2 * COUNT, result  # the truth, one count of quantisation


@pytest.fixture(scope="module")
def own_planner():
    return run_lines(OWN_LINES, "planner")


def test_own_program_planner(own_planner):
    check(own_planner, 0.05)


def test_own_program_simple_mode_completes_but_is_slower(own_planner):
    simple = run_lines(OWN_LINES, "simple")
    assert not simple.alarms and simple.final_error_counts <= 1.0 + 1e-6
    assert simple.job_s > 1.3 * own_planner.job_s


@pytest.mark.parametrize("name", ["potrace_logo.ngc", "arcs_circles.ngc"])
def test_inkscape_sample_planner(name):
    result = run_lines(sample_lines(name), "planner")
    check(result, 0.1)  # the machine's specification
    assert result.contour_max_mm <= 0.05  # the planner's own target


def test_contour_error_of_a_known_offset():
    path = [np.array([[0.0, 0.0, 0.0], [10.0, 0.0, 0.0]]), np.array([[10.0, 0.0, 0.0], [10.0, 10.0, 0.0]])]
    points = np.array([[5.0, 0.3, 0.0], [10.2, 5.0, 0.0], [10.0, 0.0, 0.1]])
    err = contour_errors(points, np.array([-1, 0, 0]), path)
    assert err == pytest.approx([0.3, 0.2, 0.1])
