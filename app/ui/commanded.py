"""The commanded position for the diagnostics view (no Qt).

The status frame carries the measured position only, so the commanded one is taken
from the program: the point of the path being executed (the moves of the current and
the previous device line) nearest to the measured position. Their difference is the
tool's deviation from the programmed path per axis, which is what a PID tuner watches.
"""

from __future__ import annotations

import numpy as np


def nearest_on_polyline(points: np.ndarray, p: np.ndarray) -> np.ndarray:
    """The point of the polyline ``points`` (k, 3) nearest to ``p``."""
    if len(points) == 1:
        return points[0]
    a, b = points[:-1], points[1:]
    ab = b - a
    denom = np.einsum("ij,ij->i", ab, ab)
    t = np.einsum("ij,ij->i", p - a, ab) / np.where(denom > 0, denom, 1.0)
    q = a + np.clip(t, 0.0, 1.0)[:, None] * ab
    return q[np.argmin(np.einsum("ij,ij->i", q - p, q - p))]


def commanded_position(model, executing_seq: int, measured) -> np.ndarray:
    """Nearest point on the moves of device lines ``executing_seq - 1 .. executing_seq``."""
    p = np.asarray(measured, dtype=float)
    if model is None or model.empty:
        return p
    geometry = model.geometry
    last = model.move_of_device_line(executing_seq)
    first = model.move_of_device_line(executing_seq - 1)
    if last < 0:
        return p
    lo = int(np.searchsorted(geometry.move[1:], max(first, 0), "left"))
    hi = int(np.searchsorted(geometry.move[1:], last, "right")) + 1
    points = geometry.points[lo:hi]
    return nearest_on_polyline(points, p) if len(points) else p


class SpindleTrack:
    """The commanded spindle speed along a job's device lines. ``at(seq)`` is the speed in
    force while line ``seq`` runs; the lines are folded in as the job goes (a job only
    moves forward), so no pass over a big program happens at its start. ``lines`` may be
    a function giving them, called at the first question (a program renders its device
    lines on first use: by then the job's start has done it)."""

    def __init__(self, lines, start_rpm: float = 0.0):
        self._lines, self.start_rpm = lines, start_rpm
        self._restart()

    @property
    def lines(self):
        if callable(self._lines):
            self._lines = self._lines()
        return self._lines

    def _restart(self) -> None:
        from app.comm.modal import ModalState

        self.state = ModalState(spindle_rpm=self.start_rpm or None)
        self.folded = 0  # lines[:folded] are in ``state``

    def at(self, seq: int) -> float:
        if seq + 1 < self.folded:
            self._restart()  # asked about an earlier line: fold again from the start
        lines, state = self.lines, self.state
        for index in range(self.folded, min(seq + 1, len(lines))):
            line = lines[index]
            if line.startswith(("M", "m")):  # the dialect's spindle words ride on M lines only
                state.apply(line)
        self.folded = max(self.folded, min(seq + 1, len(lines)))
        return float(state.spindle_rpm or 0.0)
