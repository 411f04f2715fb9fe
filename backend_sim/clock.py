"""One simulated clock for the whole machine.

Time is kept in whole milliseconds (``now_ms``), the period of the CNC MCU's control
loop; ``now`` gives seconds. Nothing in the simulator reads the wall clock except
``SimClock.pace``, which a runner thread calls to keep simulated time in step with the
wall clock:

- ``speed=1.0``: real time (the GUI);
- ``speed=20.0``: a speed factor (one wall second is 20 simulated seconds);
- ``speed=None``: as fast as possible (tests, benchmarks; ``pace`` never waits).

Only the simulator advances the clock (``advance_to``); everybody else reads it.

Link time (``link_now``) is the clock of the host-facing link timers (host lost, the
LED and buzzer): simulated time divided by the speed factor, so at any factor it runs
in step with the wall clock and a host that knows nothing of the factor keeps the link
alive; unpaced (tests), it is simulated time. It is derived from simulated time, so
the simulation stays deterministic.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

MS = 0.001


@dataclass
class SimClock:
    """Simulated time in ms plus the pacing rule against the wall clock."""

    speed: float | None = None
    now_ms: int = 0
    _wall0: float = field(default=0.0, repr=False)
    _sim0: int = field(default=0, repr=False)
    _link0: float = field(default=0.0, repr=False)

    @property
    def now(self) -> float:
        """Simulated seconds since power-up."""
        return self.now_ms * MS

    @property
    def link_now(self) -> float:
        """Link seconds: simulated seconds / speed since the last anchor (see the module)."""
        return self._link0 + (self.now_ms - self._sim0) * MS / (self.speed or 1.0)

    def ms_at_link(self, link_s: float) -> int:
        """The first simulated ms at which ``link_now`` reaches ``link_s``."""
        return self._sim0 + math.ceil((link_s - self._link0) * (self.speed or 1.0) * 1000 - 1e-6)

    def advance_to(self, ms: int) -> None:
        if ms < self.now_ms:
            raise ValueError(f"clock cannot go back from {self.now_ms} to {ms} ms")
        self.now_ms = ms

    def set_speed(self, speed: float | None) -> None:
        """Change the pacing; the wall clock reference restarts at the current time."""
        if speed is not None and speed <= 0:
            raise ValueError(f"speed must be > 0 or None, not {speed}")
        self.anchor()
        self.speed = speed

    def anchor(self) -> None:
        """Tie the current simulated time to the current wall time."""
        self._link0 = self.link_now
        self._wall0 = time.monotonic()
        self._sim0 = self.now_ms

    def target_ms(self) -> int | None:
        """The simulated ms the wall clock allows now, or None when unpaced."""
        if self.speed is None:
            return None
        return self._sim0 + int((time.monotonic() - self._wall0) * self.speed * 1000)

    def wall_seconds(self, sim_seconds: float) -> float:
        """Wall seconds that ``sim_seconds`` of simulated time take at this speed."""
        return 0.0 if self.speed is None else sim_seconds / self.speed

    def wall_until(self, ms: int) -> float:
        """Wall seconds to wait before simulated time ``ms`` is due (0 when unpaced)."""
        if self.speed is None:
            return 0.0
        due = self._wall0 + (ms - self._sim0) / 1000 / self.speed
        return max(0.0, due - time.monotonic())
