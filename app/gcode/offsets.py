"""Coordinate systems and offsets, as LinuxCNC's rs274ngc applies them (no rotation).

One rule: the rows (preview, device lines) are in the machine's work frame, whose
zero is the operator's work zero (``ZERO`` on the machine, the profile's work offset).
``G54`` with zero offsets is that frame; a program's offsets shift from there and never
change the operator's work zero. A point in program coordinates ``p`` is at
``rotate(p + g92, R) + g5x + tool`` in the frame (``Offsets.to_frame``), as rs274ngc
adds its axis offset, turns the XY plane by the work offset's rotation (``G10 L2 R``,
degrees about Z), then adds its origin offset and tool offset. Without rotation that
is the translation ``Offsets.total()``.

G28 and G30 go to the positions stored in #5161-#5163 and #5181-#5183 (G28.1, G30.1,
or a program writing them), held in the machine frame, so no offset moves them: a
row of the frame is a machine position (rs274ngc subtracts the offsets from the
stored position to get a program point, and adds them back to move). All these
parameters hold millimetres, as LinuxCNC configured for a metric machine.

The nine work offsets live in the numbered parameters (#5221.. for G54, 20 apart,
the rotation at #5230..), in millimetres; the G92 offset in #5211-#5213 (#5210 = 1 while applied); the active
system in #5220. Only a line that succeeds writes them (``State.set_param``). The
tool parameters #5400-#5410 lie past the table's last number (#5399) and are not kept.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from app.i18n import msg

from .errors import LineError

SYSTEM_BASE = 5201  # #5201 + 20 * n + axis: work offset n (1 = G54 .. 9 = G59.3)
STORED_BASE = {28: 5161, 30: 5181}  # G28 / G30 positions, X Y Z (machine frame, mm)
G92_APPLIED, G92_BASE, ACTIVE_SYSTEM = 5210, 5211, 5220


def _zeros() -> list[float]:
    return [0.0, 0.0, 0.0]


def rotate(x: float, y: float, degrees: float) -> tuple[float, float]:
    """(x, y) turned counter-clockwise by ``degrees`` (exactly unchanged for 0)."""
    if not degrees:
        return x, y
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return x * c - y * s, x * s + y * c


@dataclass(slots=True)
class Offsets:
    """The active offsets (mm, X Y Z), the active system's XY rotation (degrees) and
    which work offset is selected (1-9)."""

    system: int = 1
    g5x: list[float] = field(default_factory=_zeros)
    g92: list[float] = field(default_factory=_zeros)
    tool: list[float] = field(default_factory=_zeros)
    rotation: float = 0.0

    def copy(self) -> Offsets:
        return Offsets(self.system, list(self.g5x), list(self.g92), list(self.tool), self.rotation)

    def total(self) -> list[float]:
        """The translation from program to frame (exact only without rotation)."""
        return [a + b + c for a, b, c in zip(self.g5x, self.g92, self.tool, strict=True)]

    def to_frame(self, p) -> list[float]:
        """A program point (mm) in the frame."""
        x, y = rotate(p[0] + self.g92[0], p[1] + self.g92[1], self.rotation)
        return [x + self.g5x[0] + self.tool[0], y + self.g5x[1] + self.tool[1],
                p[2] + self.g92[2] + self.g5x[2] + self.tool[2]]

    def to_program(self, f) -> list[float]:
        """A frame point (mm) in program coordinates."""
        x, y = rotate(f[0] - self.g5x[0] - self.tool[0], f[1] - self.g5x[1] - self.tool[1], -self.rotation)
        return [x - self.g92[0], y - self.g92[1], f[2] - self.g5x[2] - self.tool[2] - self.g92[2]]

    def is_zero(self) -> bool:
        return not any(self.g5x) and not any(self.g92) and not any(self.tool) and not self.rotation


def system_param(system: int, axis: int) -> int:
    return SYSTEM_BASE + 20 * system + axis


def _no_comp(state, column: int, message: str) -> None:
    if state.comp is not None:
        raise LineError(column, message)


def select_system(state, system: int, column: int) -> None:
    """G54..G59.3: load work offset ``system`` from the parameters."""
    _no_comp(state, column, msg("cannot change coordinate systems with cutter radius compensation on"))
    if system == state.offsets.system:
        return
    state.offsets.system = system
    state.offsets.g5x = [state.param(system_param(system, i)) for i in range(3)]
    state.offsets.rotation = state.param(system_param(system, 9))
    state.set_param(ACTIVE_SYSTEM, system)


def _axis_values(state, params) -> dict[int, float]:
    return {i: params[c].value * state.scale for i, c in enumerate("XYZ") if c in params}


def _system_p(state, params, level: int, column: int) -> int:
    if "I" in params or "J" in params:
        raise LineError(params.get("I", params.get("J")).column, msg("I J words not allowed with G10 L2"))
    if "P" not in params:
        raise LineError(column, msg("{code} needs a P word (work offset 0-9)", code=f"G10 L{level}"))
    p = params["P"].value
    if p != int(p) or not 0 <= p <= 9:
        raise LineError(params["P"].column,
                        msg("P value out of range (0-9) with {code}", code=f"G10 L{level}"))
    system = int(p) or state.offsets.system
    if state.comp is not None and system == state.offsets.system:
        raise LineError(column, msg("cannot change the active coordinate system "
                                    "with cutter radius compensation on"))
    return system


def set_system(state, params, level: int, column: int) -> None:
    """G10 L2 (offset given, R its rotation) or L20 (offset so the current point reads
    the given values in that system, its rotation kept)."""
    system = _system_p(state, params, level, column)
    if "R" in params and level == 20:
        raise LineError(params["R"].column, msg("R not allowed in G10 L20"))
    off = state.offsets
    old = [state.param(system_param(system, i)) for i in range(3)]
    rotation = params["R"].value if "R" in params else state.param(system_param(system, 9))
    values = _axis_values(state, params)
    if level == 20:  # the current point, seen in that system, reads ``values``
        there = Offsets(system, old, off.g92, off.tool, rotation)
        prog = there.to_program(state.pos)
        for axis, value in values.items():
            prog[axis] = value
        x, y = rotate(prog[0] + off.g92[0], prog[1] + off.g92[1], rotation)
        moved = [x, y, prog[2] + off.g92[2]]
        axes = [0, 1] + ([2] if 2 in values else [])  # rs274 rewrites X and Y always
        values = {axis: state.pos[axis] - off.tool[axis] - moved[axis] for axis in axes}
    for axis, value in values.items():
        old[axis] = value
        state.set_param(system_param(system, axis), value)
    if "R" in params:
        state.set_param(system_param(system, 9), rotation)
    if system == off.system:
        off.g5x, off.rotation = old, rotation


def _write_g92(state, applied: bool, values=None) -> None:
    state.set_param(G92_APPLIED, 1.0 if applied else 0.0)
    for i in range(3):
        if values is not None:
            state.set_param(G92_BASE + i, values[i])


def axis_offsets(state, code: float, params, column: int) -> None:
    """G92, G92.1, G92.2, G92.3 and G52 (LinuxCNC: G52 sets the G92 offset itself)."""
    _no_comp(state, column, msg("cannot change axis offsets with cutter radius compensation on"))
    off = state.offsets
    if code in (92, 52):
        values = _axis_values(state, params)
        if not values:
            raise LineError(column, msg("All axes missing with G52 or G92"))
        prog = off.to_program(state.pos)
        for axis, value in values.items():
            off.g92[axis] = prog[axis] + off.g92[axis] - value if code == 92 else value
        _write_g92(state, True, off.g92)
    elif code in (92.1, 92.2):
        off.g92 = _zeros()
        _write_g92(state, False, off.g92 if code == 92.1 else None)
    else:  # 92.3: back from the parameters
        off.g92 = [state.param(G92_BASE + i) for i in range(3)]
        _write_g92(state, True)


def set_tool_offset(state, values: list[float]) -> None:
    """The tool length offset (mm, X Y Z) becomes ``values``."""
    state.offsets.tool = list(values)


def store_position(state, code: int) -> None:
    """G28.1 / G30.1: the current point, in the machine frame, becomes the stored
    position (#5161-#5163 / #5181-#5183)."""
    for i in range(3):
        state.set_param(STORED_BASE[code] + i, state.pos[i])


def stored_position(state, code: int) -> list[float]:
    """The position G28 / G30 go to, in the machine frame (mm; machine zero unless set)."""
    return [state.param(STORED_BASE[code] + i) for i in range(3)]
