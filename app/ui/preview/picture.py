"""A layer of the preview painted once into an image the size of the view.

The preview's path (tens of thousands of segments even after level of detail) and its
finished part change rarely compared with how often the view repaints: the tool
marker moves 30 times a second. Drawn as curve items, every repaint under the marker
drew the curves again (Qt's item cache holds only a few view-sized pixmaps, and there
were ten). A ``PictureLayer`` holds its segments painted in one image instead:
``reset(parts)`` paints it anew for the current view (after a pan, a zoom or a resize,
when it is stale anyway), ``add(pen, x, y)`` paints only new segments onto it (the
finished part grows a little each frame) and repaints only where they are, and
painting the item is a blit of the exposed part. Segments are ``(x, y)`` point pairs
in data coordinates, as ``PreviewModel`` gives them.
"""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt, Signal
from PySide6.QtGui import QImage, QPainter, QPen, QTransform
from PySide6.QtWidgets import QGraphicsObject


class PictureLayer(QGraphicsObject):
    """An item in the view's data coordinates that shows an image of its segments."""

    painted = Signal()  # the image was put on the screen (for the benchmark and tests)

    def __init__(self, view: pg.ViewBox):
        super().__init__()
        self.view = view
        self.image = QImage()
        self._rect = QRectF()  # the data rectangle the image covers
        self._to_image = QTransform()  # data -> image pixels
        self.segments = 0  # painted since the last reset (for tests and the benchmark)
        self.setFlag(QGraphicsObject.GraphicsItemFlag.ItemUsesExtendedStyleOption)  # exposedRect

    def boundingRect(self) -> QRectF:
        return QRectF(self._rect)

    def paint(self, painter: QPainter, option, _widget=None) -> None:
        if self.image.isNull():
            return
        to_device = painter.transform()
        target = to_device.mapRect(self._rect)
        exposed = option.exposedRect.intersected(self._rect)  # only what Qt repaints
        source = self._to_image.mapRect(exposed) if not exposed.isEmpty() else QRectF(self.image.rect())
        painter.save()
        painter.resetTransform()
        if exposed.isEmpty():
            painter.drawImage(target, self.image)
        else:
            painter.drawImage(to_device.mapRect(exposed), self.image, source)
        painter.restore()
        self.painted.emit()

    def reset(self, parts: list[tuple[QPen, np.ndarray, np.ndarray]]) -> None:
        """Paint the image again for the current view with these (pen, x, y) parts alone."""
        self.prepareGeometryChange()
        (x0, x1), (y0, y1) = self.view.viewRange()
        self._rect = QRectF(QPointF(x0, y0), QPointF(x1, y1)).normalized()
        ratio = self._pixel_ratio()
        size = self.view.size()
        width, height = max(1, round(size.width() * ratio)), max(1, round(size.height() * ratio))
        self.image = QImage(width, height, QImage.Format.Format_ARGB32_Premultiplied)
        self.image.fill(Qt.GlobalColor.transparent)
        # data -> image: x0..x1 onto 0..width, y1..y0 onto 0..height (y grows downwards)
        sx, sy = width / max(x1 - x0, 1e-12), height / max(y1 - y0, 1e-12)
        self._to_image = QTransform(sx, 0, 0, -sy, -x0 * sx, y1 * sy)
        self.segments = 0
        for pen, x, y in parts:
            self._paint(pen, x, y)
        self.update()

    def add(self, pen: QPen, x: np.ndarray, y: np.ndarray) -> None:
        """Paint these segments onto the image (the view has not changed since ``reset``)."""
        if self._paint(pen, x, y):
            self.update(self._dirty_rect(x, y))  # only where the new segments are

    def clear(self) -> None:
        self.reset([])

    def _paint(self, pen: QPen, x: np.ndarray, y: np.ndarray) -> bool:
        if len(x) < 2 or self.image.isNull():
            return False
        cosmetic = QPen(pen)
        cosmetic.setCosmetic(True)  # one pixel wide whatever the zoom
        painter = QPainter(self.image)
        painter.setTransform(self._to_image)
        painter.setPen(cosmetic)
        painter.drawPath(pg.arrayToQPath(np.asarray(x, float), np.asarray(y, float), connect="pairs"))
        painter.end()
        self.segments += len(x) // 2
        return True

    def _dirty_rect(self, x: np.ndarray, y: np.ndarray) -> QRectF:
        """Data rectangle of the segments, widened by two image pixels for the pen."""
        pad_x = 2 / abs(self._to_image.m11())
        pad_y = 2 / abs(self._to_image.m22())
        x0, x1, y0, y1 = float(np.min(x)), float(np.max(x)), float(np.min(y)), float(np.max(y))
        return QRectF(x0 - pad_x, y0 - pad_y, x1 - x0 + 2 * pad_x, y1 - y0 + 2 * pad_y)

    def _pixel_ratio(self) -> float:
        views = self.scene().views() if self.scene() is not None else []
        return views[0].devicePixelRatioF() if views else 1.0
