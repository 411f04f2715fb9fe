"""The range of every feature and import option, and the work a feature may ask for.

Ranges come from the loader's own limits (``limits.py``: numbers below
``MAX_NUMBER``, feeds of at least ``MIN_FEED``, dwells up to ``MAX_DWELL_S``;
``motion.LIMIT_MM`` for positions), so a program a feature writes is never one the
loader then refuses (``Finf``, ``S1e12``, ``F0``, ``G04 P1000000000``). Every option is
checked before any geometry, non-finite values included; ``check_work`` then refuses,
from the options alone, a feature that would make more rings, layers or moves than
the budget (a tiny tool on a big pocket, a stepover of 0.00001 %), naming the option
to change. The window's fields take their limits from ``RANGES``.
"""

from __future__ import annotations

import math

from app.i18n import N_, msg

from ..limits import MAX_DWELL_S, MAX_NUMBER, MIN_FEED
from ..motion import LIMIT_MM
from .errors import FeatureError

COORD = LIMIT_MM / 10  # mm: positions and sizes (room left for clearance, leads and offsets)
MIN_TOOL = 0.1  # mm: the machine holds the path within 0.1 mm
MIN_STEP = 0.01  # mm: the least stepdown, clearance or pitch (ten of the device's thousandths)
MAX_TOOL_NUMBER = 9999
MAX_HOLES = 10_000
MAX_RINGS = 500  # rings of one roughing layer (or around an island): shapely unions of more take minutes
MAX_LAYERS = 10_000
MAX_MOVES = 2_000_000  # estimated moves of one feature

# name -> (lowest, highest, lowest excluded): the window's spin boxes use the same
RANGES: dict[str, tuple[float, float, bool]] = {
    "x": (-COORD, COORD, False), "y": (-COORD, COORD, False),
    "x1": (-COORD, COORD, False), "y1": (-COORD, COORD, False),
    "x2": (-COORD, COORD, False), "y2": (-COORD, COORD, False),
    "width": (0.0, COORD, True), "height": (0.0, COORD, True), "diameter": (0.0, COORD, True),
    "angle": (-360.0, 360.0, False), "start_angle": (-360.0, 360.0, False),
    "corner_radius": (0.0, COORD, False), "stock": (0.0, COORD, False),
    "pitch": (MIN_STEP, COORD, False), "peck": (0.0, COORD, False), "dwell": (0.0, MAX_DWELL_S, False),
    "count": (1, MAX_HOLES, False), "tool": (0, MAX_TOOL_NUMBER, False),
    "tool_diameter": (MIN_TOOL, COORD, False), "depth": (0.0, COORD, True), "top": (-COORD, COORD, False),
    "stepdown": (MIN_STEP, COORD, False), "stepover": (0.0, 100.0, True),
    "finish_xy": (0.0, COORD, False), "finish_z": (0.0, COORD, False), "clearance": (MIN_STEP, COORD, False),
    "feed": (MIN_FEED, MAX_NUMBER / 10, False), "plunge_feed": (MIN_FEED, MAX_NUMBER / 10, False),
    "rpm": (1.0, MAX_NUMBER / 10, False),
    "scale": (0.0, MAX_NUMBER / 10, True), "cut_z": (-COORD, COORD, False),
}


def within(value, field: str) -> float:
    """``value`` as a float if it is a finite number in ``RANGES[field]``, else
    ``FeatureError(field, ...)`` saying the range."""
    low, high, open_low = RANGES[field]
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = math.nan
    ok = math.isfinite(number) and (number > low if open_low else number >= low) and number <= high
    if not ok:
        template = (N_("must be a number above {low:g} and at most {high:g} (got {value})") if open_low else
                    N_("must be a number from {low:g} to {high:g} (got {value})"))
        raise FeatureError(field, msg(template, low=float(low), high=float(high), value=_shown(value)))
    return number


def whole(value, field: str) -> int:
    """``within`` for a count or a number that must be whole."""
    number = within(value, field)
    if not number.is_integer():
        raise FeatureError(field, msg("must be a whole number (got {value})", value=_shown(value)))
    return int(number)


def _shown(value) -> str:
    try:
        return f"{float(value):g}"
    except (TypeError, ValueError):
        return repr(value)


def check_count(field: str, count: float, most: int, what: str) -> None:
    """Refuse, naming ``field``, a feature that would make ``count`` ``what`` (a core
    message: rings, layers, moves; more than ``most``)."""
    if count > most:
        raise FeatureError(field, msg("would make about {count:,.0f} {what}; at most {most:,} can be made",
                                      count=float(count), what=what, most=most))


def layers_of(cut) -> int:
    """How many depth levels ``cut`` makes (before the geometry)."""
    return math.ceil(cut.depth / cut.stepdown) + 1


def check_work(cut, rings: float, ring_points: float, field: str = "stepover") -> None:
    """The budget of a feature that cuts ``rings`` rings of about ``ring_points`` points
    on every layer (``field``: what to change when there are too many)."""
    check_count("stepdown", layers_of(cut), MAX_LAYERS, msg("layers"))
    check_count(field, rings, MAX_RINGS, msg("rings"))
    check_count(field, layers_of(cut) * max(rings, 1) * max(ring_points, 4), MAX_MOVES, msg("moves"))


def round_points(size: float) -> float:
    """About how many points a ring of a round shape ``size`` mm across has."""
    from .rings import quad_segs

    return 4 * quad_segs(max(size, 0.0) / 2) + 4
