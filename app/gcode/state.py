"""The modal state of the interpreter, LinuxCNC's defaults: at (0, 0, 0), G80 (no
motion mode), G17, G21, G90, G91.1, feed 0, spindle off. Positions are millimetres.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(slots=True)
class State:
    """Everything one line can change; ``copy()`` before a line that may fail."""

    pos: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    motion: int | None = None
    plane: int = 0
    inch: bool = False
    absolute: bool = True
    ijk_absolute: bool = False
    feed: float = 0.0
    speed: float | None = None
    spindle_on: bool = False
    ended: int = 0  # source line of M2/M30, 0 while running

    @property
    def scale(self) -> float:
        """Millimetres per program unit."""
        return 25.4 if self.inch else 1.0

    def copy(self) -> State:
        other = State(list(self.pos), self.motion, self.plane, self.inch, self.absolute)
        other.ijk_absolute, other.feed, other.speed = self.ijk_absolute, self.feed, self.speed
        other.spindle_on, other.ended = self.spindle_on, self.ended
        return other

    def fast_path_ok(self) -> bool:
        """True when the bulk XY interpreter can take over (G17, G91.1, running)."""
        return self.plane == 0 and not self.ijk_absolute and not self.ended
