"""The toolpath preview: XY view of the program drawn with pyqtgraph.

Few items: the path (every drawing group: rapids dashed, cuts coloured by depth) and
its finished part, each a ``PictureLayer`` (an image of the view, ``picture.py``; the
finished part grows by painting only what is new), the travel rectangle, the
program's bounding box, the tool marker and a highlighted move. After every pan or
zoom the path is repainted from the model's level of detail for the new view
(coalesced to one refill per event-loop turn), so the cost of a redraw stays bounded
for a file of a million lines, and a moving tool marker costs a blit.
"""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QEvent, Qt, QTimer, Signal
from PySide6.QtGui import QPen
from PySide6.QtWidgets import QVBoxLayout, QWidget

from app.ui.numbers import decimal
from app.ui.plot.axes import local_axes, refresh_ticks
from app.ui.preview.geometry import AIR_GROUP, DEPTH_BANDS, RAPID_GROUP
from app.ui.preview.model import PreviewModel
from app.ui.preview.picture import PictureLayer

DONE_COLOUR = "#39d353"
LEVELS_POLL_MS = 250
MARKER_COLOUR = "#ff4040"
HIGHLIGHT_COLOUR = "#00e5ff"


RAPID_COLOUR = "#9a9a9a"
AIR_COLOUR = "#5fa8d3"
# Shallow to deep: warm colours that stand out on the black background.
DEPTH_COLOURS = ("#ffe066", "#ffa94d", "#ff6b6b", "#f06595", "#cc5de8")


def group_colours() -> list[str]:
    """The colour of each drawing group: rapids, cuts at or above the stock, depth bands."""
    return [RAPID_COLOUR, AIR_COLOUR] + [DEPTH_COLOURS[i % len(DEPTH_COLOURS)] for i in range(DEPTH_BANDS)]


def legend_entries(model: PreviewModel) -> list[tuple[int, str]]:
    """(group, label) of each drawing group ``model`` has, in the legend's order."""
    if model is None or model.empty:
        return []
    edges = model.geometry.depth_edges
    entries = [(RAPID_GROUP, QCoreApplication.translate("PreviewWidget", "rapid"))]
    if len(model.groups[AIR_GROUP]):
        entries.append((AIR_GROUP, QCoreApplication.translate("PreviewWidget", "feed Z ≥ 0")))
    for band in range(DEPTH_BANDS):
        if len(model.groups[2 + band]):
            entries.append((2 + band, f"Z {decimal(edges[band], 2)} … {decimal(edges[band + 1], 2)}"))
    return entries


def rectangle_pairs(x0: float, y0: float, x1: float, y1: float) -> tuple[list[float], list[float]]:
    """The four sides of a rectangle as point pairs (the curves here draw ``connect="pairs"``:
    a 5-point outline would draw two sides of four)."""
    xs = [x0, x1, x1, x1, x1, x0, x0, x0]
    ys = [y0, y0, y0, y1, y1, y1, y1, y0]
    return xs, ys

class PreviewWidget(QWidget):
    """``show_program(toolpath)``, ``fit()``, ``set_tool(x, y)``, ``set_done(seq)``."""

    frame_drawn = Signal()

    def __init__(self, parent=None, travel=(150.0, 150.0), offset=(0.0, 0.0)):
        super().__init__(parent)
        self.model: PreviewModel | None = None
        self._done_move = -1
        self.plot = pg.PlotWidget(axisItems=local_axes())
        self.plot.setAspectLocked(True)
        self.grid = False
        self.plot.setLabel("bottom", "X", units="mm")
        self.plot.setLabel("left", "Y", units="mm")
        for side in ("left", "bottom"):  # major ticks only: tick text is most of a frame's cost
            axis = self.plot.getAxis(side)
            axis.enableAutoSIPrefix(False)
            axis.setStyle(maxTickLevel=0, textFillLimits=[(0, 0.8)])
        self.plot.getPlotItem().setMenuEnabled(False)
        self.view = self.plot.getViewBox()
        self.view.disableAutoRange()
        self.legend = self.plot.addLegend(offset=(10, 10), labelTextSize="8pt")
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.plot)
        self._make_items()
        self.set_travel(travel, offset)
        self._refill = QTimer(self, singleShot=True, interval=0, timeout=self._refill_now)
        self.view.sigRangeChanged.connect(self._refill.start)
        self.view.sigResized.connect(self._refill.start)  # the pictures are the view's size
        # Until the loader has built every level of detail, look again now and then.
        self._levels_poll = QTimer(self, singleShot=True, interval=LEVELS_POLL_MS, timeout=self._refill_now)
        self.view.setRange(xRange=(0, travel[0]), yRange=(0, travel[1]))
        self.plot.setToolTip(self.tr("wheel: zoom · drag: pan · Ctrl+F: fit · Ctrl+G: grid"))

    def _make_items(self) -> None:
        self.travel_item = self._curve(pg.mkPen("#808080", width=1), z=-10)
        self.bounds_item = self._curve(pg.mkPen("#c8a000", width=1, style=Qt.PenStyle.DashLine), z=-5)
        colours = group_colours()
        pens = [pg.mkPen(colours[0], width=1, style=Qt.PenStyle.DashLine)]  # rapids
        pens += [pg.mkPen(colour, width=1) for colour in colours[1:]]
        self.group_pens = pens
        self.group_data = [(np.zeros(0), np.zeros(0)) for _ in pens]  # what the path layer shows
        self.group_samples = [pg.PlotDataItem(pen=pen) for pen in pens]  # legend samples only
        self.done_pen = pg.mkPen(DONE_COLOUR, width=1)
        self.path_layer = self._layer(z=5)
        self.done_layer = self._layer(z=20)
        self.highlight_item = self._curve(pg.mkPen(HIGHLIGHT_COLOUR, width=3), z=30)
        self.marker = pg.ScatterPlotItem(size=14, symbol="+", pen=pg.mkPen(MARKER_COLOUR, width=2))
        self.marker.setZValue(40)
        self.plot.addItem(self.marker)

    def _layer(self, z: int) -> PictureLayer:
        layer = PictureLayer(self.view)
        layer.setZValue(z)
        self.plot.addItem(layer)
        return layer

    def _curve(self, pen: QPen, z: int) -> pg.PlotCurveItem:
        item = pg.PlotCurveItem(pen=pen, connect="pairs", skipFiniteCheck=True)
        item.setZValue(z)
        self.plot.addItem(item)
        return item

    # -- the program ----------------------------------------------------------------

    def set_travel(self, travel, offset) -> None:
        """The machine's travel rectangle, drawn in work coordinates (shifted by -offset)."""
        x0, y0 = -offset[0], -offset[1]
        x1, y1 = x0 + travel[0], y0 + travel[1]
        self.travel_item.setData(*rectangle_pairs(x0, y0, x1, y1))

    def show_program(self, toolpath, tolerance: float = 0.01) -> None:
        self.show_model(PreviewModel(toolpath, tolerance) if toolpath is not None else None)

    def show_model(self, model: PreviewModel | None) -> None:
        self.model = model
        self._done_move = -1
        self.highlight_item.setData([], [])
        self._update_legend()
        if model is None or model.empty:
            self.bounds_item.setData([], [])
            self._refill_now()
            return
        xmin, xmax, ymin, ymax = model.bounds()
        self.bounds_item.setData(*rectangle_pairs(xmin, ymin, xmax, ymax))
        self.fit()
        self._refill_now()
        self.plot.viewport().repaint()  # on the screen now, not after whatever else the caller does

    def retranslate_ui(self) -> None:
        self.plot.setToolTip(self.tr("wheel: zoom · drag: pan · Ctrl+F: fit · Ctrl+G: grid"))
        self._update_legend()
        refresh_ticks(self.plot.getPlotItem())

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def replace_model(self, model: PreviewModel) -> None:
        """The same program drawn from ``model`` (finer): the view and the finished part stay."""
        self.model = model
        self._update_legend()
        self._refill_now()

    def _update_legend(self) -> None:
        self.legend.clear()
        for group, label in legend_entries(self.model):
            self.legend.addItem(self.group_samples[group], label)

    def fit(self) -> None:
        """Zoom to the program (or to the travel when no program is open)."""
        if self.model is None or self.model.empty:
            self.view.autoRange(items=[self.travel_item])
            return
        x_range, y_range = self.model.fitted_range()
        self.view.setRange(xRange=x_range, yRange=y_range, padding=0)

    def set_grid(self, on: bool) -> None:
        """Grid lines (off by default: they cost a third of a frame on a slow machine)."""
        self.grid = on
        self.plot.showGrid(x=on, y=on, alpha=0.25 if on else 0)

    def zoom(self, factor: float) -> None:
        self.view.scaleBy((1 / factor, 1 / factor))

    # -- live -----------------------------------------------------------------------

    def set_tool(self, x: float, y: float) -> None:
        self.marker.setData([x], [y])

    def set_done(self, seq: int) -> None:
        """Recolour the path up to device line ``seq`` as finished."""
        if self.model is None:
            return
        move = self.model.move_of_device_line(seq)
        if move == self._done_move:
            return
        before, self._done_move = self._done_move, move
        if move < before:  # a new run: start the picture again
            self._refill_done(*self._view_and_pixel())
        else:  # only what was finished since the last frame is painted
            self.done_layer.add(self.done_pen, *self.model.recent_segments(before, move))

    def highlight_move(self, index: int | None) -> None:
        """Draw one move thick and centre the view on it."""
        if self.model is None or index is None:
            self.highlight_item.setData([], [])
            return
        pts = self.model.geometry.move_vertices(index)
        self.highlight_item.setData(pts[:, 0], pts[:, 1])
        if len(pts):
            cx, cy = pts[:, 0].mean(), pts[:, 1].mean()
            half = max(np.ptp(pts[:, 0]), np.ptp(pts[:, 1]), 5.0)
            self.view.setRange(xRange=(cx - half, cx + half), yRange=(cy - half, cy + half), padding=0)

    # -- drawing --------------------------------------------------------------------

    def _view_and_pixel(self):
        (x0, x1), (y0, y1) = self.view.viewRange()
        px, py = self.view.viewPixelSize()
        return (x0, x1, y0, y1), max(px, py)

    def _refill_now(self) -> None:
        self._refill.stop()  # a refill asked for before this one (by a fit, say) is this one
        view, pixel = self._view_and_pixel()
        if self.model is None or self.model.empty:
            self.group_data = [(np.zeros(0), np.zeros(0)) for _ in self.group_pens]
            self.done_layer.clear()
        else:
            self.group_data = self.model.frame(view, pixel, wait=False)  # never build here
            self._refill_done(view, pixel)
            if not self.model.levels_built:  # drawn from the nearest level built so far
                self._levels_poll.start()
        pairs = zip(self.group_pens, self.group_data, strict=True)
        self.path_layer.reset([(pen, x, y) for pen, (x, y) in pairs])
        self.frame_drawn.emit()

    def _refill_done(self, view, pixel) -> None:
        """Paint the whole finished part again (the view changed, or a new run began)."""
        done = self.model.done_frame(view, pixel, self._done_move, wait=False)
        self.done_layer.reset([(self.done_pen, *done)])

    def plotted_bounds(self) -> tuple[float, float, float, float]:
        """Extents of the toolpath as drawn now (for tests)."""
        xs, ys = [], []
        for x, y in self.group_data:
            if len(x) and np.isfinite(x).any():
                xs += [np.nanmin(x), np.nanmax(x)]
                ys += [np.nanmin(y), np.nanmax(y)]
        return (min(xs), max(xs), min(ys), max(ys)) if xs else (0.0, 0.0, 0.0, 0.0)
