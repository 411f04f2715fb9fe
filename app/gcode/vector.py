"""The fast interpreter: a run of simple lines (bulk.py) in G17 G91.1 (G90 or G91), at once.

For lines ``a..b`` of a ``Scan`` and the state before them, modal values are
forward-filled with numpy: the motion mode from the G words, the units from G20/G21,
each axis from its words (summed in G91), the feed from F (read in the units before the line's
G20/G21, as rs274ngc does), the spindle from M3/M5/S. Rows go to the ``OpBuffer`` as
arrays. The run stops before the first line the general interpreter must judge (an
error of any kind), so both paths report the same errors; ``run`` returns the new
state and where it stopped. The semantics are those of ``interp.py``/``motion.py``;
the tests compare the two paths on random programs.
"""

from __future__ import annotations

import numpy as np

from .arcs import RADIUS_TOL, SPIRAL_ABS, spiral_refused
from .bulk import Scan
from .limits import bad_rows
from .motion import LIMIT_MM
from .ops import ARC_CW, SPINDLE, OpBuffer
from .state import State


def _ffill(values: np.ndarray, first: float) -> np.ndarray:
    """``values`` (float64) with NaNs replaced by the last number before them (``first``
    at start); ``values`` itself when it has no NaN (a word on every line: not to be
    written to), a constant when it is all NaN (a word on none)."""
    known = values == values  # not NaN (one pass, no isnan and invert)
    if known.all():
        return values
    if not known.any():
        return np.full(len(values), first)
    arr = np.empty(len(values) + 1)
    arr[0], arr[1:] = first, values
    idx = np.arange(len(arr), dtype=np.int32)  # a run is at most RUN_MAX lines
    np.multiply(idx[1:], known, out=idx[1:])  # 0 at NaNs
    np.maximum.accumulate(idx, out=idx)
    return arr.take(idx[1:])


def _first(mask: np.ndarray) -> int:
    hits = np.flatnonzero(mask)
    return int(hits[0]) if len(hits) else len(mask)


def _nan(x):
    return np.nan if x is None else float(x)


class _Run:
    """Columns of lines ``a..b`` and the modal values forward-filled over them."""

    def __init__(self, scan: Scan, a: int, b: int, state: State):
        rows = slice(a - scan.first, b - scan.first)  # the scan may be a window of the program
        self.v = {c: scan.values[c][rows] for c in "XYZIJFMS"}
        g = scan.g[rows]
        units = scan.units[rows]
        self.inch = _ffill(np.where(units >= 0, units, np.nan), float(state.inch)) > 0.5
        self.scale = np.where(self.inch, 25.4, 1.0)
        self.scale_before = np.concatenate(([state.scale], self.scale[:-1]))
        self.metric = not self.inch.any() and state.scale == 1.0  # scaling by 1.0 changes no bit
        v = self.v
        self.has_axis = ~(np.isnan(v["X"]) & np.isnan(v["Y"]) & np.isnan(v["Z"]))
        self.has_ij = ~(np.isnan(v["I"]) & np.isnan(v["J"]))
        mode = _ffill(np.where(g >= 0, g, np.nan), _nan(state.motion))
        self.mode = np.where(np.isnan(mode), -1, mode).astype(np.int8)
        self.to_be = np.where(g >= 0, g, np.where(self.has_axis, self.mode, -1))
        self.arc = (self.to_be == 2) | (self.to_be == 3)

    def bad_words(self) -> np.ndarray:
        """Lines the general path must judge, from the words alone."""
        bad = self.has_axis & (self.to_be < 0)
        bad |= self.has_ij & ~self.arc
        bad |= self.arc & ~self.has_ij
        with np.errstate(invalid="ignore"):
            for c in "XYZIJ":
                bad |= np.abs(self.v[c]) * self.scale > LIMIT_MM
        return bad | bad_rows(self.v)

    def spindle(self, stop: int, state: State):
        """(event mask, rpm value) of M3/M5/S lines before ``stop``."""
        m, s = self.v["M"][:stop], self.v["S"][:stop]
        on = _ffill(np.where(m == 3, 1.0, np.where(m == 5, 0.0, np.nan)), float(state.spindle_on)) > 0.5
        speed = _ffill(s, _nan(state.speed))
        event = ~np.isnan(m) | (~np.isnan(s) & on)
        value = np.where(m == 5, 0.0, np.where(np.isnan(speed), -1.0, speed))
        return event, value, on, speed


def _arc_bad(sx, sy, ex, ey, cx, cy, inch) -> np.ndarray:
    """LinuxCNC's refusals of centre-format arcs; coordinates (columns) in program units."""
    r1 = np.hypot(cx - sx, cy - sy)
    r2 = np.hypot(cx - ex, cy - ey)
    some_inch = inch.any()
    tol = np.where(inch, RADIUS_TOL[True], RADIUS_TOL[False]) if some_inch else RADIUS_TOL[False]
    bad = (r1 < tol) | (r2 < tol)
    err = np.abs(r1 - r2)
    odd = np.flatnonzero(err > min(SPIRAL_ABS.values()))  # no other arc can be refused as a spiral
    if len(odd):
        err, r, inch = err[odd], np.maximum(r1[odd], r2[odd]), inch[odd]
        refused = spiral_refused(err, r, False)
        if some_inch:
            refused = np.where(inch, spiral_refused(err, r, True), refused)
        bad[odd] |= refused
    return bad


def _geometry(run: _Run, stop: int, rows: np.ndarray, state: State):
    """End points (one column per axis), and per row end, centre and whether LinuxCNC
    refuses the arc."""
    scale = run.scale[:stop]
    mm = [run.v[c][:stop] if run.metric else run.v[c][:stop] * scale for c in "XYZ"]
    if state.absolute:  # program values plus the work offsets in force (offsets.py)
        total = state.offsets.total()
        end = [_ffill(mm[i] + total[i], state.pos[i]) for i in range(3)]  # -0.0 + 0.0 is 0.0, as motion.py
    else:  # G91: every axis word is a step from where the tool is
        steps = [np.nan_to_num(m) for m in mm]
        end = [np.cumsum(np.concatenate(([state.pos[i]], steps[i])))[1:] for i in range(3)]
    ends = np.empty((len(rows), 3))
    starts = []
    for i in range(3):
        column = end[i].take(rows)
        ends[:, i] = column
        starts.append(np.concatenate(([state.pos[i]], column[:-1])) if len(rows) else column)
    sel = np.flatnonzero(run.arc[rows] & (run.to_be[rows] >= 0))
    arc_rows = rows[sel]
    i_word, j_word = run.v["I"][arc_rows], run.v["J"][arc_rows]
    k = run.scale[arc_rows]  # centre and check in program units, as motion.py does
    points = (starts[0], starts[1], ends[:, 0], ends[:, 1])
    sx, sy, ex, ey = (a[sel] if run.metric else a[sel] / k for a in points)
    cx = sx + np.where(np.isnan(i_word), 0.0, i_word)
    cy = sy + np.where(np.isnan(j_word), 0.0, j_word)
    center = np.full_like(ends, np.nan)
    center[:, 0][sel] = cx if run.metric else cx * k
    center[:, 1][sel] = cy if run.metric else cy * k
    center[:, 2][sel] = starts[2][sel]
    bad = np.zeros(len(rows), bool)
    bad[sel] = _arc_bad(sx, sy, ex, ey, cx, cy, run.inch[arc_rows])
    return end, ends, center, bad


def run(scan: Scan, a: int, b: int, state: State, ops: OpBuffer) -> tuple[State, int]:
    """Interpret lines ``a..b`` (0-based) on the fast path; return (state, stop line)."""
    r = _Run(scan, a, b, state)
    stop = _first(r.bad_words())
    event, rpm, on, speed = r.spindle(stop, state)
    moving = (r.has_axis[:stop] | r.arc[:stop]) & (r.to_be[:stop] >= 0)
    rows = np.flatnonzero(moving | event)
    end, ends, center, arc_bad = _geometry(r, stop, rows, state)
    for axis in range(3):  # G91 steps adding up: motion.py refuses them (a column at a time:
        arc_bad |= np.abs(ends[:, axis]) > LIMIT_MM  # numpy's any(axis=1) loops per row)
    if arc_bad.any():
        cut = _first(arc_bad)
        stop, rows, ends, center = int(rows[cut]), rows[:cut], ends[:cut], center[:cut]
    f_word = r.v["F"][:stop]
    feed = _ffill(f_word if r.metric else f_word * r.scale_before[:stop], state.feed)
    to_be = r.to_be[rows]
    zero_feed = (to_be >= 1) & (feed[rows] == 0) & ~event[rows]  # refused: the general path says so
    if zero_feed.any():
        cut = _first(zero_feed)
        stop, rows, ends, center, to_be = int(rows[cut]), rows[:cut], ends[:cut], center[:cut], to_be[:cut]
    kind = np.where(event[rows], SPINDLE, np.where(to_be >= 2, to_be - 2 + ARC_CW, to_be)).astype(np.int8)
    turn = np.where(to_be == 2, -1, np.where(to_be == 3, 1, 0)).astype(np.int32)
    turn[event[rows]] = 0
    value = np.where(event[rows], rpm[rows], feed[rows])
    ops.add_block(rows + a + 1, kind, ends, center, turn, value)
    new = state.copy()
    if stop > 0:
        last = stop - 1
        new.pos = [float(column[last]) for column in end]
        new.feed = float(feed[last])
        new.motion = None if r.mode[last] < 0 else int(r.mode[last])
        new.inch = bool(r.inch[last])
        new.spindle_on = bool(on[last])
        new.speed = None if np.isnan(speed[last]) else float(speed[last])
    return new, a + stop
