"""What each G and M code means to the interpreter: per-code tables, no logic.

``G_CODES`` maps a code to (modal group, setting name, value); ``M_CODES`` likewise.
``REFUSED_G`` / ``REFUSED_M`` / ``REFUSED_LETTERS`` name what this machine cannot run,
with the reason the interpreter reports (line and feature). The groups follow
rs274ngc's modal groups; a line may hold one code of each.
"""

from __future__ import annotations

from app.i18n import N_, msg

CYCLES = (73, 81, 82, 83, 85, 89)

G_CODES: dict[float, tuple[str, str | None, object]] = {
    0: ("motion", "motion", 0),
    1: ("motion", "motion", 1),
    2: ("motion", "motion", 2),
    3: ("motion", "motion", 3),
    80: ("motion", "motion", None),
    5: ("motion", "motion", 5),
    5.1: ("motion", "motion", 5.1),
    **{float(c): ("motion", "motion", c) for c in CYCLES},
    4: ("nonmodal", "dwell", True),
    10: ("nonmodal", "setup", True),
    52: ("nonmodal", "local", True),
    53: ("nonmodal", "machine", True),
    28: ("nonmodal", "home", True),
    28.1: ("nonmodal", "home", True),
    30: ("nonmodal", "home", True),
    30.1: ("nonmodal", "home", True),
    92: ("nonmodal", "g92", True),
    92.1: ("nonmodal", "g92", True),
    92.2: ("nonmodal", "g92", True),
    92.3: ("nonmodal", "g92", True),
    17: ("plane", "plane", 0),
    18: ("plane", "plane", 1),
    19: ("plane", "plane", 2),
    20: ("units", "inch", True),
    21: ("units", "inch", False),
    90: ("distance", "absolute", True),
    91: ("distance", "absolute", False),
    90.1: ("ijk", "ijk_absolute", True),
    91.1: ("ijk", "ijk_absolute", False),
    94: ("feedmode", None, None),
    40: ("cutter", None, None),
    41: ("cutter", None, None),
    42: ("cutter", None, None),
    41.1: ("cutter", None, None),
    42.1: ("cutter", None, None),
    43: ("toollength", None, None),
    43.1: ("toollength", None, None),
    49: ("toollength", None, None),
    **{float(g): ("coords", None, g - 53) for g in range(54, 60)},
    59.1: ("coords", None, 7),
    59.2: ("coords", None, 8),
    59.3: ("coords", None, 9),
    61: ("pathmode", None, None),
    61.1: ("pathmode", None, None),
    64: ("pathmode", None, None),
    98: ("retract", "retract_r", False),
    99: ("retract", "retract_r", True),
    8: ("lathe", None, None),
}

_SPINDLE_SYNC = N_("spindle-synchronised motion needs a spindle encoder in the motion loop, "
                    "which this machine has not")
REFUSED_G: dict[float, str] = {
    7: N_("G7 (diameter mode) is a lathe code: this machine is a mill"),
    33: _SPINDLE_SYNC,
    33.1: _SPINDLE_SYNC,
    76: _SPINDLE_SYNC,
    **{g: N_("probing (G38.x) needs a probe input, which this machine has not")
       for g in (38.2, 38.3, 38.4, 38.5)},
    70: N_("G70 (finishing cycle) is a lathe code: this machine is a mill"),
    71: N_("G71 (roughing cycle) is a lathe code: this machine is a mill"),
    71.1: N_("G71.1 (roughing cycle) is a lathe code: this machine is a mill"),
    71.2: N_("G71.2 (roughing cycle) is a lathe code: this machine is a mill"),
    72: N_("G72 (facing cycle) is a lathe code: this machine is a mill"),
    72.1: N_("G72.1 (facing cycle) is a lathe code: this machine is a mill"),
    72.2: N_("G72.2 (facing cycle) is a lathe code: this machine is a mill"),
    74: N_("G74 (left-hand tapping) needs a spindle that reverses in step with Z: this one cannot"),
    84: N_("G84 (tapping) needs a spindle that reverses in step with Z: this one cannot"),
    86: N_("G86 (boring, spindle stop) needs a spindle stop and restart inside the cycle: "
           "not on this machine"),
    87: N_("G87 (back boring) needs spindle orientation: not on this machine"),
    88: N_("G88 (boring, manual retract) needs an operator retract inside the cycle: not on this machine"),
    93: N_("inverse-time feed G93 is not supported (use G94)"),
    95: N_("feed per revolution G95 is not supported (use G94)"),
    96: N_("constant surface speed G96 is not supported (use G97)"),
    43.2: N_("additive tool length offset G43.2 is not supported (use G43 or G43.1)"),
    5.2: N_("NURBS G5.2 are not supported (G5 cubic and G5.1 quadratic splines are)"),
    5.3: N_("NURBS G5.3 are not supported (G5 cubic and G5.1 quadratic splines are)"),
}

M_CODES: dict[int, tuple[str, str]] = {
    0: ("stop", "pause"),
    1: ("stop", "pause"),
    2: ("stop", "end"),
    30: ("stop", "end"),
    60: ("stop", "pause"),
    3: ("spindle", "cw"),
    4: ("spindle", "ccw"),
    5: ("spindle", "off"),
    6: ("toolchange", "change"),
    61: ("toolchange", "set"),
    7: ("coolant", "coolant"),
    8: ("coolant", "coolant"),
    9: ("coolant", "coolant"),
    70: ("modal_state", "save"),
    71: ("modal_state", "invalidate"),
    72: ("modal_state", "restore"),
    73: ("modal_state", "autorestore"),
}

ALLOWED_LETTERS = set("GMXYZIJKFSPRTNDHLQ@^")
REFUSED_LETTERS = {
    **{c: msg("axis {axis} is not on this machine (it has X, Y and Z)", axis=c) for c in "ABCUVW"},
    "E": msg("{letter} words are not supported", letter="E"),
}
AXES = "XYZ"
MOVE_WORDS = "XYZ@^"  # the words that make a line move (polar @ radius, ^ angle)
