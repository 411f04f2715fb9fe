"""Program stops as the host sees them (docs/protocol.md, "Program stops").

``stop_event(index, line)`` reads a stop device line (``M00``, ``M01``, ``M06 T2``)
into a ``ProgramStopEvent``; ``is_stop_line`` tells one apart. ``StopWatch`` decides,
status by status, when the machine has reached a new stop (flag ``W``: the stop line
is the one after ``done``), so each stop is reported once, and again only after a
reconnect.
"""

from __future__ import annotations

import re

from app.comm.events import ProgramStopEvent

_STOP = re.compile(r"M0*([016])(?:\s*T(\d+))?\s*$")
WAITING = "W"


def is_stop_line(line: str) -> bool:
    return _STOP.match(line.strip().upper()) is not None


def stop_event(index: int, line: str) -> ProgramStopEvent:
    """The event of the stop line ``line`` at program index ``index``."""
    match = _STOP.match(line.strip().upper())
    if match is None:
        return ProgramStopEvent(index, line, 0)
    tool = int(match.group(2)) if match.group(2) is not None else None
    return ProgramStopEvent(index, line, int(match.group(1)), tool)


class StopWatch:
    """Reports each program stop once (``seen`` holds the stream seq of the last one)."""

    def __init__(self) -> None:
        self.seen: int | None = None

    def update(self, flags: str, done: int) -> int | None:
        """The stream seq of a stop newly reached, else None; clears once running again."""
        if WAITING not in flags:
            self.seen = None
            return None
        seq = done + 1
        if seq == self.seen:
            return None
        self.seen = seq
        return seq

    def forget(self) -> None:
        """Report the current stop again (after a reconnect)."""
        self.seen = None
