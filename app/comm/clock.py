"""Host clocks: the session's timers run on machine time.

A machine simulated ``scale`` times faster than real time (``cnc-sim --speed 20``)
expects the host's heartbeat every simulated second; ``ScaledClock(scale)`` gives the
session seconds that run ``scale`` times faster than the wall clock (1.0: real time).
An in-process simulator lends its own clock instead (``SimTransport.clock``).
"""

from __future__ import annotations

import time


class ScaledClock:
    """``clock()`` -> seconds, advancing ``scale`` times as fast as ``time.monotonic``."""

    def __init__(self, scale: float = 1.0, source=time.monotonic) -> None:
        if not scale > 0:
            raise ValueError(f"time scale must be > 0, not {scale}")
        self.scale = scale
        self._source = source
        self._wall0 = source()

    def __call__(self) -> float:
        return self._wall0 + (self._source() - self._wall0) * self.scale
