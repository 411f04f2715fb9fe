"""Diagnostics for tuning the PID gains by eye: per axis (rows X, Y, Z), commanded
(dashed) vs measured position on the left and the following error (commanded -
measured) on the right, over the last 10 s, redrawn by a ~30 Hz timer."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QEvent, Qt, QTimer
from PySide6.QtWidgets import QVBoxLayout, QWidget

from app.ui.numbers import fill
from app.ui.plot.axes import local_axes, refresh_ticks
from app.ui.plot.history import COMMANDED, MEASURED, PositionHistory, T
from app.ui.plot.position_plot import AXIS_COLOURS, REDRAW_MS
from app.ui.plot.ranges import SteadyYRange


class DiagnosticsView(QWidget):
    def __init__(self, history: PositionHistory, parent=None, seconds: float = 10.0):
        super().__init__(parent)
        self.history = history
        self.seconds = seconds
        self._drawn_version = -1
        self.layout_widget = pg.GraphicsLayoutWidget()
        self.layout_widget.ci.setContentsMargins(2, 2, 2, 2)
        self.layout_widget.ci.setSpacing(0)
        self.position_curves, self.error_curves, self.plots, self.y_ranges = [], [], [], []
        self._error_plots = []
        for row, (axis, colour) in enumerate(zip("XYZ", AXIS_COLOURS, strict=True)):
            self._add_axis(row, axis, colour)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.layout_widget)
        self.timer = QTimer(self, interval=REDRAW_MS, timeout=self.redraw)
        self.timer.start()

    def retranslate_ui(self) -> None:
        for axis, plot in self._error_plots:
            plot.setLabel("left", fill(self.tr("%1 error mm"), axis))
        for plot in self.layout_widget.ci.items:
            refresh_ticks(plot)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def _add_axis(self, row: int, axis: str, colour: str) -> None:
        pos = self.layout_widget.addPlot(row=row, col=0, axisItems=local_axes())
        err = self.layout_widget.addPlot(row=row, col=1, axisItems=local_axes())
        pos.setLabel("left", f"{axis} mm")
        self._error_plots.append((axis, err))
        err.setLabel("left", fill(self.tr("%1 error mm"), axis))
        for plot in (pos, err):
            plot.showGrid(x=True, y=True, alpha=0.2)
            plot.setMenuEnabled(False)
            plot.getAxis("left").setWidth(52)
            plot.getAxis("left").enableAutoSIPrefix(False)
        err.setXLink(pos)
        pos.setXRange(-self.seconds, 0, padding=0)
        # Y moves in whole steps (the axis text is most of a frame); errors never zoom
        # into sub-micron noise
        self.y_ranges += [SteadyYRange(pos, min_span=1.0), SteadyYRange(err, min_span=0.02)]
        commanded = pos.plot(pen=pg.mkPen("#c0c0c0", width=1, style=Qt.PenStyle.DashLine), connect="finite")
        measured = pos.plot(pen=pg.mkPen(colour, width=1), connect="finite")
        self.position_curves.append((commanded, measured))
        self.error_curves.append(err.plot(pen=pg.mkPen(colour, width=1), connect="finite"))
        self.plots += [pos, err]

    def redraw(self, force: bool = False) -> bool:
        if not force and (self.history.version == self._drawn_version or not self.isVisible()):
            return False
        self._drawn_version = self.history.version
        rows = self.history.window(self.seconds)
        t = rows[:, T] - (rows[-1, T] if len(rows) else 0.0)
        measured, commanded = rows[:, MEASURED].T, rows[:, COMMANDED].T
        for axis in range(3):
            cmd_curve, meas_curve = self.position_curves[axis]
            error = commanded[axis] - measured[axis]
            cmd_curve.setData(t, commanded[axis])
            meas_curve.setData(t, measured[axis])
            self.error_curves[axis].setData(t, error)
            self.y_ranges[2 * axis].fit(np.concatenate([commanded[axis], measured[axis]]))
            self.y_ranges[2 * axis + 1].fit(error)
        return True
