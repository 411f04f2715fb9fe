"""The CNC MCU's continuous jog (docs/protocol.md, "Continuous jog (hold-to-jog)").

``R JOG <dirs> <feed>`` starts a jog along the unit vector of ``dirs`` to where that
line leaves the soft limits (homed) or one travel length further (unhomed), or keeps
the running one alive; ``R JOGEND`` ends it. ``ContinuousJog.tick`` (called whenever the
CNC MCU runs) is the dead man: no keep-alive for ``DEAD_MAN_MS`` and the jog ends by
itself with ``L jog stopped: no keep-alive ...``; a jog that ran to the travel's edge
reports ``L jog stopped at the soft limit ...``. Anything else that ends it (a hold, a
stop, the cover, a lost link) just ends it: ``tick`` sees the machine back at rest.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.comm.frame import Log
from backend_sim.motion.events import MotionError

DEAD_MAN_MS = 250
AXES = "XYZ"


@dataclass
class _Running:
    dirs: str
    deadline_ms: int
    edge: str  # what the target is clipped by: "X+ 150" (homed), "" when unhomed


def unit_vector(dirs: str) -> tuple[float, float, float]:
    """``"X+Y-"`` -> (0.707, -0.707, 0): the direction of the jog, length 1."""
    vec = [0.0, 0.0, 0.0]
    for k in range(0, len(dirs), 2):
        vec[AXES.index(dirs[k])] = 1.0 if dirs[k + 1] == "+" else -1.0
    norm = math.sqrt(sum(v * v for v in vec))
    return (vec[0] / norm, vec[1] / norm, vec[2] / norm)


def run_to_edge(start, unit, limits) -> tuple[float, str]:
    """How far the line from ``start`` along ``unit`` stays inside ``limits``, and the
    limit that stops it first (``"X+ 150"``)."""
    best, edge = math.inf, ""
    for k, axis in enumerate(AXES):
        if unit[k] == 0.0:
            continue
        low, high = limits[k]
        bound = high if unit[k] > 0 else low
        room = max(0.0, (bound - start[k]) / unit[k])
        if room < best:
            best, edge = room, f"{axis}{'+' if unit[k] > 0 else '-'} {bound:g}"
    return best, edge


class ContinuousJog:
    """At most one continuous jog of one CNC MCU, with its dead man."""

    def __init__(self, mcu) -> None:
        self.mcu = mcu
        self.running: _Running | None = None

    def keep(self, dirs: str, feed: float) -> None:
        """``R JOG``: start a jog, keep the running one alive, or end it for a new
        direction (MotionError BUSY; the next keep-alive starts the new one)."""
        now = self.mcu.clock.now_ms
        if self.running is not None and self.mcu.mc.state == "JOG":
            if self.running.dirs == dirs:
                self.running.deadline_ms = now + DEAD_MAN_MS
                return
            self.end()
            raise MotionError("BUSY", "jog changes direction")
        self._start(dirs, feed, now)

    def _start(self, dirs: str, feed: float, now: int) -> None:
        mcu = self.mcu
        if mcu.job.open and not mcu.mc.at_stop():
            raise MotionError("BUSY", "a job is open")
        if mcu.mc.state == "ALARM":
            raise MotionError("ALARM", "clear the alarm first")
        mcu.mc.ready_to_jog()
        unit = unit_vector(dirs)
        start = mcu.mc.commanded_mm
        limits = mcu.profile.travel.limits()
        if mcu.mc.homed:
            distance, edge = run_to_edge(start, unit, limits)
            if distance < 1e-3:
                raise MotionError("SOFT_LIMIT", f"{edge.replace(' ', ' at ')}")
        else:
            distance, edge = max(hi - lo for lo, hi in limits), ""
        target = tuple(start[k] + unit[k] * distance for k in range(3))
        rate = min(feed, mcu.profile.motion.rapid_mm_min)
        mcu.mc.jog_to(start, target, rate, f"jog {dirs}")
        self.running = _Running(dirs, now + DEAD_MAN_MS, edge)

    def end(self) -> None:
        """``R JOGEND`` (or a new direction): decelerate and stop the continuous jog."""
        if self.running is not None and self.mcu.mc.state == "JOG":
            self.mcu.mc.end_jog()
        self.running = None

    def tick(self) -> None:
        """The dead man, and the message of a jog that ran to the travel's edge."""
        running, mcu = self.running, self.mcu
        if running is None:
            return
        if mcu.mc.state != "JOG":
            self.running = None
            if running.edge and not mcu.mc.stopping and self._at_edge(running.edge):
                mcu.send(Log(f"jog stopped at the soft limit {running.edge}"))
        elif mcu.clock.now_ms >= running.deadline_ms:
            self.end()
            mcu.send(Log(f"jog stopped: no keep-alive for {DEAD_MAN_MS} ms"))

    def _at_edge(self, edge: str) -> bool:
        k, bound = AXES.index(edge[0]), float(edge.split(" ")[1])
        return abs(self.mcu.mc.commanded_mm[k] - bound) < 1e-3

    def next_due_ms(self) -> int | None:
        return None if self.running is None else self.running.deadline_ms
