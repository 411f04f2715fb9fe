"""What the machine accepts as a value (docs/protocol.md, "Machine conventions").

The machine refuses what the host's loader refuses (``app/gcode/limits.py`` and the
interpreter's coordinate limit), with its own copy of the numbers: ``backend_sim``
never imports ``app.gcode``, as a firmware would not. ``word_problem`` is the check of
a word of a ``D`` line; ``distance_problem``/``feed_problem``/``rpm_problem`` those of
``JOG`` and ``SPINDLE``; each returns the text of a ``BAD_VALUE`` refusal or None.
``set_value`` is the grammar of a ``SET`` value (choices are one plain digit).
"""

from __future__ import annotations

MAX_NUMBER = 1e9  # every number: |value| below this
MAX_COORD_MM = 1e6  # X Y Z I J, work mm
MIN_FEED = 0.001  # mm/min; a feed is > 0 and at least this
MAX_DWELL_S = 3600.0  # G04 P<seconds>
CHOICES = {"CHECK": "01", "OPTSTOP": "01", "STOPSPINDLE": "01", "AFTERJOB": "0123"}
COORDINATES = "XYZIJ"


def _size_problem(letter: str, value: float) -> str | None:
    if not abs(value) < MAX_NUMBER:
        return f"{letter}{value:.12g}: a number must be below {MAX_NUMBER:.0f} in size"
    return None


def word_problem(letter: str, value: float) -> str | None:
    """What is wrong with the word ``letter value`` of a device line, or None."""
    problem = _size_problem(letter, value)
    if problem:
        return problem
    if letter in COORDINATES and abs(value) > MAX_COORD_MM:
        return f"{letter}{value:.12g}: beyond {MAX_COORD_MM:.0f} mm"
    if letter == "F" and 0 < value < MIN_FEED:
        return f"feed F{value:.12g} is below {MIN_FEED:g} mm/min"
    if letter == "P" and value > MAX_DWELL_S:
        return f"dwell P{value:.12g} is longer than {MAX_DWELL_S:.0f} s"
    return None


def distance_problem(value: float) -> str | None:
    if abs(value) > MAX_COORD_MM:
        return f"distance {value:.12g}: beyond {MAX_COORD_MM:.0f} mm"
    return None


def feed_problem(value: float) -> str | None:
    if not MIN_FEED <= value < MAX_NUMBER:
        return f"feed {value:.12g}: {MIN_FEED:g} mm/min to below {MAX_NUMBER:.0f}"
    return None


def rpm_problem(value: float) -> str | None:
    if not 0 <= value < MAX_NUMBER:
        return f"rpm {value:.12g}: 0 to below {MAX_NUMBER:.0f}"
    return None


def set_value(name: str, text: str) -> float | None:
    """A choice's value: exactly one digit, no sign, point or leading zero (ValueError,
    ``BAD_ARGS``, otherwise); None for a name that takes a number (the number grammar
    and the name's range apply)."""
    choices = CHOICES.get(name)
    if choices is None:
        return None
    if len(text) != 1 or text not in "0123456789":
        raise ValueError(f"{name} {text[:20]!r}: one digit, one of {' '.join(choices)}")
    return float(text)


def choice_problem(name: str, text: str) -> str | None:
    """A digit that is not among the choices of ``name`` (``BAD_PARAM``), or None."""
    choices = CHOICES.get(name)
    if choices is not None and text not in choices:
        return f"{name} {text}: one of {' '.join(choices)}"
    return None
