"""Job progress (no Qt): percent by executed line, elapsed time, and the remaining
time from the program's estimate corrected by the rate measured so far. Time spent
held (a program stop waiting for the operator, a feed hold) is not motion: it counts
in the elapsed time but not in the measured rate (``hold(now)``/``release(now)``).
``finish(now, completed)`` stops the clock; a run that did not complete shows no
remaining time (a stale figure would mislead)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ProgressView:
    done: int  # device lines finished
    total: int
    elapsed: float
    remaining: float | None

    @property
    def percent(self) -> float:
        return 100.0 * self.done / self.total if self.total else 100.0


def line_times(toolpath, device_lines: int) -> np.ndarray:
    """Cumulative estimated seconds at the end of every device line."""
    per_line = np.zeros(max(device_lines, 1))
    times = getattr(toolpath, "time", None)
    index = getattr(toolpath, "device_index", None)
    if times is not None and index is not None and len(times):
        np.add.at(per_line, np.clip(np.asarray(index), 0, len(per_line) - 1), np.asarray(times, dtype=float))
    return np.cumsum(per_line)


class ProgressTracker:
    def __init__(self, cumulative: np.ndarray, total: int, started: float, first: int = 0):
        self.cumulative = cumulative
        self.total = total
        self.started = started
        self.first = first  # lines already done when this run started (resume)
        self.done = first
        self.held_s = 0.0
        self._held_since: float | None = None
        self.ended: float | None = None  # when the run ended (the clock stops there)
        self.completed = False

    def finish(self, now: float, completed: bool) -> None:
        """The run ended: the elapsed time stops; an unfinished run has no remaining time."""
        if self.ended is None:
            self.release(now)
            self.ended, self.completed = now, completed

    def hold(self, now: float) -> None:
        if self._held_since is None:
            self._held_since = now

    def release(self, now: float) -> None:
        if self._held_since is not None:
            self.held_s += max(now - self._held_since, 0.0)
            self._held_since = None

    def moving(self, now: float) -> float:
        """Seconds of the run not spent held."""
        held = self.held_s + (max(now - self._held_since, 0.0) if self._held_since is not None else 0.0)
        return max(now - self.started - held, 0.0)

    def update(self, done_lines: int) -> None:
        self.done = max(self.done, min(done_lines, self.total))

    def view(self, now: float) -> ProgressView:
        if self.ended is not None:
            now = self.ended
        elapsed = max(now - self.started, 0.0)
        if self.ended is not None and not self.completed:
            return ProgressView(self.done, self.total, elapsed, None)  # stopped: nothing remains to wait for
        return ProgressView(self.done, self.total, elapsed, self._remaining(self.moving(now)))

    def _remaining(self, elapsed: float) -> float | None:
        if self.total == 0 or self.done >= self.total:
            return 0.0
        total_est = float(self.cumulative[self.total - 1]) if len(self.cumulative) >= self.total else 0.0
        before = float(self.cumulative[self.first - 1]) if self.first > 0 else 0.0
        done_est = (float(self.cumulative[self.done - 1]) if self.done > 0 else 0.0) - before
        left_est = total_est - before - done_est
        if done_est > 1.0 and elapsed > 2.0:
            return left_est * elapsed / done_est
        return left_est if total_est > 0 else None
