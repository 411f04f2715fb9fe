"""The moves as the machine runs them, for the planner's estimate (``estimate.py``).

The normaliser sends some arcs as G01 chords (``normalize.plan``: arcs outside the XY
plane, which the CNC MCU does not run, arcs of more than one turn, arcs whose rounded
numbers would put them off). The machine's planner then sees each chord as a block of
its own: a straight line at the arc's feed, with a junction at every chord's end. So
the estimate times those chords, each on its own device line, and not the arc the
program wrote (whose radius and tangents are in another plane than the planner's).
"""

from __future__ import annotations

import numpy as np

from .ops import ARC_CCW, ARC_CW, FEED
from .render import chord_ends
from .toolpath import Toolpath


def as_sent(toolpath: Toolpath, plan, tolerance: float) -> tuple[Toolpath, np.ndarray | None]:
    """(the moves the planner is sent, the row each of ``toolpath``'s rows begins at among
    them, or None when they are row for row: ``toolpath`` itself when the ``plan``, if
    any, sends no arc as chords; with its arcs of one chord made lines, which costs a copy
    of two columns; with every arc of several chords replaced by its chords, which copies
    every column). ``tolerance``: the profile's arc tolerance, as rendered."""
    tp, (rows, count) = toolpath, _chorded_rows(toolpath, plan)
    if not len(rows):
        return tp, None
    if (count == 1).all():  # (Gcodetools' nearly straight arcs, sent as one G01 each)
        kind, length = tp.kind.copy(), tp.length.copy()
        kind[rows], length[rows] = FEED, _lengths(tp.start[rows], tp.end[rows])
        return Toolpath(tp.start, tp.end, kind, tp.center, tp.plane, tp.turn, tp.source_line, tp.device_index,
                        [tp.feed, length, tp.time]), None
    ends = chord_ends(tp.start[rows], tp.end[rows], tp.center[rows], tp.plane[rows], tp.turn[rows], tolerance)
    if int(count.sum()) != len(ends):  # cannot happen (the same arcs, the same rule): time the arcs
        return tp, None
    per_row = np.ones(len(tp), np.int64)
    per_row[rows] = count
    source = np.repeat(np.arange(len(tp)), per_row)  # the toolpath's row of each move sent
    at = np.flatnonzero(np.repeat(np.isin(np.arange(len(tp)), rows), per_row))  # the chords, as ``ends``
    nth = np.arange(len(at)) - np.repeat(np.cumsum(count) - count, count)  # each chord's place in its arc
    end, start = tp.end[source], tp.start[source]
    end[at] = ends
    later = at[nth > 0]
    start[later] = end[later - 1]  # a chord starts where the one before it ends
    kind, device, length = tp.kind[source], tp.device_index[source], tp.length[source]
    kind[at] = FEED
    device[at] += nth  # the arc's j-th chord is its j-th device line
    length[at] = _lengths(start[at], end[at])
    return Toolpath(start, end, kind, tp.center[source], tp.plane[source], tp.turn[source],
                    tp.source_line[source], device, [tp.feed[source], length, tp.time[source]]), \
        np.cumsum(per_row) - per_row


def _lengths(start: np.ndarray, end: np.ndarray) -> np.ndarray:
    return np.sqrt(np.square(end - start).sum(axis=1))


def _chorded_rows(tp: Toolpath, plan) -> tuple[np.ndarray, np.ndarray]:
    """The toolpath's rows (arcs) that the plan sends as chords, found from the plan's
    side (a few rows, by their first device line: the toolpath's rows are in device line
    order), and the plan's count of chords for each."""
    if plan is None or not len(tp) or not plan.chords.any():
        return np.empty(0, np.int64), np.empty(0, np.int64)
    chorded = np.flatnonzero(plan.chords)
    lines = plan.first[chorded]
    rows = np.minimum(np.searchsorted(tp.device_index, lines), len(tp) - 1)
    found = (tp.device_index[rows] == lines) & ((tp.kind[rows] == ARC_CW) | (tp.kind[rows] == ARC_CCW))
    return rows[found], plan.count[chorded[found]]


def fold(row_seconds: np.ndarray, begins: np.ndarray) -> np.ndarray:
    """Seconds per row of the toolpath ``as_sent`` was given: its chords' seconds summed."""
    return np.add.reduceat(row_seconds, begins) if len(begins) else row_seconds[:0]
