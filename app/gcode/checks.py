"""Warnings about moves the machine can run but the operator should know of.

- out of the envelope: a move (or the bulge of an arc) past the machine's travel,
  with the profile's default work offset: ``line 12, column 5: X+ beyond travel
  (152.300 > 150)``, in work coordinates, one per line, axis and direction;
- feed moves at feed 0 (no F yet, or F0): LinuxCNC would refuse them; here they warn
  and the time estimate uses the maximum feed.
Vectorised over all rows; at most ``Report.limit`` of each kind are listed.
"""

from __future__ import annotations

import numpy as np

from app.i18n import msg
from app.profile import MachineProfile

from .arcs import arc_box
from .diagnostics import Report
from .lexer import lex_line
from .ops import ARC_CCW, ARC_CW, FEED, PLANE_AXES, Ops


def _column(lines: list[str], line_no: int, letter: str) -> int:
    words = lex_line(lines[line_no - 1], line_no).words
    return next((w.column for w in words if w.letter == letter), 0)


def _arc_extremes(ops: Ops, rows: np.ndarray):
    """Per arc row, (low xyz, high xyz) of the whole arc."""
    axes = np.array(PLANE_AXES)[ops.plane[rows]]
    return arc_box(ops.starts()[rows], ops.end[rows], ops.center[rows], axes, ops.turn[rows])


def _may_bulge_out(ops: Ops, rows: np.ndarray, profile: MachineProfile) -> np.ndarray:
    """Mask of arcs whose full circle reaches past the travel (the others cannot)."""
    center = ops.center.take(rows, axis=0)
    step = ops.starts().take(rows, axis=0) - center
    radius = np.sqrt(step[:, 0] * step[:, 0] + step[:, 1] * step[:, 1] + step[:, 2] * step[:, 2])
    del step  # the centre shares the normal axis: only the other two reach out
    normal = np.array(PLANE_AXES)[:, 2][ops.plane[rows]]
    limits = _limits(profile)
    out = np.zeros(len(rows), bool)
    for axis in range(3):
        reach = radius * (normal != axis)
        out |= (center[:, axis] - reach < limits[axis, 0]) | (center[:, axis] + reach > limits[axis, 1])
    return out


def _limits(profile: MachineProfile) -> np.ndarray:
    """(3, 2) travel limits in work coordinates (the default work offset applied)."""
    offset = np.array(profile.travel.work_offset())
    return np.array(profile.travel.limits()) - offset[:, None]


def _candidates(ops: Ops, profile: MachineProfile) -> np.ndarray:
    """Moves that may leave the travel: an end outside, or an arc whose circle reaches out."""
    limits = _limits(profile)
    kind = ops.kind
    out = np.zeros(len(kind), bool)
    for axis in range(3):
        out |= (ops.end[:, axis] < limits[axis, 0]) | (ops.end[:, axis] > limits[axis, 1])
    out &= kind <= ARC_CCW
    arcs = np.flatnonzero((kind == ARC_CW) | (kind == ARC_CCW))
    out[arcs[_may_bulge_out(ops, arcs, profile)]] = True
    return np.flatnonzero(out)


def _envelope(ops: Ops, profile: MachineProfile, lines: list[str], report: Report) -> None:
    moves = _candidates(ops, profile)
    if not len(moves):
        return
    low, high = ops.end[moves].copy(), ops.end[moves].copy()
    still = ops.end[moves] == ops.starts()[moves]  # an axis a move leaves alone is not news
    low[still], high[still] = np.inf, -np.inf
    arcs = np.flatnonzero((ops.kind[moves] == ARC_CW) | (ops.kind[moves] == ARC_CCW))
    if len(arcs):
        low[arcs], high[arcs] = _arc_extremes(ops, moves[arcs])
    for axis, (lo, hi) in enumerate(_limits(profile).tolist()):
        name = "XYZ"[axis]
        for sign, values, limit, beyond in (("+", high, hi, np.greater), ("-", low, lo, np.less)):
            hit = beyond(values[:, axis], limit + (1e-9 if sign == "+" else -1e-9))
            out, vals = moves[hit], values[hit, axis]
            rel = ">" if sign == "+" else "<"
            for row, value in zip(out[: report.limit].tolist(), vals[: report.limit].tolist(), strict=True):
                line = int(ops.line[row])
                report.warning(line, _column(lines, line, name),
                               msg("{axis}{sign} beyond travel ({value:.3f} {rel} {limit:g})", axis=name,
                                   sign=sign, value=float(value), rel=rel, limit=float(limit)),
                               f"{name}{sign} beyond travel")
            report.overflow("warning", f"{name}{sign} beyond travel", len(out) - report.limit)


def _feed_zero(ops: Ops, lines: list[str], report: Report) -> None:
    kind = ops.kind
    rows = np.flatnonzero(((kind == FEED) | (kind == ARC_CW) | (kind == ARC_CCW)) & (ops.value <= 0))
    message = msg("feed move at feed 0 (no F word yet, or F0)")
    for row in rows[: report.limit].tolist():
        report.warning(int(ops.line[row]), 0, message, message)
    report.overflow("warning", message, len(rows) - report.limit)


def run(ops: Ops, profile: MachineProfile, lines: list[str], report: Report) -> None:
    """Add the envelope and feed warnings of ``ops`` to ``report``."""
    _envelope(ops, profile, lines, report)
    _feed_zero(ops, lines, report)
