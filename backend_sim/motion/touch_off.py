"""Touch-off at a program stop (docs/protocol.md, "Program stops and tool changes").

While the job waits at a stop (``waiting``), a jog may run: the job's queue (the wait
first, then the stop's own moves and any line behind it) is *parked*, the planner runs
the jog (state ``JOG``), and when the jog ends the queue comes back, the wait at its
head (state ``RUN``, still waiting). ``shift_stop(delta)`` (a new work zero at the stop)
moves the held position and every queued move by ``delta`` machine mm, so they keep
their work coordinates. ``RESUME`` (``return_moves``) first brings the tool back to the
held position: Z up to the top of the travel, X Y, Z down (never above the top).

A mixin of ``MotionController``: it relies on ``job``, ``planner``, ``state``,
``waiting``, ``commanded_mm``, ``profile`` and ``_set_state``.
"""

from __future__ import annotations

from dataclasses import replace

from backend_sim.motion.dialect import Move
from backend_sim.motion.events import Stopped

_EPS = 1e-6


class TouchOff:
    parked: list[Move] | None = None

    def at_stop(self) -> bool:
        """Whether the job holds at a program stop, at rest, where a touch-off may jog."""
        return (self.waiting is not None and not self.stopping and self.spin_up is None
                and (self.state == "JOG" and self.parked is not None
                     or self.state in ("RUN", "HOLD") and self.job.at_rest()))

    def _park(self) -> None:
        """A touch-off jog starts: the job's queue waits aside, the planner is free."""
        if self.parked is None:
            self.parked = self.job.queued_moves()
            self.job.reset_position(self.commanded_mm)
            self.planner.reset_position(self.commanded_mm)

    def end_jog(self) -> None:
        """End a jog: a touch-off jog decelerates and gives the job back (``_unpark``);
        any other jog stops as ``stop`` stops it."""
        if self.parked is not None and self.state == "JOG":
            self.planner.hold()
            self._update_watch()
        elif self.state == "JOG":
            self.stop()

    def _unpark(self) -> None:
        """The touch-off jog is over: the job's queue comes back, still waiting."""
        moves, self.parked = self.parked, None
        cut_short = self.planner.holding
        self._requeue(moves)
        if self._cover:
            self.job.hold()
        self._set_state("HOLD" if self._cover else "RUN")
        if cut_short:
            self._events.append(Stopped())  # a PAUSE that cancelled the jog is answered

    def _requeue(self, moves: list[Move]) -> None:
        """Queue ``moves`` again from where the tool stands (geometry recomputed)."""
        here = self.commanded_mm
        self.job.reset_position(here)
        self.planner.reset_position(here)
        for move in moves:
            self.job.add(move)

    def shift_stop(self, delta) -> None:
        """A new work zero at the stop: the held position and the queued moves keep
        their work coordinates (each moves by ``delta`` machine mm)."""
        if self.waiting is None:
            return
        queued = self.parked if self.parked is not None else self.job.queued_moves()
        shifted = [_shifted(m, delta) for m in queued]
        wait = next((m for m in shifted if m.kind == "wait"), None)
        self.waiting = wait if wait is not None else _shifted(self.waiting, delta)
        if self.parked is not None:
            self.parked = shifted
        else:
            self._requeue(shifted)

    def return_moves(self) -> None:
        """``RESUME`` at a stop: drop the wait and queue the way back to the held
        position ahead of the rest (nothing when the tool stands there)."""
        held = self.waiting.target
        top = self.profile.travel.limits()[2][1]
        target = (held[0], held[1], min(held[2], top))
        here = self.commanded_mm
        rest = [m for m in self.job.queued_moves() if m.kind != "wait"]
        if max(abs(a - b) for a, b in zip(here, target, strict=True)) < _EPS:
            return
        way, z = [], here[2]
        if z < top - _EPS:
            z = top
            way.append((here[0], here[1], top))
        if abs(here[0] - target[0]) > _EPS or abs(here[1] - target[1]) > _EPS:
            way.append((target[0], target[1], z))
        if abs(z - target[2]) > _EPS:
            way.append(target)
        back = [Move(-1, "rapid", point, source="return") for point in way]
        self._requeue(back + [_clamped(m, top) for m in rest])


def _shifted(move: Move, delta) -> Move:
    target = tuple(v + d for v, d in zip(move.target, delta, strict=True))
    center = None if move.center is None else (move.center[0] + delta[0], move.center[1] + delta[1])
    return replace(move, target=target, center=center)


def _clamped(move: Move, top: float) -> Move:
    """The stop's own way down (``source`` ``return``) never above the top of the travel."""
    if move.source != "return" or move.target[2] <= top:
        return move
    return replace(move, target=(move.target[0], move.target[1], top))
