"""The fast interpreter: a run of simple lines (bulk.py) in G90 G17 G91.1, at once.

For lines ``a..b`` of a ``Scan`` and the state before them, modal values are
forward-filled with numpy: the motion mode from the G words, each axis from its
words, the feed from F. Rows go to the ``OpBuffer`` as arrays. The run stops before
the first line the general interpreter must judge (an error of any kind), so
both paths report the same errors; ``run`` returns the new state and where it
stopped. The semantics are those of ``interp.py``, which the tests compare against.
"""

from __future__ import annotations

import numpy as np

from .arcs import RADIUS_TOL, spiral_refused
from .bulk import Scan
from .motion import LIMIT_MM
from .ops import ARC_CW, OpBuffer
from .state import State


def _ffill(values: np.ndarray, first: float) -> np.ndarray:
    """``values`` with NaNs replaced by the last number before them (``first`` at start)."""
    arr = np.concatenate(([first], values))
    idx = np.where(np.isnan(arr), 0, np.arange(len(arr)))
    np.maximum.accumulate(idx, out=idx)
    return arr[idx][1:]


def _bad_words(g, has_axis, has_ij, mode):
    """Lines the general path must judge, from the words alone."""
    to_be = np.where(g >= 0, g, np.where(has_axis, mode, -1))
    arc = (to_be == 2) | (to_be == 3)
    bad = has_axis & (to_be < 0)
    bad |= has_ij & ~arc
    return bad, to_be


def _arc_bad(start, end, center, inch: bool) -> np.ndarray:
    k = 25.4 if inch else 1.0
    r1 = np.hypot(center[:, 0] - start[:, 0], center[:, 1] - start[:, 1]) / k
    r2 = np.hypot(center[:, 0] - end[:, 0], center[:, 1] - end[:, 1]) / k
    zero = (r1 < RADIUS_TOL[inch]) | (r2 < RADIUS_TOL[inch])
    return zero | spiral_refused(np.abs(r1 - r2), np.maximum(r1, r2), inch)


def _first(mask: np.ndarray) -> int:
    hits = np.flatnonzero(mask)
    return int(hits[0]) if len(hits) else len(mask)


def _modes(scan: Scan, a: int, b: int, state: State):
    g = scan.g[a:b]
    v = {c: scan.values[c][a:b] for c in "XYZIJF"}
    has_axis = ~(np.isnan(v["X"]) & np.isnan(v["Y"]) & np.isnan(v["Z"]))
    has_ij = ~(np.isnan(v["I"]) & np.isnan(v["J"]))
    gf = np.where(g >= 0, g, np.nan).astype(np.float64)
    mode = _ffill(gf, np.nan if state.motion is None else state.motion)
    mode = np.where(np.isnan(mode), -1, mode).astype(np.int8)
    return g, v, has_axis, has_ij, mode


def run(scan: Scan, a: int, b: int, state: State, ops: OpBuffer) -> tuple[State, int]:
    """Interpret lines ``a..b`` (0-based) on the fast path; return (state, stop line)."""
    g, v, has_axis, has_ij, mode = _modes(scan, a, b, state)
    bad, to_be = _bad_words(g, has_axis, has_ij, mode)
    arc = (to_be == 2) | (to_be == 3)
    bad |= arc & ~has_ij
    with np.errstate(invalid="ignore"):
        for c in "XYZIJ":
            bad |= np.abs(v[c]) * state.scale > LIMIT_MM
    stop = _first(bad)
    k = state.scale
    moving = (has_axis[:stop] | arc[:stop]) & (to_be[:stop] >= 0)
    end = np.stack([_ffill(v[c][:stop] * k, state.pos[i]) for i, c in enumerate("XYZ")], axis=1)
    rows = np.flatnonzero(moving)
    ends = end[rows]
    starts = np.empty_like(ends)
    if len(rows):
        starts[0] = state.pos
        starts[1:] = ends[:-1]
    kinds = to_be[:stop][rows]
    is_arc = (kinds == 2) | (kinds == 3)
    center = np.full_like(ends, np.nan)
    ij = np.nan_to_num(np.stack([v["I"][:stop][rows], v["J"][:stop][rows]], axis=1)) * k
    center[is_arc, :2] = starts[is_arc, :2] + ij[is_arc]
    center[is_arc, 2] = starts[is_arc, 2]
    arc_bad = np.zeros(len(rows), bool)
    arc_bad[is_arc] = _arc_bad(starts[is_arc], ends[is_arc], center[is_arc], state.inch)
    if arc_bad.any():
        cut = _first(arc_bad)
        stop, rows, ends, kinds, center = int(rows[cut]), rows[:cut], ends[:cut], kinds[:cut], center[:cut]
    feed = _ffill(v["F"][:stop] * k, state.feed)
    turn = np.where(kinds == 2, -1, np.where(kinds == 3, 1, 0)).astype(np.int32)
    kind = np.where(kinds >= 2, kinds - 2 + ARC_CW, kinds).astype(np.int8)
    ops.add_block(rows + a + 1, kind, ends, center, turn, feed[rows])
    new = state.copy()
    if stop > 0:
        new.pos = [float(x) for x in end[stop - 1]]
        new.feed = float(feed[stop - 1])
        last_mode = int(mode[stop - 1])
        new.motion = None if last_mode < 0 else last_mode
    return new, a + stop
