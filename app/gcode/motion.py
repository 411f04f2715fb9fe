"""Motion words of one line: dwell G4, straight moves G0/G1, arcs G2/G3.

``do_motion`` follows rs274ngc: the motion of a line is its G0-G3 word, or the modal
motion when the line has axis words; I J K R need an arc, P a dwell or an arc (turns),
and axis words with no motion mode (G80, or none yet) are refused. A line with G0/G1
and no axis word sets the mode and moves nowhere. Arc centres are checked with
LinuxCNC's tolerances (``arcs.py``) in the program's units; an arc with no axis word
is a full circle (LinuxCNC 2.9 accepts ``G2 I10``); positions and centres
leave here in millimetres. Raises ``LineError``; changes ``state`` in place.
"""

from __future__ import annotations

from .arcs import ijk_error, r_center
from .limits import dwell_problem, turns_problem
from .ops import ARC_CCW, ARC_CW, DWELL, FEED, PLANE_AXES, PLANE_NAMES, RAPID, OpBuffer
from .state import State
from .words import AXES

LIMIT_MM = 1e6
_OFFSETS = "IJK"


class LineError(Exception):
    """A refused line: a 1-based column (0 = the whole line) and the reason."""

    def __init__(self, column: int, message: str):
        super().__init__(message)
        self.column = column
        self.message = message


def _col(params, letters: str) -> int:
    cols = [params[c].column for c in letters if c in params]
    return min(cols) if cols else 0


def _dwell(state: State, params, line_no: int, ops: OpBuffer) -> None:
    if "P" not in params:
        raise LineError(0, "G4 dwell needs a P word (seconds)")
    seconds = params["P"].value
    if seconds < 0:
        raise LineError(params["P"].column, "G4 dwell time P must not be negative")
    if dwell_problem(seconds):
        raise LineError(params["P"].column, dwell_problem(seconds))
    ops.add(line_no, DWELL, state.pos, value=seconds)


def _motion_to_be(state: State, groups, params) -> int | None:
    has_axis = any(c in params for c in AXES)
    if "motion" in groups:
        return groups["motion"][0]
    return state.motion if has_axis else None


def _check_usage(motion, groups, params) -> None:
    has_axis = any(c in params for c in AXES)
    if has_axis and motion is None or has_axis and motion == 80:
        raise LineError(_col(params, AXES), "axis word with no motion mode (G0, G1, G2 or G3)")
    for letter in "IJKR":
        if letter in params and motion not in (2, 3):
            raise LineError(params[letter].column, f"{letter} word with no G2 or G3 to use it")
    if "P" in params and motion not in (2, 3) and "nonmodal" not in groups:
        raise LineError(params["P"].column, "P word with no G4, G2 or G3 to use it")


def _target(state: State, params) -> list[float]:
    target = list(state.pos)
    for i, c in enumerate(AXES):
        if c in params:
            v = params[c].value * state.scale
            target[i] = v if state.absolute else state.pos[i] + v
            if abs(target[i]) > LIMIT_MM:
                raise LineError(params[c].column, f"{c} coordinate out of range")
    return target


def _arc_words(state: State, params) -> None:
    a3 = PLANE_AXES[state.plane][2]
    name = PLANE_NAMES[state.plane]
    has_ijk = any(c in params for c in _OFFSETS)
    if "R" in params and has_ijk:
        raise LineError(params["R"].column, "arc with both R and I/J/K words")
    if "R" not in params and not has_ijk:
        raise LineError(0, "R, I, J and K words all missing for arc")
    bad = _OFFSETS[a3]
    if "R" not in params and bad in params:
        raise LineError(params[bad].column, f"{bad} word given for arc in {name} plane")


def _turns(params, clockwise: bool) -> int:
    turns = 1
    if "P" in params:
        p = params["P"].value
        if p != int(p) or p < 1:
            raise LineError(params["P"].column, "arc turns P must be a whole number >= 1")
        if turns_problem(p):
            raise LineError(params["P"].column, turns_problem(p))
        turns = int(p)
    return -turns if clockwise else turns


def _arc(state: State, params, target, line_no: int, ops: OpBuffer, clockwise: bool) -> None:
    _arc_words(state, params)
    a1, a2, a3 = PLANE_AXES[state.plane]
    k = state.scale
    start = (state.pos[a1] / k, state.pos[a2] / k)
    end = (target[a1] / k, target[a2] / k)
    if "R" in params:
        if abs(params["R"].value) * k > LIMIT_MM:
            raise LineError(params["R"].column, "arc radius out of range")
        center, why = r_center(start, end, params["R"].value, clockwise, state.inch)
    else:
        o1 = params[_OFFSETS[a1]].value if _OFFSETS[a1] in params else 0.0
        o2 = params[_OFFSETS[a2]].value if _OFFSETS[a2] in params else 0.0
        if max(abs(o1), abs(o2)) * k > LIMIT_MM:
            raise LineError(_col(params, _OFFSETS), "arc centre out of range")
        center = (o1, o2) if state.ijk_absolute else (start[0] + o1, start[1] + o2)
        why = ijk_error(start, end, center, state.inch)
    if why:
        raise LineError(0, why)
    center3 = [0.0, 0.0, 0.0]
    center3[a1], center3[a2], center3[a3] = center[0] * k, center[1] * k, state.pos[a3]
    kind = ARC_CW if clockwise else ARC_CCW
    ops.add(line_no, kind, target, center3, state.plane, _turns(params, clockwise), state.feed)


def do_motion(state: State, groups, params, line_no: int, ops: OpBuffer) -> None:
    """Dwell and motion of one line (see the module docstring)."""
    motion = _motion_to_be(state, groups, params)
    _check_usage(motion, groups, params)
    if "nonmodal" in groups:
        _dwell(state, params, line_no, ops)
    if "motion" in groups:
        code = groups["motion"][0]
        state.motion = None if code == 80 else int(code)
    if motion is None or motion == 80:
        return
    motion = int(motion)
    if motion in (0, 1) and not any(c in params for c in AXES):
        return
    target = _target(state, params)
    if motion in (2, 3):
        _arc(state, params, target, line_no, ops, clockwise=motion == 2)
    else:
        ops.add(line_no, RAPID if motion == 0 else FEED, target, value=state.feed)
    state.pos = target
