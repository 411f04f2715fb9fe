"""Warnings about moves the machine can run but the operator should know of.

- out of the envelope: a move (or the bulge of an arc) past the machine's travel,
  with the profile's default work offset: ``line 12, column 5: X+ beyond travel
  (152.300 > 150)``, in work coordinates, one per line, axis and direction;
- feed moves at feed 0 (no F yet, or F0): LinuxCNC would refuse them; here they warn
  and the time estimate uses the maximum feed;
- a spindle speed the motor cannot reach (``MachineProfile.max_spindle_rpm``: no-load speed at the
  supply minus the bridge drop): ``S9000 is beyond the spindle's maximum (3750 rpm)``.
Vectorised over all rows; at most ``Report.limit`` of each kind are listed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.i18n import N_, msg
from app.profile import MachineProfile

from .arcs import arc_box, in_plane
from .diagnostics import ERROR, Diagnostic, Report
from .lexer import lex_line
from .ops import ARC_CCW, ARC_CW, DWELL, FEED, PLANE_AXES, SPINDLE, Ops

BLOCK = 1 << 16  # rows the envelope check takes at a time


def _column(lines: list[str], line_no: int, letter: str, seen: dict | None = None) -> int:
    """Column of ``letter``'s word on line ``line_no`` (0 when none); ``seen`` keeps each
    line's words, as a line usually earns a warning for X and one for Y."""
    words = None if seen is None else seen.get(line_no)
    if words is None:
        words = lex_line(lines[line_no - 1], line_no).words
        if seen is not None:
            seen[line_no] = words
    return next((w.column for w in words if w.letter == letter), 0)


def _arc_extremes(ops: Ops, rows: np.ndarray):
    """Per arc row, (low xyz, high xyz) of the whole arc."""
    axes = np.array(PLANE_AXES)[ops.plane[rows]]
    return arc_box(ops.starts()[rows], ops.end[rows], ops.center[rows], axes, ops.turn[rows])


def _circle_reach(ops: Ops, rows: np.ndarray, start: np.ndarray, end: np.ndarray):
    """Per arc row (``start``/``end`` its ends), the farthest ``arc_box`` could reach:
    (low, high) xyz of its circle in its plane (centre -/+ radius, computed as
    ``arc_box`` does), the box of its ends on the normal axis."""
    plane = ops.plane[rows]
    one = not len(rows) or (plane == plane[0]).all()  # one plane: whole columns, no gathers
    axes = np.array(PLANE_AXES)[plane[:1] if one else plane]
    center = ops.center.take(rows, axis=0)
    if one:
        s, e, c = (p[:, axes[0, :2]] for p in (start, end, center))
    else:
        s, e, c, _ = in_plane(axes, start, end, center)
    r = np.maximum(np.hypot(*(s - c).T), np.hypot(*(e - c).T))
    reach_low, reach_high = np.minimum(start, end), np.maximum(start, end)
    idx = slice(None) if one else np.arange(len(rows))
    for k in range(2):
        axis = int(axes[0, k]) if one else axes[:, k]
        reach_low[idx, axis] = c[:, k] - r
        reach_high[idx, axis] = c[:, k] + r
    return reach_low, reach_high


def _may_bulge_out(ops: Ops, rows: np.ndarray, limits: np.ndarray) -> np.ndarray:
    """Mask of arcs whose full circle reaches past the travel (the others cannot)."""
    center = ops.center.take(rows, axis=0)
    step = ops.starts().take(rows, axis=0) - center
    radius = np.sqrt(step[:, 0] * step[:, 0] + step[:, 1] * step[:, 1] + step[:, 2] * step[:, 2])
    del step  # the centre shares the normal axis: only the other two reach out
    normal = np.array(PLANE_AXES)[:, 2][ops.plane[rows]]
    out = np.zeros(len(rows), bool)
    for axis in range(3):
        reach = radius * (normal != axis)
        out |= (center[:, axis] - reach < limits[axis, 0]) | (center[:, axis] + reach > limits[axis, 1])
    return out


def _limits(profile: MachineProfile, offset=None) -> np.ndarray:
    """(3, 2) travel limits in work coordinates (``offset``: machine mm of work zero;
    default: the profile's default work offset)."""
    offset = np.array(profile.travel.work_offset() if offset is None else offset, dtype=float)
    return np.array(profile.travel.limits()) - offset[:, None]


def _candidates(ops: Ops, limits: np.ndarray, first: int, stop: int) -> np.ndarray:
    """Moves among rows ``first..stop`` that may leave the travel: an end outside, or an
    arc whose circle reaches out."""
    kind, end = ops.kind[first:stop], ops.end[first:stop]
    out = np.zeros(len(kind), bool)
    for axis in range(3):
        out |= (end[:, axis] < limits[axis, 0]) | (end[:, axis] > limits[axis, 1])
    out &= kind <= ARC_CCW
    arcs = np.flatnonzero((kind == ARC_CW) | (kind == ARC_CCW))
    out[arcs[_may_bulge_out(ops, arcs + first, limits)]] = True
    return np.flatnonzero(out) + first


def _violations(ops: Ops, limits: np.ndarray, shown: int = 1):
    """Per axis and direction past ``limits``: (axis name, sign, limit, rows, values,
    count), in work coordinates: the first ``shown`` rows in program order with their
    exact values (the arcs' quadrant points are worked out only for arcs the ends of
    which do not already decide, and for those shown), and how many rows there are in
    all. Rows are taken ``BLOCK`` at a time, so memory stays small whatever the
    program's size (a file mostly outside the travel keeps no list of its rows)."""
    found: dict[tuple[int, str], list] = {}
    for first in range(0, len(ops), BLOCK):
        for axis, sign, limit, rows, values in _block(ops, limits, shown, first, first + BLOCK):
            entry = found.setdefault((axis, sign), [limit, [], [], 0])
            room = max(shown - sum(len(r) for r in entry[1]), 0)
            entry[1].append(rows[:room].copy())  # a copy: a view would keep the block's rows
            entry[2].append(values[:room].copy())
            entry[3] += len(rows)
    for axis in range(3):
        for sign in "+-":
            if (axis, sign) in found:
                limit, rows, values, count = found[axis, sign]
                yield "XYZ"[axis], sign, limit, np.concatenate(rows), np.concatenate(values), count


def _block(ops: Ops, limits: np.ndarray, shown: int, first: int, stop: int) -> list:
    """``_violations`` of rows ``first..stop``: (axis, sign, limit, rows, values)."""
    moves = _candidates(ops, limits, first, stop)
    if not len(moves):
        return []
    end, start = ops.end.take(moves, axis=0), ops.starts().take(moves, axis=0)
    kind = ops.kind[moves]
    is_arc = (kind == ARC_CW) | (kind == ARC_CCW)
    line_still = (end == start) & ~is_arc[:, None]  # an axis a line leaves alone is not news
    low, high = np.where(line_still, np.inf, end), np.where(line_still, -np.inf, end)
    np.minimum(low, start, out=low, where=is_arc[:, None])  # an arc: the box of its ends,
    np.maximum(high, start, out=high, where=is_arc[:, None])  # a bound of the arc's box
    arcs = np.flatnonzero(is_arc)
    exact = np.ones(len(moves), bool)
    if len(arcs):
        arc_start, arc_end = start.take(arcs, axis=0), end.take(arcs, axis=0)
        arc_low, arc_high = low.take(arcs, axis=0), high.take(arcs, axis=0)
        reach_low, reach_high = _circle_reach(ops, moves[arcs], arc_start, arc_end)
        lo, hi = limits[:, 0] - 1e-9, limits[:, 1] + 1e-9
        open_ = ((arc_high <= hi) & (reach_high > hi)) | ((arc_low >= lo) & (reach_low < lo))
        exact[arcs] = False
        _exact_arcs(ops, moves, arcs[open_.any(axis=1)], low, high, exact)
    found = []
    for axis, (lo, hi) in enumerate(limits.tolist()):
        for sign, values, limit, beyond in (("+", high, hi, np.greater), ("-", low, lo, np.less)):
            hit = np.flatnonzero(beyond(values[:, axis], limit + (1e-9 if sign == "+" else -1e-9)))
            if len(hit):
                found.append((axis, sign, limit, hit))
    if found:
        firsts = _distinct(np.concatenate([hit[:shown] for *_, hit in found]))
        _exact_arcs(ops, moves, firsts[~exact[firsts]], low, high, exact)
    return [(axis, sign, limit, moves[hit], (high if sign == "+" else low)[hit, axis])
            for axis, sign, limit, hit in found]


def _distinct(values: np.ndarray) -> np.ndarray:
    """``np.unique(values)`` without importing ``numpy.ma`` (``np.unique`` does, 6 ms)."""
    values = np.sort(values)
    return values[np.concatenate(([True], values[1:] != values[:-1]))] if len(values) else values


def _exact_arcs(ops: Ops, moves: np.ndarray, rows: np.ndarray, low, high, exact) -> None:
    """The whole-arc box of ``moves[rows]`` into ``low``/``high`` at ``rows``."""
    if len(rows):
        low[rows], high[rows] = _arc_extremes(ops, moves[rows])
        exact[rows] = True


class _MoveRows:
    """A ``Toolpath`` under the names the envelope check reads from ``Ops``: its rows are
    the moves, the events left out."""

    def __init__(self, toolpath, ops: Ops):
        self.kind, self.end, self.center = toolpath.kind, toolpath.end, toolpath.center
        self.plane, self.turn, self._tp, self._ops = toolpath.plane, toolpath.turn, toolpath, ops

    def row_of(self, move: int) -> int:
        """The row of ``Ops`` that move ``move`` comes from."""
        return int(np.flatnonzero(self._ops.kind <= DWELL)[move])

    def __len__(self) -> int:
        return len(self.kind)

    def starts(self) -> np.ndarray:
        return self._tp.start

    def main_lines(self) -> np.ndarray:
        return self._tp.source_line


def _rows(ops: Ops):
    """What the envelope check reads: the ``Toolpath`` that holds the moves (``_MoveRows``)
    once ``ops`` has handed them over, else ``ops``."""
    return ops if ops.handed_to is None else _MoveRows(ops.handed_to, ops)


def _first_row(rows, out: np.ndarray) -> int:
    """The row of ``Ops`` of the first of ``out`` (rows of ``rows``, see ``_rows``)."""
    return int(out[0]) if isinstance(rows, Ops) else rows.row_of(int(out[0]))


def _envelope(ops: Ops, profile: MachineProfile, lines: list[str], report: Report) -> Envelope:
    """The envelope warnings of ``ops``; the rows found are rows of ``ops``."""
    limits, found, seen, ops = _limits(profile), [], {}, _rows(ops)
    for name, sign, limit, out, vals, count in _violations(ops, limits, report.limit):
        found.append((name, sign, limit, _first_row(ops, out), float(vals[0]), count))
        rel = ">" if sign == "+" else "<"
        for row, value in zip(out[: report.limit].tolist(), vals[: report.limit].tolist(), strict=True):
            line = int(ops.main_lines()[row])  # a subprogram's row: its calling line
            report.warning(line, _column(lines, line, name, seen),
                           msg("{axis}{sign} beyond travel ({value:.3f} {rel} {limit:g})", axis=name,
                               sign=sign, value=float(value), rel=rel, limit=float(limit)),
                           f"{name}{sign} beyond travel")
        report.overflow("warning", f"{name}{sign} beyond travel", count - report.limit)
    return Envelope(limits, found)


@dataclass(frozen=True)
class Envelope:
    """What the load's envelope check found, for ``preflight`` to reuse when the work zero
    gives the same limits: per axis and direction (name, sign, limit, first row, its
    value, number of rows), in work coordinates."""

    limits: np.ndarray
    found: list


_LEAVES_ONE = N_("{axis}{sign} leaves the travel by {by:.3f} mm with the work zero at machine "
                 "{axis}{zero:.3f} ({axis} {value:.3f} {rel} {limit:g}); {count} move in all")
_LEAVES_MANY = N_("{axis}{sign} leaves the travel by {by:.3f} mm with the work zero at machine "
                  "{axis}{zero:.3f} ({axis} {value:.3f} {rel} {limit:g}); {count} moves in all")


def preflight(ops: Ops, profile: MachineProfile, lines: list[str], offset,
              known: Envelope | None = None) -> list[Diagnostic]:
    """Errors for moves that would leave the travel with the work zero at ``offset``
    (machine mm, as the machine reports it): the first line per axis and direction,
    by how much, in program order. Empty when the whole program fits. ``known`` is the
    load's ``Envelope`` (``Program.envelope``): used as it is when its limits are these."""
    limits = _limits(profile, offset)
    if known is not None and np.array_equal(known.limits, limits):
        found = known.found  # the load checked these limits already: no second pass
    else:
        moves = _rows(ops)
        found = [(name, sign, limit, _first_row(moves, rows), float(values[0]), count)
                 for name, sign, limit, rows, values, count in _violations(moves, limits)]
    out = []
    for name, sign, limit, row, value, count in found:
        line = int(ops.main_lines()[row])
        k = "XYZ".index(name)
        template = (_LEAVES_ONE if count == 1 else _LEAVES_MANY)
        message = msg(template, axis=name, sign=sign, by=abs(value - limit), zero=float(offset[k]),
                      value=value + float(offset[k]), rel=">" if sign == "+" else "<",
                      limit=float(limit + offset[k]), count=count)
        out.append(Diagnostic(line, _column(lines, line, name) if lines else 0, ERROR, message))
    return sorted(out)


def _feed_zero(ops: Ops, lines: list[str], report: Report) -> None:
    kind = ops.kind
    rows = np.flatnonzero(((kind == FEED) | (kind == ARC_CW) | (kind == ARC_CCW)) & (ops.value <= 0))
    message = msg("feed move at feed 0 (no F word yet, or F0)")
    for row in rows[: report.limit].tolist():
        report.warning(int(ops.main_lines()[row]), 0, message, message)
    report.overflow("warning", message, len(rows) - report.limit)


def _spindle_speed(ops: Ops, profile: MachineProfile, lines: list[str], report: Report) -> None:
    top = profile.max_spindle_rpm()
    rows = np.flatnonzero((ops.kind == SPINDLE) & (ops.value > top + 0.5))
    key = "S beyond the spindle's maximum"
    for row in rows[: report.limit].tolist():
        line = int(ops.main_lines()[row])
        report.warning(line, _column(lines, line, "S"),
                       msg("S{speed:g} is beyond the spindle's maximum ({top:.0f} rpm): it runs at "
                           "{top:.0f} rpm", speed=float(ops.value[row]), top=float(top)), key)

    report.overflow("warning", key, len(rows) - report.limit)


def run(ops: Ops, profile: MachineProfile, lines: list[str], report: Report) -> Envelope:
    """Add the envelope, feed and spindle speed warnings of ``ops`` to ``report``; return
    what the envelope check found (for ``preflight``). Once ``ops`` has handed the moves'
    positions to the Toolpath (``Ops.hand_over``) the envelope check reads them there."""
    envelope = _envelope(ops, profile, lines, report)
    _feed_zero(ops, lines, report)
    _spindle_speed(ops, profile, lines, report)
    return envelope
