"""Models with no drawing: position history ring buffer, progress, SD names, ports."""

import numpy as np
import pytest

from app.ui.plot.history import PositionHistory
from app.ui.ports import available_ports
from app.ui.progress import ProgressTracker, line_times
from app.ui.sd_panel import name_problem, suggest_name


def test_history_is_a_ring_with_contiguous_rows():
    history = PositionHistory(capacity=5)
    for i in range(12):
        history.append(float(i), (i, 2 * i, 3 * i), (i + 0.5, 2 * i, 3 * i))
    rows = history.rows()
    assert len(rows) == 5 and rows.base is not None  # a view into the buffer
    assert list(rows[:, 0]) == [7, 8, 9, 10, 11]
    assert list(history.window(2.0)[:, 0]) == [9, 10, 11]
    assert history.latest()[1] == 11 and history.latest()[4] == 11.5


def test_history_window_when_empty():
    assert len(PositionHistory(4).window(10)) == 0


def test_progress_remaining_is_corrected_by_the_measured_rate():
    cumulative = np.cumsum(np.full(100, 2.0))  # 2 s per line, 200 s in all
    tracker = ProgressTracker(cumulative, 100, started=0.0)
    tracker.update(50)
    view = tracker.view(now=50.0)  # twice as fast as estimated
    assert view.percent == 50.0
    assert view.remaining == pytest.approx(50.0)
    tracker.update(100)
    assert tracker.view(now=100.0).remaining == 0.0


def test_time_held_at_a_stop_is_not_motion():
    cumulative = np.cumsum(np.full(100, 2.0))  # 2 s per line, 200 s in all
    tracker = ProgressTracker(cumulative, 100, started=0.0)
    tracker.update(50)
    tracker.hold(30.0)  # a program stop: the operator changes the tool for 600 s
    assert tracker.view(now=330.0).remaining == pytest.approx(30.0)  # 30 moving s did 100 estimated
    tracker.release(630.0)
    view = tracker.view(now=650.0)
    assert view.elapsed == 650.0 and view.remaining == pytest.approx(50.0)  # 50 moving s for 100


def test_line_times_from_toolpath():
    class Tp:
        time = np.array([1.0, 2.0, 3.0])
        device_index = np.array([0, 2, 3])

    assert list(line_times(Tp, 4)) == [1.0, 1.0, 3.0, 6.0]


@pytest.mark.parametrize(
    "path, name",
    [("/x/star passes.ngc", "star_passes.nc"), ("logo (v2).gcode", "logo_v2.nc"), ("%%%.nc", "program.nc"),
     ("a" * 50 + ".ngc", "a" * 29 + ".nc")],
)
def test_sd_name_suggested_from_the_file(path, name):
    assert suggest_name(path) == name
    assert name_problem(name) == ""


@pytest.mark.parametrize("bad", ["", "../etc", "a/b", "x" * 33, "sp ace"])
def test_sd_bad_names_are_explained(bad):
    assert "letters" in name_problem(bad)


def test_port_list_puts_the_simulator_first():
    ports = available_ports()
    assert ports[0][0].startswith("sim://")
