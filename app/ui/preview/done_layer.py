"""The finished part of the path as a picture that only ever grows while a job runs.

Recolouring the finished part by redrawing it costs time in proportion to all that is
finished, which for a long job is a stall of tens of milliseconds. ``DoneLayer`` keeps
the finished part painted in an image the size of the view instead: ``add(x, y)``
paints only the new segments onto it (a few per frame while a job runs), ``reset(x, y)``
paints everything again (after a pan, a zoom or a resize, when the image is stale
anyway), and painting the item is one blit. Segments are ``(x, y)`` point pairs in
data coordinates, as ``PreviewModel`` gives them.
"""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QPointF, QRectF, Qt
from PySide6.QtGui import QImage, QPainter, QPen, QTransform
from PySide6.QtWidgets import QGraphicsObject


class DoneLayer(QGraphicsObject):
    """An item in the view's data coordinates that shows an image of the finished part."""

    def __init__(self, view: pg.ViewBox, pen: QPen):
        super().__init__()
        self.view = view
        self.pen = QPen(pen)
        self.pen.setCosmetic(True)
        self.image = QImage()
        self._rect = QRectF()  # the data rectangle the image covers
        self._to_image = QTransform()  # data -> image pixels
        self.segments = 0  # painted since the last reset (for tests and the benchmark)

    def boundingRect(self) -> QRectF:
        return QRectF(self._rect)

    def paint(self, painter: QPainter, *_args) -> None:
        if self.image.isNull():
            return
        target = painter.transform().mapRect(self._rect)
        painter.save()
        painter.resetTransform()
        painter.drawImage(target, self.image)
        painter.restore()

    def reset(self, x: np.ndarray, y: np.ndarray) -> None:
        """Paint the image again for the current view with these segments alone."""
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
        self.add(x, y)

    def add(self, x: np.ndarray, y: np.ndarray) -> None:
        """Paint these segments onto the image (the view has not changed since ``reset``)."""
        if len(x) < 2 or self.image.isNull():
            return
        painter = QPainter(self.image)
        painter.setTransform(self._to_image)
        painter.setPen(self.pen)
        painter.drawPath(pg.arrayToQPath(np.asarray(x, float), np.asarray(y, float), connect="pairs"))
        painter.end()
        self.segments += len(x) // 2
        self.update()

    def clear(self) -> None:
        self.reset(np.zeros(0), np.zeros(0))

    def _pixel_ratio(self) -> float:
        views = self.scene().views() if self.scene() is not None else []
        return views[0].devicePixelRatioF() if views else 1.0
