"""Events the motion controller reports (drained by ``MotionController.events()``) and its error.

All events are frozen dataclasses; the CNC MCU layer turns them into frames
(``Finished`` -> ``F``, ``Alarm`` -> ``X``, ``StateChanged`` -> ``S``).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Finished:
    """Move ``seq`` has finished (setpoint at its end; ``end`` moves also settled) at
    controller time ``at_ms``."""

    seq: int
    source: str
    at_ms: int = -1


@dataclass(frozen=True)
class Alarm:
    """LIMIT, FOLLOWING_ERROR, COVER_OPEN; ``text`` names the axis or cause."""

    code: str
    text: str


@dataclass(frozen=True)
class Homed:
    """Homing finished; the machine stands at home (X0 Y0 Z30 machine)."""


@dataclass(frozen=True)
class StateChanged:
    state: str


@dataclass(frozen=True)
class Held:
    """A feed hold (PAUSE, cover) has brought the machine to rest on the path."""


@dataclass(frozen=True)
class ProgramStop:
    """Execution reached a program stop (M00/M01/M06) and waits for ``release_stop``."""

    seq: int
    line: str


@dataclass(frozen=True)
class Stopped:
    """A stop has finished: at rest, queue flushed, spindle off."""


class MotionError(RuntimeError):
    """A request the controller refuses now: ``code`` (QUEUE_FULL, COVER_OPEN, ALARM, BUSY)."""

    def __init__(self, code: str, text: str):
        super().__init__(f"{code} {text}")
        self.code = code
        self.text = text
