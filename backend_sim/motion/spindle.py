"""RS775 spindle: first-order speed response, 20 pulse/rev encoder read over a gate time.

Contract: evaluated lazily and exactly from the time of the last command, so it costs
nothing per tick. ``command(now_ms, rpm)`` sets the target (capped by what the supply
minus the L298N drop can reach; OFF brakes, so the spindle stops within half a
second); ``measured_rpm(now_ms)`` is the pulse count of the last complete ``GATE_MS``
gate scaled to rpm, as the MCU's timer capture would report it. ``settled(now_ms)``
says whether the speed still changes (after OFF it decays to 0).
"""

from __future__ import annotations

import math

GATE_MS = 100
TAU_S = 0.25  # mechanical time constant of the unloaded spindle
TAU_BRAKE_S = 0.1  # OFF brakes the motor (L298N fast stop: both bridge legs low)


class SpindleModel:
    def __init__(self, profile):
        sp = profile.spindle
        self.ppr = sp.encoder_ppr
        self.max_rpm = sp.no_load_rpm * max(0.0, sp.supply_v - profile.axis.bridge_drop_v) / sp.supply_v
        self.reset(0)

    def reset(self, now_ms: int) -> None:
        self.t_ref, self.w_ref, self.revs_ref, self.target = now_ms, 0.0, 0.0, 0.0
        self.tau = TAU_S

    def effective(self, rpm: float) -> float:
        """The speed a command of ``rpm`` settles at."""
        return min(max(rpm, 0.0), self.max_rpm)

    def command(self, now_ms: int, rpm: float) -> None:
        self.w_ref, self.revs_ref = self.true_rpm(now_ms), self._revs(now_ms)
        self.t_ref, self.target = now_ms, self.effective(rpm)
        self.tau = TAU_BRAKE_S if self.target == 0.0 else TAU_S

    def true_rpm(self, now_ms: int) -> float:
        dt = (now_ms - self.t_ref) / 1000.0
        return self.target + (self.w_ref - self.target) * math.exp(-dt / self.tau)

    def _revs(self, now_ms: int) -> float:
        dt = (now_ms - self.t_ref) / 1000.0
        decay = self.tau * (1.0 - math.exp(-dt / self.tau))
        return self.revs_ref + (self.target * dt + (self.w_ref - self.target) * decay) / 60.0

    def _pulses(self, now_ms: int) -> int:
        return math.floor(self._revs(now_ms) * self.ppr + 1e-9)

    def measured_rpm(self, now_ms: int) -> float:
        end = now_ms - now_ms % GATE_MS
        if end < GATE_MS:
            return 0.0
        start = end - GATE_MS
        if start < self.t_ref:  # gate straddles the last command: count both parts
            pulses = self._pulses(end) - math.floor(self._before(start) * self.ppr + 1e-9)
        else:
            pulses = self._pulses(end) - self._pulses(start)
        return pulses * 60000.0 / (self.ppr * GATE_MS)

    def _before(self, t_ms: int) -> float:
        """Revolutions at a time before the last command (previous segment, approximated)."""
        return self.revs_ref - self.w_ref * (self.t_ref - t_ms) / 60000.0

    def settled(self, now_ms: int) -> bool:
        """At its target speed (within 0.5 rpm), and reading 0 once stopped: until then the
        MCU keeps the loop and its status reports running, so the reading decays to 0."""
        if abs(self.true_rpm(now_ms) - self.target) >= 0.5:
            return False
        return self.target > 0 or self.measured_rpm(now_ms) == 0.0

    def ready(self, now_ms: int, rpm: float) -> bool:
        """Measured speed within 5 % (or 30 rpm) of the speed ``rpm`` settles at."""
        goal = self.effective(rpm)
        return abs(self.measured_rpm(now_ms) - goal) <= max(0.05 * goal, 30.0)
