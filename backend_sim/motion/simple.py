"""The original firmware's method ("simple" mode), kept so the planner can be compared.

Contract: the same as ``Planner`` (``add``, ``step``, ``hold``, ``resume``, ``flush``,
``idle``...). Each line, and each chord of an arc (sagitta <= arc_tolerance_mm), is
stepped from standstill at the programmed feed with Bresenham's algorithm in whole
encoder counts (no acceleration), then the setpoint waits until every axis is within
one count of it (or 300 ms) before the next segment starts. A hold freezes the stepping
where it is (on the path).
"""

from __future__ import annotations

import math
from collections import deque

from backend_sim.motion.dialect import Move
from backend_sim.motion.geometry import Segment
from backend_sim.motion.hold import FeedHold
from backend_sim.motion.planner import barrier_done

_SETTLE_MAX_MS = 300


class SimpleInterpolator(FeedHold):
    """Bresenham stepping of whole counts, stop at every segment end."""

    def __init__(self, profile, ctx, events: list, position=(0.0, 0.0, 0.0)):
        mo, ax = profile.motion, profile.axis
        self.cpm = ax.counts_per_rev / ax.lead_mm
        self.rapid = mo.rapid_mm_min / 60.0
        self.max_feed = mo.max_feed_mm_min / 60.0
        self.tolerance = mo.arc_tolerance_mm
        self.ctx, self.events = ctx, events
        self.moves: deque[Move] = deque()
        self.holding = False
        self.reset_position(position)

    def reset_position(self, position) -> None:
        self.moves.clear()
        self.pos = self.tail = tuple(float(v) for v in position)
        self.counts = [round(v * self.cpm) for v in self.pos]
        self.chords: list = []
        self.current: Move | None = None
        self.line = None  # (deltas, signs, dominant, rate, errors) of the chord being stepped
        self.done = self.progress = self.wait_ms = 0
        self.held_flag = True
        self.holding = False

    def __len__(self) -> int:
        return len(self.moves) + (self.current is not None)

    def queued_moves(self) -> list[Move]:
        """The moves not yet finished, the one under way first."""
        return ([self.current] if self.current is not None else []) + list(self.moves)

    def add(self, move: Move) -> None:
        self.moves.append(move)
        if move.moves_axes:
            self.tail = move.target

    def at_rest(self) -> bool:
        return self.line is None or self.holding

    def idle(self) -> bool:
        return self.current is None and not self.moves

    def just_held(self) -> bool:
        if self.holding and not self.held_flag:
            self.held_flag = True
            return True
        return False

    def step(self):
        if self.current is None and not self._next_move():
            return self.pos
        if self.holding:
            return self.pos
        move = self.current
        if not move.moves_axes:
            self.wait_ms += 1
            if barrier_done(self.ctx, move, self.wait_ms):
                self._finish()
            return self.pos
        if self.line is not None:
            self._bresenham()
        elif self._settled() and not self._next_chord():
            self._finish()
        return self.pos

    def _next_move(self) -> bool:
        if not self.moves:
            return False
        move = self.current = self.moves.popleft()
        self.wait_ms = 0
        if move.moves_axes:
            start = tuple(c / self.cpm for c in self.counts)
            self.chords = Segment.from_move(start, move).chords(self.tolerance)[1:]
        return True

    def _settled(self) -> bool:
        self.wait_ms += 1
        return self.wait_ms > _SETTLE_MAX_MS or self.ctx.settled()

    def _next_chord(self) -> bool:
        if not self.chords:
            return False
        target = [round(v * self.cpm) for v in self.chords.pop(0)]
        deltas = [t - c for t, c in zip(target, self.counts, strict=True)]
        dom = max(abs(d) for d in deltas)
        self.wait_ms = 0
        if dom == 0:
            return True
        move = self.current
        speed = self.rapid if move.kind == "rapid" else min(move.feed / 60.0, self.max_feed)
        length = math.sqrt(sum(d * d for d in deltas))  # counts
        rate = speed * self.cpm * dom / length / 1000.0  # dominant steps per ms
        signs = [1 if d > 0 else -1 for d in deltas]
        self.line = ([abs(d) for d in deltas], signs, dom, rate, [0, 0, 0])
        self.done, self.progress = 0, 0.0
        return True

    def _bresenham(self) -> None:
        deltas, signs, dom, rate, err = self.line
        self.progress += rate
        goal = min(dom, int(self.progress))
        counts = self.counts
        while self.done < goal:
            self.done += 1
            for k in range(3):
                err[k] += deltas[k]
                if 2 * err[k] >= dom:
                    err[k] -= dom
                    counts[k] += signs[k]
        cpm = self.cpm
        self.pos = (counts[0] / cpm, counts[1] / cpm, counts[2] / cpm)
        if self.done >= dom:
            self.line = None
            self.wait_ms = 0

    def _finish(self) -> None:
        move, self.current = self.current, None
        if move.seq >= 0:
            self.ctx.finished(move)
