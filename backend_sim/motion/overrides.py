"""The operator's overrides as the CNC MCU keeps them (docs/protocol.md, "Overrides").

Contract: ``Overrides`` holds the feed, spindle and rapid percentages (100 each at
power-up and after a reset; the values are range-checked by the frame grammar before
they get here). ``apply(controller)`` hands the feed and rapid scales to the planner
(which re-plans its queue without stopping) and ramps the spindle to its programmed
speed times the spindle scale.
"""

from __future__ import annotations

from dataclasses import dataclass

VERBS = ("FEED", "SPINDLE", "RAPID")


@dataclass
class Overrides:
    feed: int = 100
    spindle: int = 100
    rapid: int = 100

    def set(self, verb: str, percent: int) -> None:
        """Take ``R <id> <verb> <percent>``; ValueError for another verb."""
        if verb not in VERBS:
            raise ValueError(f"no override {verb!r}")
        setattr(self, verb.lower(), int(percent))

    def as_tuple(self) -> tuple[int, int, int]:
        """The status's ``ovr`` field: (feed, spindle, rapid)."""
        return (self.feed, self.spindle, self.rapid)

    def spindle_rpm(self, programmed: float) -> float:
        """The speed the spindle is driven at for a programmed ``programmed`` rpm."""
        return programmed * self.spindle / 100.0
