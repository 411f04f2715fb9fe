"""Steady axes for live plots: a Y range that moves in whole steps, and cached axes.

Re-laying out an axis (its tick text) is most of the cost of a live plot's frame, so
the Y range changes only when the data leaves it, in steps of 1, 2 or 5 x 10^k, and
each axis is kept as a pixmap that is redrawn only when its range changes.
"""

from __future__ import annotations

import math

import numpy as np
from PySide6.QtWidgets import QGraphicsItem


def nice_step(span: float) -> float:
    """The smallest of 1, 2, 5 x 10^k that is at least a quarter of ``span``."""
    target = max(span, 1e-9) / 4
    power = 10.0 ** math.floor(math.log10(target))
    return next(m * power for m in (1, 2, 5, 10) if m * power >= target)


def stepped(lo: float, hi: float, min_span: float, step: float | None = None) -> tuple[float, float]:
    """(lo, hi) widened to at least ``min_span`` and rounded outwards to whole steps."""
    if hi - lo < min_span:
        middle = (lo + hi) / 2
        lo, hi = middle - min_span / 2, middle + min_span / 2
    step = step or nice_step(hi - lo)
    return math.floor(lo / step) * step, math.ceil(hi / step) * step


class SteadyYRange:
    """Sets a plot's Y range from its data only when the stepped range changes."""

    def __init__(self, plot_item, min_span: float, step: float | None = None, margin: float = 0.0):
        self.plot_item, self.min_span, self.step, self.margin = plot_item, min_span, step, margin
        self.range: tuple[float, float] | None = None
        plot_item.disableAutoRange()
        cache_axes(plot_item)

    def fit(self, values: np.ndarray) -> None:
        finite = values[np.isfinite(values)]
        if not len(finite):
            return
        lo, hi = stepped(float(finite.min()), float(finite.max()), self.min_span, self.step)
        if self.range is None or lo < self.range[0] or hi > self.range[1] or _shrunk(lo, hi, self.range):
            self.range = (lo, hi)
            self.plot_item.setYRange(lo - self.margin, hi + self.margin, padding=0)


def _shrunk(lo: float, hi: float, current: tuple[float, float]) -> bool:
    """The data now fills less than a quarter of the range: zoom back in."""
    return (hi - lo) * 4 < current[1] - current[0]


def cache_axes(plot_item) -> None:
    """Draw each axis (tick text and grid) into a pixmap, redrawn when its range changes."""
    for side in ("left", "bottom"):
        plot_item.getAxis(side).setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
