"""What each G and M code means to the interpreter: per-code tables, no logic.

``G_CODES`` maps a code to (modal group, setting name, value); ``M_CODES`` likewise.
``REFUSED_G`` / ``REFUSED_LETTERS`` name what this machine cannot run, with the
reason the interpreter reports (line and feature).
"""

from __future__ import annotations

from app.i18n import N_, msg

G_CODES: dict[float, tuple[str, str, object]] = {
    0: ("motion", "motion", 0),
    1: ("motion", "motion", 1),
    2: ("motion", "motion", 2),
    3: ("motion", "motion", 3),
    80: ("motion", "motion", None),
    4: ("nonmodal", "dwell", True),
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
    49: ("toollength", None, None),
    61: ("pathmode", None, None),
    61.1: ("pathmode", None, None),
    64: ("pathmode", None, None),
}

_CYCLES = N_("canned cycles (G81-G89) are not supported")
REFUSED_G: dict[float, str] = {
    **{float(g): _CYCLES for g in range(81, 90)},
    73: _CYCLES,
    41: N_("cutter radius compensation (G41/G42) is not supported"),
    41.1: N_("cutter radius compensation (G41/G42) is not supported"),
    42: N_("cutter radius compensation (G41/G42) is not supported"),
    42.1: N_("cutter radius compensation (G41/G42) is not supported"),
    92: N_("G92 coordinate offsets are not supported yet"),
    92.1: N_("G92 coordinate offsets are not supported yet"),
    92.2: N_("G92 coordinate offsets are not supported yet"),
    92.3: N_("G92 coordinate offsets are not supported yet"),
    **{float(g): N_("work offsets G54-G59 are not supported yet") for g in range(54, 60)},
    59.1: N_("work offsets G54-G59 are not supported yet"),
    59.2: N_("work offsets G54-G59 are not supported yet"),
    59.3: N_("work offsets G54-G59 are not supported yet"),
    93: N_("inverse-time feed G93 is not supported (use G94)"),
    95: N_("feed per revolution G95 is not supported (use G94)"),
    28: N_("G28 (go to a stored position) is not supported"),
    30: N_("G30 (go to a stored position) is not supported"),
    53: N_("G53 machine-coordinate moves are not supported"),
    43: N_("tool length offsets (G43) are not supported: this machine has one tool"),
    10: N_("G10 (set offsets and tables) is not supported"),
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
    7: ("coolant", "coolant"),
    8: ("coolant", "coolant"),
    9: ("coolant", "coolant"),
}

ALLOWED_LETTERS = set("GMXYZIJKFSPRTN")
REFUSED_LETTERS = {
    **{c: msg("axis {axis} is not on this machine (it has X, Y and Z)", axis=c) for c in "ABCUVW"},
    **{c: msg("{letter} words are not supported", letter=c) for c in "DEHLQ"},
}
AXES = "XYZ"
