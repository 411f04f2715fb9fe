"""LinuxCNC's predefined named parameters: what an o-word program reads of the
interpreter's state (``#<_x>``, ``#<_metric>``, ``#<_motion_mode>`` ...), as rs274ngc
2.9 gives them. Read-only.

``CONSTANT`` ones are fixed for this machine and compiled into the expression (and
``#<_line>`` is the line's own number); the others are written into the global
named table from the interpreter's state by ``publish`` before a read (the walker's
sync, as for #5400-#5428). The lathe, override, coolant and feed-mode ones have the
values a mill with no overrides, no coolant and G94 G97 reads.
"""

from __future__ import annotations

from app.gcode.comp_corners import LEFT
from app.i18n import msg

from .errors import MacroError

CONSTANT = {
    "_vmajor": 2.9, "_vminor": 0.0, "_task": 0.0, "_remap_level": 0.0, "_inverse_time": 0.0,
    "_units_per_rev": 0.0, "_units_per_minute": 1.0, "_spindle_rpm_mode": 1.0,
    "_spindle_css_mode": 0.0, "_lathe_diameter_mode": 0.0, "_lathe_radius_mode": 1.0,
    "_speed_override": 1.0, "_feed_override": 1.0, "_adaptive_feed": 0.0, "_feed_hold": 1.0,
    "_mist": 0.0, "_flood": 0.0,
}
FROM_STATE = frozenset({
    "_metric", "_imperial", "_absolute", "_incremental", "_motion_mode", "_plane", "_ccomp",
    "_coord_system", "_tool_offset", "_retract_r_plane", "_retract_old_z", "_feed", "_rpm",
    "_current_tool", "_selected_tool", "_current_pocket", "_selected_pocket", "_spindle_on",
    "_spindle_cw", "_ijk_absolute_mode", "_x", "_y", "_z", "_a", "_b", "_c", "_u", "_v", "_w",
    "_call_level",
})
READ_ONLY = FROM_STATE | set(CONSTANT) | {"_line"}
_SYSTEMS = {7: 591.0, 8: 592.0, 9: 593.0}


def refuse_write(name: str) -> MacroError:
    if name.startswith("_ini["):
        return MacroError(msg("#<{name}> is a value of the machine's ini file: it can be read, not set",
                              name=name))
    return MacroError(msg("#<{name}> is a predefined parameter: it can be read, not set", name=name))


def publish(state, call_level: int) -> None:
    """Write the ``FROM_STATE`` parameters from ``state`` into ``state.params.named``."""
    named, scale = state.params.named, state.scale
    motion = state.motion
    point = state.program_pos()
    on = 1.0 if state.spindle_on else 0.0
    system = state.offsets.system
    named.update({
        "_metric": 0.0 if state.inch else 1.0, "_imperial": 1.0 if state.inch else 0.0,
        "_absolute": 1.0 if state.absolute else 0.0, "_incremental": 0.0 if state.absolute else 1.0,
        "_motion_mode": 800.0 if motion is None else round(float(motion) * 10),
        "_plane": 170.0 + 10 * state.plane,
        "_ccomp": 400.0 if state.comp is None else (410.0 if state.comp.side == LEFT else 420.0),
        "_coord_system": _SYSTEMS.get(system, 530.0 + 10 * system),
        "_tool_offset": 1.0 if any(state.offsets.tool) else 0.0,
        "_retract_r_plane": 1.0 if state.retract_r else 0.0,
        "_retract_old_z": 0.0 if state.retract_r else 1.0,
        "_feed": state.feed / scale, "_rpm": float(state.speed or 0.0),
        "_current_tool": float(state.tool), "_selected_tool": float(state.selected),
        "_current_pocket": float(state.tool), "_selected_pocket": float(state.selected),
        "_spindle_on": on, "_spindle_cw": on, "_ijk_absolute_mode": 1.0 if state.ijk_absolute else 0.0,
        "_x": point[0] / scale, "_y": point[1] / scale, "_z": point[2] / scale,
        "_a": 0.0, "_b": 0.0, "_c": 0.0, "_u": 0.0, "_v": 0.0, "_w": 0.0,
        "_call_level": float(call_level),
    })
