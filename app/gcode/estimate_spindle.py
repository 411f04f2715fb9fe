"""How long the machine waits at a spindle command before the path goes on.

Contract: ``spin_wait_ms(profile, rpm_from, rpm_to)`` is the mean number of milliseconds
(over the phase of the 100 ms measuring gate) from ``M03 S..`` until the CNC MCU sees the
spindle at speed: the spindle follows a first-order response (time constant 0.25 s),
its encoder is counted over 100 ms gates, and the machine goes on once the measured
speed is within 5 % (or 30 rpm) of the speed the command settles at, or after 4 s.
Switching off (``M05``) does not wait. These are the simulator's spindle rules
(``backend_sim/motion/spindle.py``, ``controller_ops.spindle_command``), restated here
because ``app.gcode`` never imports the simulator.
"""

from __future__ import annotations

import math
from functools import lru_cache

GATE_MS = 100
TAU_S = 0.25
MAX_WAIT_MS = 4000
PHASES = 10  # gate phases averaged over (the job's start time is not known in advance)


def spin_wait_ms(profile, rpm_from: float, rpm_to: float) -> float:
    """Mean milliseconds the barrier of ``M03 S<rpm_to>`` lasts after ``rpm_from``."""
    sp = profile.spindle
    top = profile.max_spindle_rpm()
    return _mean_wait(min(max(rpm_from, 0.0), top), min(max(rpm_to, 0.0), top), sp.encoder_ppr)


@lru_cache(maxsize=256)
def _mean_wait(w0: float, target: float, ppr: int) -> float:
    if target <= 0:
        return 1.0
    waits = [_wait(w0, target, ppr, phase * GATE_MS // PHASES) for phase in range(PHASES)]
    return sum(waits) / len(waits)


def _wait(w0: float, target: float, ppr: int, phase_ms: int) -> int:
    """Barrier milliseconds when the command falls ``phase_ms`` into a gate."""
    def revs(t_ms: float) -> float:  # revolutions since the command (steady w0 before it)
        if t_ms <= 0:
            return w0 * t_ms / 60000.0
        dt = t_ms / 1000.0
        return (target * dt + (w0 - target) * TAU_S * (1.0 - math.exp(-dt / TAU_S))) / 60.0

    tolerance = max(0.05 * target, 30.0)
    gate_end = GATE_MS - phase_ms  # first gate end after the command, ms from it
    while gate_end < MAX_WAIT_MS:
        pulses = math.floor(revs(gate_end) * ppr + 1e-9) - math.floor(revs(gate_end - GATE_MS) * ppr + 1e-9)
        if abs(pulses * 60000.0 / (ppr * GATE_MS) - target) <= tolerance:
            return gate_end + 1
        gate_end += GATE_MS
    return MAX_WAIT_MS + 1
