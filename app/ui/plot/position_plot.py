"""Live X, Y, Z position against time: a scrolling window redrawn by a ~30 Hz timer.

Status frames only append to the shared ``PositionHistory``; the timer redraws when
the history changed and the widget is visible, never once per frame.
"""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QEvent, QTimer
from PySide6.QtWidgets import QVBoxLayout, QWidget

from app.ui.plot.axes import local_axes, refresh_ticks
from app.ui.plot.history import MEASURED, PositionHistory, T
from app.ui.plot.ranges import SteadyYRange

AXIS_COLOURS = ("#ff5555", "#50fa7b", "#5599ff")
REDRAW_MS = 33
Y_STEP = 10.0


class PositionPlot(QWidget):
    def __init__(self, history: PositionHistory, parent=None, seconds: float = 30.0):
        super().__init__(parent)
        self.history = history
        self.seconds = seconds
        self._drawn_version = -1
        self.plot = pg.PlotWidget(axisItems=local_axes())
        self.retranslate_ui()
        self.plot.showGrid(x=True, y=True, alpha=0.2)
        for side in ("left", "bottom"):
            self.plot.getAxis(side).enableAutoSIPrefix(False)
        self.plot.addLegend(offset=(10, 10), labelTextSize="8pt")
        self.plot.getPlotItem().setMenuEnabled(False)
        self.curves = [
            self.plot.plot(pen=pg.mkPen(colour, width=1), name=axis, connect="finite")
            for axis, colour in zip("XYZ", AXIS_COLOURS, strict=True)
        ]
        self.plot.setXRange(-seconds, 0, padding=0)
        self.y_range = SteadyYRange(self.plot.getPlotItem(), min_span=Y_STEP, step=Y_STEP, margin=2.0)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.plot)
        self.timer = QTimer(self, interval=REDRAW_MS, timeout=self.redraw)
        self.timer.start()

    def retranslate_ui(self) -> None:
        self.plot.setLabel("bottom", self.tr("time"), units="s")
        self.plot.setLabel("left", self.tr("position"), units="mm")
        refresh_ticks(self.plot.getPlotItem())

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)
    def redraw(self, force: bool = False) -> bool:
        """Refill the curves if the history changed; True when something was drawn."""
        if not force and (self.history.version == self._drawn_version or not self.isVisible()):
            return False
        self._drawn_version = self.history.version
        rows = self.history.window(self.seconds)
        t = rows[:, T] - (rows[-1, T] if len(rows) else 0.0)
        for curve, column in zip(self.curves, rows[:, MEASURED].T, strict=True):
            curve.setData(t, column)
        self.y_range.fit(rows[:, MEASURED])  # whole steps of 10 mm: the axis text rarely changes
        return True
