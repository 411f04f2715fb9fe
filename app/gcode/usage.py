"""Which word a line may hold, given its codes: rs274ngc's ``check_other_codes``.

Every letter other than G, M, N, F, S, T must have a code on the line (or a modal
motion) that uses it; otherwise the line is refused with the word's column and
rs274's reason. Returns whether the axis words belong to G10, G92, G52, G28, G30 or
G43.1 (then the line makes no move of its motion mode).
"""

from __future__ import annotations

from app.i18n import N_, msg

from .errors import LineError
from .words import CYCLES, MOVE_WORDS

_AXIS_USERS = {10: "G10", 52: "G52", 92: "G92", 28: "G28", 30: "G30"}


def _motion_to_be(state, groups, params, axes_taken: bool):
    if "motion" in groups:
        return groups["motion"][0]
    if not axes_taken and any(c in params for c in MOVE_WORDS):
        return state.motion
    return None


def _axes_taken(groups, params) -> bool:
    nonmodal = groups.get("nonmodal", (None,))[0]
    taken = nonmodal in _AXIS_USERS or groups.get("toollength", (None,))[0] == 43.1
    if taken and "motion" in groups and any(c in params for c in MOVE_WORDS):
        raise LineError(groups["motion"][1].column, msg("Cannot use two G codes that both use axis values"))
    return taken


def _refuse(params, letter: str, users: str) -> None:
    raise LineError(params[letter].column, msg("{letter} word with no {users} to use it", letter=letter,
                                               users=msg(users)))


def check_usage(state, groups, mgroups, params) -> bool:
    """Refuse a word nothing on the line uses; True when G10/G92/G52/G43.1 take the axes."""
    taken = _axes_taken(groups, params)
    motion = _motion_to_be(state, groups, params, taken)
    nonmodal = groups.get("nonmodal", (None,))[0]
    arc, cycle = motion in (2, 3), motion in CYCLES
    spline = motion in (5, 5.1)
    g10 = nonmodal == 10
    pathmode = groups.get("pathmode", (None,))[0] == 64
    m61 = mgroups.get("toolchange", (None,))[0] == 61
    if nonmodal == 53:
        if motion not in (0, 1):
            raise LineError(groups["nonmodal"][1].column, msg("Must use G0 or G1 with G53"))
        distance = groups.get("distance", (None,))[0]
        if distance == 91 or distance is None and not state.absolute:
            raise LineError(groups["nonmodal"][1].column, msg("Cannot use G53 incremental"))
        if state.comp is not None:
            raise LineError(groups["nonmodal"][1].column,
                            msg("Cannot use G53 with cutter radius compensation on"))
        if "@" in params or "^" in params:
            raise LineError(groups["nonmodal"][1].column, msg("Cannot use polar coordinates with G53"))
    if ("@" in params or "^" in params) and ("X" in params or "Y" in params):
        letter = "X" if "X" in params else "Y"
        raise LineError(params[letter].column, msg("Cannot specify both polar coordinate and {letter} word",
                                                   letter=letter))

    for letter in "IJK":
        if letter in params and not (arc or spline and letter != "K"):
            _refuse(params, letter, N_("G2, G3, G5 or G5.1"))
    if "R" in params and not (arc or cycle or g10):
        _refuse(params, "R", N_("G2, G3, G10 or canned cycle"))
    if "P" in params and not (arc or cycle or g10 or pathmode or nonmodal == 4 or motion == 5):
        _refuse(params, "P", N_("G4, G2, G3, G5, G10, G64 or canned cycle"))
    if "Q" in params and not (motion in (73, 83, 5) or m61 or pathmode):
        _refuse(params, "Q", N_("G5, G64, G73, G83 or M61"))
    if "L" in params and not (cycle or g10):
        _refuse(params, "L", N_("G10 or canned cycle"))
    if "D" in params and groups.get("cutter", (None,))[0] not in (41, 42, 41.1, 42.1):
        _refuse(params, "D", N_("G41, G41.1, G42 or G42.1"))
    if "H" in params and groups.get("toollength", (None,))[0] != 43:
        _refuse(params, "H", "G43")
    return taken
