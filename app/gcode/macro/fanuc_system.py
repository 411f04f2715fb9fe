"""Fanuc's system variables: what a macro B program reads of the control, and #3000.

Read (refreshed from the interpreter's state before a Fanuc macro reads #4000 and
up, as the LinuxCNC block #5400-#5428 is): #4001-#4022 the modal G code of each
group (1 motion, 2 plane, 3 G90/G91, 5 feed mode, 6 units, 7 cutter compensation,
8 tool length offset, 9 canned cycle, 10 cycle retract, 14 work offset), #4109 F,
#4119 S, #4120 T; #5001-#5003 the end point of the last block and #5041-#5043 the
current point (work coordinates, program units), #5021-#5023 the point in the
machine's frame. They are read-only: setting one is an error. ``#3000 = n (TEXT)``
raises the macro alarm 3000 + n with the line's comment as its message and stops
the program, as the control does.
"""

from __future__ import annotations

from app.gcode.comp_corners import LEFT
from app.i18n import msg

from .errors import MacroError

ALARM = 3000
_MODAL = range(4001, 4023)
_READ_ONLY = (range(4001, 4131), range(5001, 5004), range(5021, 5024), range(5041, 5044))
_CYCLES = {73, 74, 76, 81, 82, 83, 84, 85, 86, 87, 88, 89}


def read_only(number: int) -> bool:
    """True for a system variable a Fanuc macro may read but not set."""
    return any(number in r for r in _READ_ONLY)


def refuse_write(number: int) -> MacroError:
    return MacroError(msg("#{number} is a system variable of the control: it can be read, not set",
                          number=number))


def alarm(value, message: str) -> MacroError:
    """The error ``#3000 = value`` raises (``message``: the line's comment, may be empty)."""
    number = ALARM + int(value or 0)
    return MacroError(msg("macro alarm {number}: {message}", number=number, message=message) if message
                      else msg("macro alarm {number}", number=number))


def publish(state) -> None:
    """Write the variables of the module docstring from ``state`` into ``state.params``."""
    params, scale = state.params, state.scale
    groups = _groups(state)
    for number in _MODAL:
        params.set(number, groups.get(number))
    params.set(4109, state.feed / scale)
    params.set(4119, state.speed or 0.0)
    params.set(4120, float(state.selected))
    point = state.program_pos()
    for i in range(3):
        params.set(5001 + i, point[i] / scale)
        params.set(5041 + i, point[i] / scale)
        params.set(5021 + i, state.pos[i] / scale)


def _groups(state) -> dict[int, float]:
    motion = state.motion
    cycle = motion if motion in _CYCLES else 80
    system = state.offsets.system
    return {
        4001: float(motion if motion is not None and motion <= 3 else (cycle if cycle != 80 else 0)),
        4002: 17.0 + state.plane,
        4003: 90.0 if state.absolute else 91.0,
        4005: 94.0,
        4006: 20.0 if state.inch else 21.0,
        4007: 40.0 if state.comp is None else (41.0 if state.comp.side == LEFT else 42.0),
        4008: 49.0 if not any(state.offsets.tool) else 43.0,
        4009: float(cycle),
        4010: 99.0 if state.retract_r else 98.0,
        4014: 53.0 + system if system <= 6 else round(59.0 + (system - 6) / 10, 1),
    }
