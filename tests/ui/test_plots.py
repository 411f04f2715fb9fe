"""Live plots: the curves show the history's window, the Y range moves in whole steps
and holds the data, and nothing is redrawn while the history is unchanged."""

import numpy as np
import pytest

from app.ui.plot.diagnostics import DiagnosticsView
from app.ui.plot.history import PositionHistory
from app.ui.plot.position_plot import PositionPlot
from app.ui.plot.ranges import nice_step, stepped


@pytest.mark.parametrize(("span", "step"), [(1.0, 0.5), (4.0, 1.0), (7.0, 2.0), (0.013, 0.005), (150, 50)])
def test_nice_steps(span, step):
    assert nice_step(span) == pytest.approx(step)


def test_stepped_range_holds_the_data_in_whole_steps():
    lo, hi = stepped(-0.0123, 0.0311, min_span=0.02)
    step = nice_step(0.0434)
    assert lo <= -0.0123 and hi >= 0.0311
    assert lo / step == pytest.approx(round(lo / step)) and hi / step == pytest.approx(round(hi / step))
    assert stepped(5.0, 5.0, min_span=1.0) == pytest.approx((4.5, 5.5))


def _history(n=300):
    history = PositionHistory(1000)
    for i in range(n):
        t = i * 0.02
        measured = (40 + 10 * np.sin(t), 20 + 5 * np.cos(t), 3.0)
        history.append(t, measured, (measured[0] + 0.004, measured[1], measured[2] - 0.002))
    return history


@pytest.fixture
def shown(qtbot):
    def show(widget):
        qtbot.addWidget(widget)
        widget.resize(700, 500)
        widget.show()
        qtbot.waitExposed(widget)
        return widget
    return show


def test_position_plot_shows_the_window_and_steadies_its_range(shown):
    history = _history()
    plot = shown(PositionPlot(history, seconds=30.0))
    assert plot.redraw()
    assert not plot.redraw()  # unchanged history: nothing to draw
    x, y = plot.curves[0].getData()
    assert len(x) == 300 and x[-1] == 0.0 and np.allclose(y, history.rows()[:, 1])
    (lo, hi) = plot.plot.getPlotItem().getViewBox().viewRange()[1]
    assert lo <= y.min() and hi >= y.max() and plot.y_range.range[0] % 10 == 0
    before = plot.y_range.range
    history.append(history.latest()[0] + 0.02, (45.0, 20.0, 3.0))
    plot.redraw()
    assert plot.y_range.range == before  # a move inside the range leaves the axis alone


def test_diagnostics_show_following_error(shown):
    history = _history()
    view = shown(DiagnosticsView(history))
    assert view.redraw()
    _, error = view.error_curves[0].getData()
    assert np.allclose(error, 0.004)
    lo, hi = view.y_ranges[1].range
    assert lo <= 0.004 <= hi and hi - lo >= 0.02
    empty = shown(DiagnosticsView(PositionHistory(10)))
    assert empty.redraw(force=True) and empty.y_ranges[1].range is None  # no data, no range yet
