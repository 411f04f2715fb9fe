"""Limits on what a program may ask for, checked at load time (issue 14).

Every number a program holds is finite and below ``MAX_NUMBER`` (the lexer says so
with the line and column); feeds and spindle speeds are not negative, and a feed is
either 0 or at least ``MIN_FEED`` (the machine's resolution: smaller would be sent
as ``F0``); a dwell lasts at most ``MAX_DWELL_S``; an arc turns at most
``MAX_TURNS`` times; one line expands to at most ``MAX_LINE_MOVES`` moves and all
such lines of a program to ``MAX_MOVES`` (``Budget``); a file is at most
``MAX_FILE_BYTES``; ``program_checks`` looks
at the whole program (no moves; wider than the travel). ``word_problem`` is the
word-level rule both the general lexer and the numpy fast path (``bad_rows``) apply.
"""

from __future__ import annotations

import numpy as np

from app.i18n import msg

MAX_NUMBER = 1e9
MIN_FEED = 0.001
MAX_DWELL_S = 3600
MAX_TURNS = 1000
MAX_FILE_BYTES = 256 << 20
MAX_LINE_MOVES = 500_000  # the moves one line may expand to (a canned cycle's repeats and pecks, a spline)
MAX_MOVES = 1_000_000  # the moves all such lines of a program may make (about 3 s with the checks)


class Budget:
    """The moves that lines expanding to many (cycles, splines) have made in the whole
    program: shared by every copy of the interpreter's state. Counted, never timed, so a
    program is refused the same way on every machine."""

    __slots__ = ("made",)

    def __init__(self) -> None:
        self.made = 0

    def spend(self, moves: int, code: str, line_no: int, what: str = "") -> None:
        """Refuse the line (``ValueError`` with the message) before it makes ``moves``
        moves past ``MAX_LINE_MOVES`` or the program's ``MAX_MOVES``; ``what`` names what
        the count is of when it is not moves (pecks, repeats)."""
        counted = msg(" ({what})", what=what) if what else ""
        if moves > MAX_LINE_MOVES:
            raise ValueError(msg("{code} at line {line} would make {moves:,} moves{counted}; the limit "
                                 "is {limit:,}", code=code, line=line_no, moves=moves, counted=counted,
                                 limit=MAX_LINE_MOVES))
        if self.made + moves > MAX_MOVES:
            raise ValueError(msg("{code} at line {line} would bring the moves that cycles and splines "
                                 "make to {moves:,}; the limit for a program is {limit:,}", code=code,
                                 line=line_no, moves=self.made + moves, limit=MAX_MOVES))
        self.made += moves


def plain(value: float) -> str:
    """``value`` without an exponent (``0.0000001``, ``100000000``)."""
    return np.format_float_positional(value, trim="-")


def word_problem(letter: str, value: float) -> str | None:
    """What is wrong with word ``letter value`` whatever the line means, or None."""
    if not abs(value) < MAX_NUMBER:
        return msg("number too large: {letter} must be below {limit:,.0f} in size", letter=letter,
                   limit=MAX_NUMBER)
    if letter == "F" and value < 0:
        return msg("feed F{value} is negative", value=plain(value))
    if letter == "F" and 0 < value < MIN_FEED:
        return msg("feed F{value} is below {least:g} (it would be sent as F0)", value=plain(value),
                   least=MIN_FEED)
    if letter == "S" and value < 0:
        return msg("spindle speed S{value} is negative", value=plain(value))
    return None


def bad_rows(values: dict[str, np.ndarray]) -> np.ndarray:
    """Rows of the fast path's columns (NaN: no word) that ``word_problem`` refuses."""
    columns = list(values.values())
    bad = np.zeros(len(columns[0]), bool)
    with np.errstate(invalid="ignore"):
        for column in columns:
            bad |= np.abs(column) >= MAX_NUMBER
        feed = values["F"]
        bad |= (feed < MIN_FEED) & (feed != 0)
        bad |= values["S"] < 0
    return bad


def dwell_problem(seconds: float) -> str | None:
    if seconds > MAX_DWELL_S:
        return msg("dwell P{value} is longer than {limit} s", value=plain(seconds), limit=MAX_DWELL_S)
    return None


def turns_problem(turns: float) -> str | None:
    if turns > MAX_TURNS:
        return msg("arc turns P{value}: at most {limit}", value=plain(turns), limit=MAX_TURNS)
    return None


def program_checks(toolpath, profile, report) -> None:
    """Whole-program checks: a program with no moves (and no errors) says so; a program
    wider than the machine's travel on an axis (no work offset can fit it: G91 moves
    piling up, wrong units) gets one warning naming that, at the first move that makes
    it so (the envelope check's warnings name each move; positions past ``LIMIT_MM``
    are errors of the interpreter)."""
    if len(toolpath) == 0:
        if not any(d.severity == "error" for d in report.items):
            report.warning(1, 0, msg("the program has no moves (nothing to run)"))
        return
    for axis, (low, high) in enumerate(profile.travel.limits()):
        ends = toolpath.end[:, axis]
        row = _first_too_wide(ends, high - low)
        if row is not None:
            name, lo, hi = "XYZ"[axis], ends[: row + 1].min(), ends[: row + 1].max()
            report.warning(int(toolpath.source_line[row]), 0,
                           msg("the program spans {axis} {lo:.3f}..{hi:.3f} ({span:.3f} mm), more than the "
                               "machine's {axis} travel of {travel:g} mm: no work offset fits it "
                               "(relative G91 moves adding up, or the wrong units?)",
                               axis=name, lo=lo, hi=hi, span=hi - lo, travel=high - low))


def _first_too_wide(ends: np.ndarray, span: float, block: int = 1 << 14) -> int | None:
    """The first row at which the ends so far spread over more than ``span``: the whole
    column first (a program that fits is done in one pass), then ``block`` rows at a
    time up to the block where it happens (the running extremes are the same numbers)."""
    if not len(ends) or not ends.max() - ends.min() > span + 1e-6:
        return None
    low = high = ends[0]
    for first in range(0, len(ends), block):
        part = ends[first : first + block]
        part_low, part_high = min(low, part.min()), max(high, part.max())
        if part_high - part_low > span + 1e-6:
            spread = np.maximum(np.maximum.accumulate(part), high)
            spread -= np.minimum(np.minimum.accumulate(part), low)
            return first + int(np.flatnonzero(spread > span + 1e-6)[0])
        low, high = part_low, part_high
    return None
