"""G5 (cubic) and G5.1 (quadratic) splines in the XY plane, as LinuxCNC reads them,
cut as straight chords that stay within the arc tolerance of the curve.

G5 X Y I J P Q: a cubic Bezier from the current point to X Y; I J is the first
control point's offset from the start, P Q the second's from the end. I J may be
left out after a G5: the first control point then mirrors the last one (-P, -Q of
the previous G5), as rs274ngc does. G5.1 X Y I J: a quadratic Bezier, I J the control
point's offset from the start. Z moves linearly along the chords. The number of chords
bounds the chord error by the curve's second derivative: ``n >= sqrt(max|B''| / (8 tol))``.
"""

from __future__ import annotations

import math

import numpy as np

from app.i18n import N_, msg

from .errors import LineError
from .offsets import rotate
from .ops import FEED, OpBuffer

MAX_CHORDS = 100_000


def _need(params, letters: str, message: str, column: int) -> None:
    if not all(c in params for c in letters):
        raise LineError(column, msg(message))


def _step(state, i: float, j: float) -> tuple[float, float]:
    """A program-unit offset as a frame vector (mm, turned with a rotated system)."""
    return rotate(i * state.scale, j * state.scale, state.offsets.rotation)


def _points(state, code: float, params, column: int, start, end):
    """The Bezier control points (frame mm, XY) of this block."""
    if code == 5.1:
        _need(params, "IJ", N_("Must specify both I and J with G5.1"), column)
        di, dj = _step(state, params["I"].value, params["J"].value)
        return [start, (start[0] + di, start[1] + dj), end]
    if ("I" in params) != ("J" in params):
        raise LineError(column, msg("Must specify both I and J, or neither"))
    _need(params, "PQ", N_("Must specify both P and Q with G5"), column)
    if "I" in params:
        i, j = params["I"].value, params["J"].value
    else:
        i, j = state.cycle.spline_i, state.cycle.spline_j
    p, q = params["P"].value, params["Q"].value
    state.cycle.spline_i, state.cycle.spline_j = -p, -q
    (di, dj), (dp, dq) = _step(state, i, j), _step(state, p, q)
    return [start, (start[0] + di, start[1] + dj), (end[0] + dp, end[1] + dq), end]


def chord_count(points, tolerance: float) -> int:
    """Chords needed so none strays more than ``tolerance`` mm from the Bezier."""
    pts = np.asarray(points, float)
    degree = len(pts) - 1
    second = pts[:-2] - 2 * pts[1:-1] + pts[2:]
    bound = degree * (degree - 1) * float(np.max(np.hypot(second[:, 0], second[:, 1])))
    n = math.ceil(math.sqrt(bound / (8.0 * tolerance))) if bound > 0 else 1
    return max(1, min(n, MAX_CHORDS))


def bezier(points, t: np.ndarray) -> np.ndarray:
    """Points (len(t), 2) of the Bezier curve with ``points`` as control points."""
    pts = np.asarray(points, float)
    degree = len(pts) - 1
    out = np.zeros((len(t), 2))
    for i, p in enumerate(pts):
        out += math.comb(degree, i) * ((1 - t) ** (degree - i) * t ** i)[:, None] * p
    return out


def run_spline(state, code: float, params, target, line_no: int, ops: OpBuffer, column: int) -> None:
    """Expand one G5/G5.1 block into feed rows (``state.pos`` is the start)."""
    if state.plane != 0:
        raise LineError(column, msg("splines are cut only in the XY plane on this machine"))
    if state.comp is not None:
        raise LineError(column, msg("Cannot convert spline with cutter radius compensation"))
    if state.feed == 0:
        raise LineError(column, msg("Cannot make arc with zero feed rate"))
    start, end = tuple(state.pos[:2]), tuple(target[:2])
    points = _points(state, code, params, column, start, end)
    n = chord_count(points, state.arc_tolerance)
    try:
        state.budget.spend(n, f"G{code:g}", line_no)
    except ValueError as exc:
        raise LineError(column, exc.args[0]) from None
    t = np.arange(1, n + 1) / n
    xy = bezier(points, t)
    xy[-1] = end
    z = state.pos[2] + (target[2] - state.pos[2]) * t
    feed = state.feed
    for (x, y), zz in zip(xy.tolist(), z.tolist(), strict=True):  # Python floats: no numpy scalars
        ops.add(line_no, FEED, (x, y, zz), value=feed)
