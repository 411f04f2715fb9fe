"""Plot axes whose tick labels use the window language's decimal separator."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QLocale


class LocalAxis(pg.AxisItem):
    """A pyqtgraph axis writing ``0,5`` instead of ``0.5`` when the language does."""

    def tickStrings(self, values, scale, spacing):  # noqa: N802 (pyqtgraph override)
        strings = super().tickStrings(values, scale, spacing)
        point = QLocale().decimalPoint()
        return strings if point == "." else [s.replace(".", point) for s in strings]


def local_axes() -> dict[str, LocalAxis]:
    """``axisItems`` for a ``PlotWidget`` / ``addPlot``: left and bottom axes."""
    return {side: LocalAxis(orientation=side) for side in ("left", "bottom")}


def refresh_ticks(plot: pg.PlotItem) -> None:
    """Redraw the tick labels of ``plot`` (after a language switch)."""
    for side in ("left", "bottom"):
        axis = plot.getAxis(side)
        axis.picture = None
        axis.update()
