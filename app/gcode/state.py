"""The modal state of the interpreter, LinuxCNC's defaults: at (0, 0, 0), G80 (no
motion mode), G17, G21, G90, G91.1, G99, G54 with zero offsets, no tool, feed 0,
spindle off. Positions are millimetres in the machine's work frame (the frame of the
rows, see ``offsets.py``); ``program_pos()`` is the point in program coordinates.

``params`` (the numbered parameters, shared with the expander) and ``tools`` (the
tool table) are shared by every copy: a line writes parameters into ``pending`` and
``commit()`` applies them once the line has succeeded; ``tools`` is replaced, never
changed in place.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from .limits import Budget
from .offsets import Offsets
from .params import Params


@dataclass(slots=True)
class Cycle:
    """The sticky values of canned cycles (rs274ngc's cycle_*): program units."""

    r: float = 0.0
    z: float = 0.0
    p: float = 0.0
    q: float = 0.0
    initial: float | None = None  # the Z level a run of cycle blocks started from (mm)
    spline_i: float = 0.0  # G5's mirrored first control point when I J are left out
    spline_j: float = 0.0


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
    offsets: Offsets = field(default_factory=Offsets)
    retract_r: bool = True  # G99 (rs274's default with no ini); False: G98
    cycle: Cycle = field(default_factory=Cycle)
    tool: int = 0  # the tool in the spindle (#5400)
    selected: int = 0  # the tool the last T word prepared
    comp: object | None = None  # comp.Comp while G41/G42 is on
    saved: dict | None = None  # M70's saved modal state
    arc_not_allowed: bool = False  # after G40 ended a compensated path: the next move is straight
    arc_tolerance: float = 0.01  # mm, for chords of splines
    params: Params = field(default_factory=Params)
    tools: dict = field(default_factory=dict)  # tool number -> tools.Tool
    pending: dict[int, float] = field(default_factory=dict)
    block_delete: bool = False  # the operator's switch: lines starting with "/" are skipped
    budget: Budget = field(default_factory=Budget)  # shared: moves of cycles and splines so far
    fanuc: bool = False  # a Fanuc program: D and H name offset registers, which exist without tools

    @property
    def scale(self) -> float:
        """Millimetres per program unit."""
        return 25.4 if self.inch else 1.0

    def copy(self) -> State:
        other = State(list(self.pos), self.motion, self.plane, self.inch, self.absolute)
        other.ijk_absolute, other.feed, other.speed = self.ijk_absolute, self.feed, self.speed
        other.spindle_on, other.ended = self.spindle_on, self.ended
        other.offsets, other.retract_r = self.offsets.copy(), self.retract_r
        c = self.cycle
        other.cycle = Cycle(c.r, c.z, c.p, c.q, c.initial, c.spline_i, c.spline_j)
        other.tool, other.selected, other.saved = self.tool, self.selected, self.saved
        other.arc_not_allowed = self.arc_not_allowed
        other.comp = self.comp.copy() if self.comp is not None else None
        other.arc_tolerance, other.params, other.tools = self.arc_tolerance, self.params, self.tools
        other.block_delete, other.budget, other.fanuc = self.block_delete, self.budget, self.fanuc
        return other

    def param(self, number: int) -> float:
        """``#number`` as this line sees it (its own writes first); unset reads 0."""
        if number in self.pending:
            return self.pending[number]
        value = self.params.get(number)
        return 0.0 if value is None else value

    def set_param(self, number: int, value: float) -> None:
        """Write ``#number`` when the line succeeds (``commit``)."""
        self.pending[number] = float(value)

    def commit(self) -> None:
        """Apply this line's parameter writes to the shared table."""
        if self.pending:
            for number, value in self.pending.items():
                self.params.set(number, value)
            self.pending.clear()

    def program_pos(self) -> list[float]:
        """The current point in program coordinates, millimetres."""
        return self.offsets.to_program(self.pos)

    def fast_path_ok(self) -> bool:
        """True when the bulk XY interpreter can take over: G17, G91.1, running, no
        compensation, no canned cycle or spline mode, no rotated work offset (the other
        offsets are a translation, which ``vector`` adds)."""
        return (self.plane == 0 and not self.ijk_absolute and not self.ended
                and self.comp is None and not self.arc_not_allowed and not self.offsets.rotation
                and (self.motion is None or self.motion <= 3))
