"""One simulated clock for the whole machine.

Time is kept in whole milliseconds (``now_ms``), the period of the CNC MCU's control
loop; ``now`` gives seconds. Nothing in the simulator reads the wall clock except this
clock (``target_ms``, ``wall_until``, ``link_now``), which the runner thread uses to
keep simulated time in step with the wall clock:

- ``speed=1.0``: real time (the GUI);
- ``speed=20.0``: a speed factor (one wall second is 20 simulated seconds);
- ``speed=None``: as fast as possible (tests, benchmarks; ``pace`` never waits).

Only the simulator advances the clock (``advance_to``); everybody else reads it.

Link time (``link_now``) is the clock of the host-facing link timers (host lost, the
partial-frame timeout of the USB side, the LED and buzzer): paced at any factor, it is
the wall clock itself (``wall``, ``time.monotonic`` unless a test injects another),
so a host that knows nothing of the factor sees the same timing at any factor, also
when the simulation cannot keep up with it (a busy machine at ``--speed 50``: the
simulated clock falls behind the wall, the link's does not). Unpaced (tests), it is
simulated time, and the simulation stays deterministic.

``speed_problem`` is the one check of a speed factor (``--speed``, ``sim://?speed=``):
finite, > 0 and at most ``MAX_SPEED``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

MS = 0.001
MAX_SPEED = 1000.0


def speed_problem(speed: float) -> str | None:
    """Why ``speed`` cannot be a speed factor, or None (nan, inf, 1e308, 0, -1 ...)."""
    if not (math.isfinite(speed) and 0 < speed <= MAX_SPEED):
        return f"speed factor {speed!r}: a number above 0 and at most {MAX_SPEED:g}"
    return None


@dataclass
class SimClock:
    """Simulated time in ms plus the pacing rule against the wall clock."""

    speed: float | None = None
    now_ms: int = 0
    wall: Callable[[], float] = field(default=time.monotonic, repr=False)
    _wall0: float = field(default=0.0, repr=False)
    _sim0: int = field(default=0, repr=False)
    _link0: float = field(default=0.0, repr=False)

    @property
    def now(self) -> float:
        """Simulated seconds since power-up."""
        return self.now_ms * MS

    @property
    def link_now(self) -> float:
        """Link seconds: wall seconds when paced, simulated seconds when not (see the module)."""
        if self.speed is None:
            return self._link0 + (self.now_ms - self._sim0) * MS
        return self._link0 + (self.wall() - self._wall0)

    def ms_at_link(self, link_s: float) -> int:
        """The simulated ms at which ``link_now`` reaches ``link_s`` if the simulation
        keeps pace from now on (``now_ms`` when it has already: the simulator looks
        again at every step, so a late simulation fires the timer at its next step)."""
        ahead = (link_s - self.link_now) * (self.speed or 1.0) * 1000
        return self.now_ms + max(0, math.ceil(ahead - 1e-6))

    def advance_to(self, ms: int) -> None:
        if ms < self.now_ms:
            raise ValueError(f"clock cannot go back from {self.now_ms} to {ms} ms")
        self.now_ms = ms

    def set_speed(self, speed: float | None) -> None:
        """Change the pacing; the wall clock reference restarts at the current time."""
        if speed is not None and speed_problem(speed):
            raise ValueError(speed_problem(speed))
        self.anchor()
        self.speed = speed

    def anchor(self) -> None:
        """Tie the current simulated time to the current wall time."""
        self._link0 = self.link_now
        self._wall0 = self.wall()
        self._sim0 = self.now_ms

    def target_ms(self) -> int | None:
        """The simulated ms the wall clock allows now, or None when unpaced."""
        if self.speed is None:
            return None
        return self._sim0 + int((self.wall() - self._wall0) * self.speed * 1000)

    def wall_seconds(self, sim_seconds: float) -> float:
        """Wall seconds that ``sim_seconds`` of simulated time take at this speed."""
        return 0.0 if self.speed is None else sim_seconds / self.speed

    def wall_until(self, ms: int) -> float:
        """Wall seconds to wait before simulated time ``ms`` is due (0 when unpaced)."""
        if self.speed is None:
            return 0.0
        due = self._wall0 + (ms - self._sim0) / 1000 / self.speed
        return max(0.0, due - self.wall())
