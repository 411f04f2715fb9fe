"""Position history for the live plots: a preallocated ring buffer (no Qt).

Rows are (t, measured x, y, z, commanded x, y, z). Every row is written twice, at
``i`` and ``i + capacity``, so the newest ``n`` rows are always one contiguous slice
and a redraw never copies or reorders.
"""

from __future__ import annotations

import numpy as np

T, MEASURED, COMMANDED = 0, slice(1, 4), slice(4, 7)
COLUMNS = 7


class PositionHistory:
    def __init__(self, capacity: int = 12_000):
        self.capacity = capacity
        self._data = np.full((2 * capacity, COLUMNS), np.nan)
        self._next = 0
        self._count = 0
        self.version = 0  # bumped on every append, so a redraw can tell it is stale

    def __len__(self) -> int:
        return self._count

    def append(self, t: float, measured, commanded=None) -> None:
        row = self._data[self._next]
        row[0] = t
        row[MEASURED] = measured
        row[COMMANDED] = measured if commanded is None else commanded
        self._data[self._next + self.capacity] = row
        self._next = (self._next + 1) % self.capacity
        self._count = min(self._count + 1, self.capacity)
        self.version += 1

    def break_line(self) -> None:
        """A gap (the link was lost): a row of no position at the newest time, so the plots
        draw no line across the time the machine was not heard (their curves skip NaN)."""
        latest = self.latest()
        if latest is not None and np.isfinite(latest[MEASURED]).any():
            self.append(float(latest[T]), (np.nan, np.nan, np.nan))

    def clear(self) -> None:
        self._count = 0
        self._next = 0
        self.version += 1

    def rows(self) -> np.ndarray:
        """The stored rows, oldest first (a view, not a copy)."""
        end = self._next + self.capacity
        return self._data[end - self._count : end]

    def window(self, seconds: float) -> np.ndarray:
        """The rows of the last ``seconds`` before the newest row."""
        rows = self.rows()
        if not len(rows):
            return rows
        start = np.searchsorted(rows[:, T], rows[-1, T] - seconds, "left")
        return rows[start:]

    def latest(self) -> np.ndarray | None:
        return self.rows()[-1] if self._count else None
