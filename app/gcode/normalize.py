"""Normaliser: interpreted rows -> the machine's dialect (DESIGN.md).

Output lines, each at most 80 characters:

- ``G00``/``G01`` with the axes whose rounded value changed and, for G01, ``F`` when it
  changed. The machine starts a job where it stands: an axis the program has not set
  yet is left out (``start.py``: ``G00 Z-5`` first is ``G00 Z-5``, X and Y stay), the
  first line that sets it names it; a move that changes nothing repeats a set axis, or
  is ``G04 P0`` while no axis is set;
- ``G02``/``G03 X Y I J [Z] [F]`` for arcs in the XY plane. **I and J are relative to
  the start point of the arc** (the device's current position, rounded as sent), the
  device's convention; X and Y are always given. Z appears when it changes (a helix);
- arcs in the XZ or YZ plane, arcs of more than one turn, arcs whose rounded
  numbers would no longer pass LinuxCNC's circle check and arcs of a radius over
  ``MAX_ARC_RADIUS`` (docs/protocol.md: nearly straight, and a single-precision firmware
  would place their points millimetres off) become ``G01`` chords that stay within
  ``arc_tolerance_mm`` of the true arc (rounding included);
- ``G04 P<seconds>``, ``M03 S<rpm>`` (``M4`` was already turned into M3; a spindle
  started with no S runs at the profile's no-load rpm), ``M05``, ``M02`` (also for M30).

Numbers are absolute millimetres rounded to 0.001 with trailing zeros dropped.
Pauses (M0, M1, M6) are not device lines: they are listed as (device index, message)
so the job can stop before that line. ``plan`` decides, vectorised, how many device
lines each row becomes (the device index of every move is known without formatting);
``render.render`` writes the text. Normalising the output again gives the same lines.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .arcs import RADIUS_TOL, segments, spiral_refused, sweep
from .numbers import rounded
from .ops import ARC_CCW, ARC_CW, PLANE_AXES, XY, Ops
from .threads import each_on

ROUNDING = 0.001
MAX_ARC_RADIUS = 1000.0  # mm: R * 2**-24 (float32) times the few operations of a point stays
# well below ROUNDING; Gcodetools writes nearly straight biarcs of radius up to 59 km
BLOCK = 1 << 16  # arcs checked at a time (the check is per arc: the same result in any blocks)


@dataclass
class Plan:
    """Per row: device lines it becomes, first device index, and whether it is chords."""

    count: np.ndarray
    first: np.ndarray
    chords: np.ndarray
    total: int


def _rounded(values: np.ndarray) -> np.ndarray:
    """``numbers.rounded``, faster for finite values below 2**50 thousandths (arc
    coordinates are): the whole float rint(x * 1000) needs no trip through int64;
    + 0.0 turns -0 into 0."""
    if not len(values) or not np.abs(values).max() < 2.0**50 / 1000.0:  # NaN too
        return rounded(values)
    out = values * 1000.0
    np.rint(out, out=out)
    out /= 1000.0
    out += 0.0
    return out


def _arc_ok_rounded(start, end, center) -> np.ndarray:
    """True where the arc can be sent as an arc: with its numbers rounded as sent, it
    passes the circle check, and its radius is at most ``MAX_ARC_RADIUS``. (XY arcs only;
    worked out a column at a time: numpy runs an (n, 2) slice of (n, 3) rows as a loop
    of two.)"""
    sx, sy, ex, ey = (_rounded(points[:, axis]) for points in (start, end) for axis in (0, 1))
    cx, cy = _rounded(center[:, 0] - sx), _rounded(center[:, 1] - sy)
    cx += sx
    cy += sy
    r1, r2 = np.hypot(cx - sx, cy - sy), np.hypot(cx - ex, cy - ey)
    ok = (r1 >= RADIUS_TOL[False]) & (r2 >= RADIUS_TOL[False]) & (r1 <= MAX_ARC_RADIUS)
    ok &= ~spiral_refused(np.abs(r1 - r2), np.maximum(r1, r2), False)
    # a short arc whose ends round together would become a full circle on the device
    same = (sx == ex) & (sy == ey)  # equal thousandths
    full = (start[:, 0] == end[:, 0]) & (start[:, 1] == end[:, 1])
    return ok & (~same | full)


def _axes(ops: Ops, rows) -> np.ndarray:
    return np.array(PLANE_AXES)[ops.plane[rows]]


def plan(ops: Ops, tolerance: float, threads: int = 1) -> Plan:
    """How many device lines each row becomes (vectorised; the arcs' check, a block at a
    time, on two threads when ``threads`` is 2 and there are several blocks: a load whose
    thread only waits for the plan)."""
    kind = ops.kind
    count = np.ones(len(kind), np.int64)  # a PAUSE row is one stop line (M00, M01, M06 T..)
    chords = np.zeros(len(ops), bool)
    arcs = np.flatnonzero((kind == ARC_CW) | (kind == ARC_CCW))
    if len(arcs):
        ok = (ops.plane[arcs] == XY) & (np.abs(ops.turn[arcs]) == 1)
        starts = ops.starts()

        def check(a: int) -> None:  # a block at a time: small temporaries
            rows = arcs[a : a + BLOCK]
            ok[a : a + BLOCK] &= _arc_ok_rounded(starts.take(rows, axis=0), ops.end.take(rows, axis=0),
                                                 ops.center.take(rows, axis=0))

        each_on(threads)(check, range(0, len(arcs), BLOCK), "plan")
        chords[arcs[~ok]] = True
        bad = arcs[~ok]
        if len(bad):
            count[bad] = _chord_counts(ops, bad, tolerance)
    first = np.cumsum(count) - count
    return Plan(count, first, chords, int(count.sum()))


def _plane_pts(ops: Ops, rows, pts3):
    ax = _axes(ops, rows)
    idx = np.arange(len(rows))
    return np.stack([pts3[idx, ax[:, 0]], pts3[idx, ax[:, 1]]], axis=1)


def _chord_counts(ops: Ops, rows, tolerance: float) -> np.ndarray:
    start = ops.starts()[rows]
    s, e, c = (_plane_pts(ops, rows, p) for p in (start, ops.end[rows], ops.center[rows]))
    r = np.maximum(np.hypot(*(s - c).T), np.hypot(*(e - c).T))
    return segments(r, sweep(s, e, c, ops.turn[rows]), tolerance - ROUNDING)
