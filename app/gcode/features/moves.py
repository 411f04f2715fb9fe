"""The generators' own small move type and a builder that tracks the tool.

A ``Move`` is a rapid, a feed line or an XY arc (helical when Z changes) ending at
``end``; arcs carry their centre (X, Y) and direction. ``note`` says where the move
comes from (``"layer 2/5 ring 3"``); writers may print it as a comment. Events that
are not motion (tool change, spindle) are ``Move`` kinds too, so one list is a whole
operation. Moves that a parametric form makes (the paper's profile rings) carry it as
``block``, so a macro writer can print that form instead of the moves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

RAPID, FEED, ARC, DWELL, TOOL, SPINDLE = "rapid", "feed", "arc", "dwell", "tool", "spindle"


@dataclass(frozen=True, slots=True)
class Move:
    """One step of a toolpath (see the module docstring)."""

    kind: str
    end: tuple[float, float, float] = (0.0, 0.0, 0.0)
    feed: float = 0.0
    center: tuple[float, float] | None = None
    cw: bool = False
    value: float = 0.0  # dwell seconds, tool number or spindle rpm
    note: str = ""
    block: object = None  # the parametric form these moves come from (``paper.PaperForm``)


class Path:
    """Appends moves while remembering where the tool is; skips moves of length 0."""

    def __init__(self, start: tuple[float, float, float]) -> None:
        self.moves: list[Move] = []
        self.pos = tuple(float(v) for v in start)
        self.note = ""

    def _to(self, kind: str, x: float | None, y: float | None, z: float | None, **kw) -> None:
        end = (self.pos[0] if x is None else float(x), self.pos[1] if y is None else float(y),
               self.pos[2] if z is None else float(z))
        if math.dist(end, self.pos) < 1e-9:
            return
        self.moves.append(Move(kind, end, note=self.note, **kw))
        self.pos = end

    def rapid(self, x=None, y=None, z=None) -> None:
        self._to(RAPID, x, y, z)

    def feed(self, x=None, y=None, z=None, *, f: float) -> None:
        self._to(FEED, x, y, z, feed=f)

    def arc(self, x, y, center, cw: bool, *, z=None, f: float) -> None:
        self._to(ARC, x, y, z, feed=f, center=(float(center[0]), float(center[1])), cw=cw)

    def dwell(self, seconds: float) -> None:
        self.moves.append(Move(DWELL, self.pos, value=seconds, note=self.note))

    def event(self, kind: str, value: float) -> None:
        self.moves.append(Move(kind, self.pos, value=value, note=self.note))
