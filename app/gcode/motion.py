"""Motion words of one line: dwell G4, straight moves G0/G1 (and G53), arcs G2/G3,
and the hand-off to canned cycles (``cycles.py``), splines (``splines.py``) and
cutter compensation (``comp.py``).

``do_motion`` follows rs274ngc: the motion of a line is its motion word, or the modal
motion when the line has axis words (X Y Z, or the polar @ ^); I J K R need an arc,
and axis words with no motion mode (G80, or none yet) are refused. A line with G0/G1
and no axis word sets the mode and moves nowhere. End points are program values
taken through the offsets (``offsets.Offsets``; none for G53). Arc centres are
checked with LinuxCNC's tolerances (``arcs.py``) in the program's units; an arc with
no axis word is a full circle (LinuxCNC 2.9 accepts ``G2 I10``); positions and
centres leave here in millimetres of the work frame. Raises ``LineError``; changes
``state`` in place.
"""

from __future__ import annotations

import math

from app.i18n import msg

from . import offsets
from .arcs import ijk_error, r_center
from .cycles import run_cycle
from .errors import LineError
from .limits import dwell_problem, turns_problem
from .ops import ARC_CCW, ARC_CW, DWELL, FEED, PLANE_AXES, PLANE_NAMES, RAPID, OpBuffer
from .splines import run_spline
from .state import State
from .words import AXES, CYCLES, MOVE_WORDS


def is_cycle(code) -> bool:
    return code in CYCLES

LIMIT_MM = 1e6
_OFFSETS = "IJK"
__all__ = ["LineError", "do_motion"]


def _col(params, letters: str) -> int:
    cols = [params[c].column for c in letters if c in params]
    return min(cols) if cols else 0


def _dwell(state: State, params, line_no: int, ops: OpBuffer) -> None:
    if "P" not in params:
        raise LineError(0, msg("G4 dwell needs a P word (seconds)"))
    seconds = params["P"].value
    if seconds < 0:
        raise LineError(params["P"].column, msg("G4 dwell time P must not be negative"))
    if dwell_problem(seconds):
        raise LineError(params["P"].column, dwell_problem(seconds))
    ops.add(line_no, DWELL, state.pos, value=seconds)


def _motion_to_be(state: State, groups, params) -> int | None:
    has_axis = any(c in params for c in MOVE_WORDS)
    if "motion" in groups:
        return groups["motion"][0]
    return state.motion if has_axis else None


def _check_usage(motion, params) -> None:
    has_axis = any(c in params for c in MOVE_WORDS)
    if has_axis and motion is None or has_axis and motion == 80:
        raise LineError(_col(params, MOVE_WORDS), msg("axis word with no motion mode (G0, G1, G2 or G3)"))


def _target(state: State, params, machine: bool = False) -> list[float]:
    """The end point in the frame: program values through the offsets (none for G53)."""
    off = state.offsets
    if machine or not off.rotation:
        target = list(state.pos)
        total = (0.0, 0.0, 0.0) if machine else off.total()
        for i, c in enumerate(AXES):
            if c in params:
                v = params[c].value * state.scale
                target[i] = v + total[i] if state.absolute else state.pos[i] + v
    else:  # a rotated system: in program coordinates, then through the rotation
        prog = off.to_program(state.pos)
        for i, c in enumerate(AXES):
            if c in params:
                v = params[c].value * state.scale
                prog[i] = v if state.absolute else prog[i] + v
        target = off.to_frame(prog)
    if "@" in params or "^" in params:
        _polar(state, params, target)
    for i, c in enumerate(AXES):
        if c in params and abs(target[i]) > LIMIT_MM:
            raise LineError(params[c].column, msg("{axis} coordinate out of range", axis=c))
    return target


def _polar(state: State, params, target) -> None:
    """@ (radius) and ^ (angle, degrees) about the program's origin, as rs274ngc:
    in G90 a missing one keeps the current point's; in G91 both are increments."""
    off = state.offsets
    x, y, _ = off.to_program(state.pos)
    word = params["@"] if "@" in params else params["^"]
    radius, theta = math.hypot(x, y), math.atan2(y, x)
    if x == 0 and y == 0 and not (state.absolute and "^" in params):
        why = (msg("Must specify angle in polar coordinate if at the origin") if state.absolute
               else msg("Incremental motion with polar coordinates is indeterminate when at the origin"))
        raise LineError(word.column, why)
    if "@" in params:
        value = params["@"].value * state.scale
        radius = value if state.absolute else radius + value
    if "^" in params:
        value = math.radians(params["^"].value)
        theta = value if state.absolute else theta + value
    if abs(radius) > LIMIT_MM:
        raise LineError(word.column, msg("polar radius out of range"))
    prog = off.to_program(target)
    prog[0], prog[1] = radius * math.cos(theta), radius * math.sin(theta)
    target[:] = off.to_frame(prog)


def _arc_words(state: State, params) -> None:
    a3 = PLANE_AXES[state.plane][2]
    name = PLANE_NAMES[state.plane]
    has_ijk = any(c in params for c in _OFFSETS)
    if "R" in params and has_ijk:
        raise LineError(params["R"].column, msg("arc with both R and I/J/K words"))
    if "R" not in params and not has_ijk:
        raise LineError(0, msg("R, I, J and K words all missing for arc"))
    bad = _OFFSETS[a3]
    if "R" not in params and bad in params:
        message = msg("{letter} word given for arc in {plane} plane", letter=bad, plane=name)
        raise LineError(params[bad].column, message)


def _turns(params, clockwise: bool) -> int:
    turns = 1
    if "P" in params:
        p = params["P"].value
        if p != int(p) or p < 1:
            raise LineError(params["P"].column, msg("arc turns P must be a whole number >= 1"))
        if turns_problem(p):
            raise LineError(params["P"].column, turns_problem(p))
        turns = int(p)
    return -turns if clockwise else turns


def arc_geometry(state: State, params, start3, target, clockwise: bool):
    """(centre in the frame (3), signed turns) of the arc from ``start3`` to ``target``,
    checked with LinuxCNC's tolerances in program units; raises ``LineError``."""
    if state.arc_not_allowed:
        raise LineError(0, msg("The move just after exiting cutter compensation mode must be straight, "
                               "not an arc"))
    _arc_words(state, params)
    a1, a2, a3 = PLANE_AXES[state.plane]
    k = state.scale
    off = state.offsets
    if off.rotation and state.plane != 0:
        raise LineError(0, msg("arcs in G18/G19 are not supported in a rotated coordinate system (G10 L2 R)"))
    p_start, p_end = off.to_program(start3), off.to_program(target)
    start = (p_start[a1] / k, p_start[a2] / k)
    end = (p_end[a1] / k, p_end[a2] / k)
    if "R" in params:
        if abs(params["R"].value) * k > LIMIT_MM:
            raise LineError(params["R"].column, msg("arc radius out of range"))
        center, why = r_center(start, end, params["R"].value, clockwise, state.inch)
    else:
        o1 = params[_OFFSETS[a1]].value if _OFFSETS[a1] in params else 0.0
        o2 = params[_OFFSETS[a2]].value if _OFFSETS[a2] in params else 0.0
        if max(abs(o1), abs(o2)) * k > LIMIT_MM:
            raise LineError(_col(params, _OFFSETS), msg("arc centre out of range"))
        center = (o1, o2) if state.ijk_absolute else (start[0] + o1, start[1] + o2)
        why = ijk_error(start, end, center, state.inch)
    if why:
        raise LineError(0, why)
    program_center = list(p_start)
    program_center[a1], program_center[a2] = center[0] * k, center[1] * k
    center3 = off.to_frame(program_center)
    center3[a3] = start3[a3]
    return center3, _turns(params, clockwise)


def _arc(state: State, params, target, line_no: int, ops: OpBuffer, clockwise: bool) -> None:
    center3, turn = arc_geometry(state, params, state.pos, target, clockwise)
    kind = ARC_CW if clockwise else ARC_CCW
    ops.add(line_no, kind, target, center3, state.plane, turn, state.feed)


def _straight_or_arc(state: State, motion: int, groups, params, line_no: int, ops: OpBuffer) -> None:
    machine = groups.get("nonmodal", (None,))[0] == 53
    target = _target(state, params, machine)
    if motion in (1, 2, 3) and state.feed == 0:  # rs274ngc and Fanuc controls refuse it alike
        raise LineError(0, msg("Cannot do G{code} with zero feed rate (no F word yet, or F0)", code=motion)
                        if motion == 1 else msg("Cannot make arc with zero feed rate (no F word yet, or F0)"))
    if motion in (0, 1):
        state.arc_not_allowed = False
    if motion in (5, 5.1):
        column = groups["motion"][1].column if "motion" in groups else 0
        run_spline(state, motion, params, target, line_no, ops, column)
    elif state.comp is not None and state.comp.radius > 0:
        state.comp.move(state, motion, params, target, line_no, ops)
    elif motion in (2, 3):
        _arc(state, params, target, line_no, ops, clockwise=motion == 2)
    else:
        ops.add(line_no, RAPID if motion == 0 else FEED, target, value=state.feed)
    state.pos = target


def go_stored(state: State, code: int, params, line_no: int, ops: OpBuffer, column: int) -> None:
    """G28 / G30: a rapid to the point the axis words give (as G0 in the current
    distance mode), then a rapid of those axes (all three without axis words) to the
    stored position (``offsets.stored_position``, machine frame), as rs274ngc moves:
    the axes are replaced in program coordinates (under a rotated system the others
    follow the rotation).
    (rs274ngc also issues the first rapid when no axis is named: it goes nowhere.)"""
    if state.comp is not None:
        raise LineError(column, msg("Cannot use G28 or G30 with cutter radius compensation"))
    named = [i for i, c in enumerate(AXES) if c in params]
    if named or "@" in params or "^" in params:
        target = _target(state, params)
        ops.add(line_no, RAPID, target, value=state.feed)
        state.pos = target
    off = state.offsets
    home = off.to_program(offsets.stored_position(state, code))
    end = off.to_program(state.pos)  # the named axes in program coordinates, as rs274ngc
    for i in named or range(3):
        end[i] = home[i]
    end = off.to_frame(end)
    ops.add(line_no, RAPID, end, value=state.feed)
    state.pos = end


def do_motion(state: State, groups, params, line_no: int, ops: OpBuffer, axes_taken: bool = False) -> None:
    """Dwell and motion of one line (see the module docstring). ``axes_taken``: the axis
    words belong to G10, G92, G52 or G43.1, so the line makes no move."""
    motion = None if axes_taken else _motion_to_be(state, groups, params)
    if not axes_taken:
        _check_usage(motion, params)
    if groups.get("nonmodal", (None,))[0] == 4:
        _dwell(state, params, line_no, ops)
    if motion is None or motion == 80 or not is_cycle(motion):
        state.cycle.initial = None
    if motion is not None and is_cycle(motion):
        run_cycle(state, int(motion), params, line_no, ops)
    elif motion is not None and motion != 80:
        motion = motion if motion == 5.1 else int(motion)
        if motion not in (0, 1) or any(c in params for c in MOVE_WORDS):
            _straight_or_arc(state, motion, groups, params, line_no, ops)
    if "motion" in groups:
        code = groups["motion"][0]
        state.motion = None if code == 80 else code if code == 5.1 else int(code)
