"""The simulated GRBL's ``$`` settings: defaults for this project's mill and the rules
a write must pass (GRBL's errors: unknown setting 3, negative value 4, step pulse
under 3 us 6, soft limits without homing 10)."""

from __future__ import annotations

import math

DEFAULTS: dict[int, float] = {
    0: 10, 1: 25, 2: 0, 3: 0, 4: 0, 5: 0, 6: 0, 10: 1, 11: 0.010, 12: 0.002, 13: 0,
    20: 0, 21: 1, 22: 1, 23: 3, 24: 100.0, 25: 500.0, 26: 250, 27: 10.0, 30: 4500, 31: 0, 32: 0,
    100: 247.5, 101: 247.5, 102: 247.5, 110: 600.0, 111: 600.0, 112: 600.0,
    120: 50.0, 121: 50.0, 122: 50.0, 130: 150.0, 131: 150.0, 132: 30.0,
}
WHOLE = frozenset({0, 1, 2, 3, 4, 5, 6, 10, 13, 20, 21, 22, 23, 26, 32})


def check(settings: dict[int, float], number: int, text: str) -> float:
    """The value ``$number=text`` would store; raises ``ValueError(code)`` as GRBL refuses."""
    if number not in DEFAULTS:
        raise ValueError(3)
    try:
        value = float(text)
    except ValueError:
        raise ValueError(2) from None
    if not math.isfinite(value):
        raise ValueError(2)
    if value < 0:
        raise ValueError(4)
    if number == 0 and value < 3:
        raise ValueError(6)
    if number == 20 and value and not settings[22]:
        raise ValueError(10)
    return float(int(value)) if number in WHOLE else value


def format_setting(number: int, value: float) -> str:
    whole = number in WHOLE or number in (26, 30, 31)
    return f"${number}={int(value)}" if whole else f"${number}={value:.3f}"
