"""The path the machine measured during a job, and how far it strayed (no Qt).

Each status frame of a job gives the measured position (the encoders') and the
commanded one the diagnostics plot compares it with (``app.ui.commanded``: the point
of the programmed path being executed nearest to it). ``MeasuredPath.append`` keeps
both as rows in arrays that grow by doubling (appending is O(1) amortised, and the
GPU copy grows the same way, so only the new rows are uploaded); the deviation of a
row is the distance between the two. A row taken during a rapid has no deviation
(stored as -1, drawn grey): the program's rapids start where the preview assumes the
tool is, the machine's where it really is, and the tolerance is the cuts'.
``largest()`` says where the deviation was greatest. ``deviation_colour`` maps a
deviation to the colour the view draws it in: cyan at 0, yellow at half the
tolerance, red from the tolerance up.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

TOLERANCE_MM = 0.1  # the machine holds the tool within this of the path (DESIGN.md)
_START_ROWS = 1024
RAMP = np.array([[0.0, 0.9, 1.0], [1.0, 0.88, 0.2], [1.0, 0.2, 0.2]], np.float32)  # 0, tol/2, tol
NO_DEVIATION = -1.0


@dataclass(frozen=True)
class Deviation:
    index: int  # row of the measured path
    distance: float  # mm
    measured: np.ndarray  # (3,) mm, work coordinates
    commanded: np.ndarray  # (3,)


class MeasuredPath:
    def __init__(self):
        self._rows = np.zeros((_START_ROWS, 4), np.float32)  # x, y, z, deviation
        self._commanded = np.zeros((_START_ROWS, 3), np.float64)
        self.count = 0
        self.version = 0  # bumped on every change (clear restarts the GPU copy)

    def __len__(self) -> int:
        return self.count

    def clear(self) -> None:
        self.count = 0
        self.version += 1

    def append(self, measured, commanded, rapid: bool = False) -> None:
        """One status of a job: where the machine was and where the program meant it to be
        (``rapid``: during a rapid move, when the deviation means nothing)."""
        if self.count == len(self._rows):
            self._rows = _grown(self._rows)
            self._commanded = _grown(self._commanded)
        m = np.asarray(measured, float)
        c = np.asarray(commanded, float)
        row = self._rows[self.count]
        row[:3] = m
        row[3] = NO_DEVIATION if rapid else float(np.sqrt(np.sum((m - c) ** 2)))
        self._commanded[self.count] = c
        self.count += 1

    def rows(self) -> np.ndarray:
        """(count, 4) float32 x, y, z, deviation (a view: the GPU's vertex format)."""
        return self._rows[: self.count]

    @property
    def capacity(self) -> int:
        return len(self._rows)

    def largest(self) -> Deviation | None:
        """Where the measured path was farthest from the programmed one (first such row)."""
        deviation = self._rows[: self.count, 3]
        if not self.count or deviation.max() < 0:
            return None
        index = int(np.argmax(deviation))
        row = self._rows[index]
        return Deviation(index, float(row[3]), row[:3].astype(float), self._commanded[index].copy())


def _grown(array: np.ndarray) -> np.ndarray:
    bigger = np.zeros((len(array) * 2, array.shape[1]), array.dtype)
    bigger[: len(array)] = array
    return bigger


def deviation_colour(distance, tolerance: float = TOLERANCE_MM) -> np.ndarray:
    """RGB (0..1) for each deviation: the view's shader computes the same ramp."""
    t = np.clip(np.asarray(distance, np.float32) / np.float32(tolerance), 0.0, 1.0) * 2
    low = np.minimum(t, 1.0)[..., None]
    high = np.maximum(t - 1.0, 0.0)[..., None]
    return RAMP[0] + (RAMP[1] - RAMP[0]) * low + (RAMP[2] - RAMP[1]) * high
