"""Arc geometry, with LinuxCNC's rs274ngc (interp_arc.cc) as the reference.

Tolerances are in the program's units, as LinuxCNC applies them:

- centre format (I J K): the radius to the start ``r1`` and to the end ``r2`` must
  both be at least ``RADIUS_TOL`` (else "zero-radius arc"); with ``T = SPIRAL_ABS``
  (2 * 0.01 * sqrt 2 mm, 2 * 0.001 * sqrt 2 inch) and ``err = |r1 - r2|`` the arc is
  refused when ``err > 100 T``, or when ``err > T`` and ``err / max(r1, r2) > 0.1 %``.
  That is what rs274 of LinuxCNC 2.9 does with no ini file (recorded in
  ``tests/oracle/data/arctol_*.canon``): an arc is accepted when its end is within
  ``T`` of the circle *or* within 0.1 % of the radius, up to ``100 T``;
- radius format (R): refused when the start equals the end, or when half the chord
  exceeds ``|R|`` by more than ``RADIUS_TOL`` (0.00005 inch, 0.00127 mm); a negative
  R takes the long way round.

``sweep`` and ``chord_points`` turn arcs into points for drawing and for the G01
chords of arcs outside the XY plane. Pure numpy, no state.
"""

from __future__ import annotations

import math

import numpy as np

from app.i18n import msg

SPIRAL_REL = 0.001
RADIUS_TOL = {False: 0.00005 * 25.4, True: 0.00005}  # key: inch mode
SPIRAL_ABS = {False: 2 * 0.01 * math.sqrt(2), True: 2 * 0.001 * math.sqrt(2)}
TINY = 1e-12


def _unit(inch: bool) -> str:
    return "inch" if inch else "mm"


def ijk_error(start, end, center, inch: bool) -> str | None:
    """Why LinuxCNC refuses this centre-format arc (plane coordinates), or None."""
    r1 = math.hypot(center[0] - start[0], center[1] - start[1])
    r2 = math.hypot(center[0] - end[0], center[1] - end[1])
    if r1 < RADIUS_TOL[inch] or r2 < RADIUS_TOL[inch]:
        return msg("zero-radius arc (the centre is on the start or end point)")
    if spiral_refused(abs(r1 - r2), max(r1, r2), inch):
        return radius_message(r1, r2, inch)
    return None


def spiral_refused(err, radius, inch: bool):
    """LinuxCNC's rule for |r1 - r2| = ``err`` (scalars or arrays, program units)."""
    tol = SPIRAL_ABS[inch]
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = np.asarray(err) / np.asarray(radius)
    return (err > 100 * tol) | ((err > tol) & ~(rel <= SPIRAL_REL))


def radius_message(r1: float, r2: float, inch: bool) -> str:
    """The refusal text for an arc whose end is not on its circle."""
    unit = _unit(inch)
    return msg(
        "arc end is not on its circle: radius to start {r1:.4f}, to end {r2:.4f} {unit} "
        "(LinuxCNC allows {allowed:.4f} {unit} or {share:.1%} of the radius)",
        r1=float(r1), r2=float(r2), unit=unit, allowed=float(SPIRAL_ABS[inch]), share=float(SPIRAL_REL),
    )


def r_center(start, end, radius: float, clockwise: bool, inch: bool):
    """(centre, None) of an R-format arc, or (None, why LinuxCNC refuses it)."""
    if end[0] == start[0] and end[1] == start[1]:
        return None, msg("R-format arc whose end is its start (use I J K for a full circle)")
    r = abs(radius)
    mid = ((end[0] + start[0]) / 2.0, (end[1] + start[1]) / 2.0)
    half = math.hypot(mid[0] - end[0], mid[1] - end[1])
    if half - r > RADIUS_TOL[inch]:
        return None, msg("arc radius R{radius:g} is too small to reach the end point", radius=float(radius))
    if r == 0 or half / r > 1 - TINY:
        half = r
    angle = math.atan2(end[1] - start[1], end[0] - start[0])
    angle += -math.pi / 2 if clockwise == (radius > 0) else math.pi / 2
    offset = r * math.cos(math.asin(half / r)) if r else 0.0
    return (mid[0] + offset * math.cos(angle), mid[1] + offset * math.sin(angle)), None


def sweep(start, end, center, turn):
    """Signed swept angle (radians, > 0 counter-clockwise) in plane coordinates.

    Works on arrays: ``start``, ``end``, ``center`` are (n, 2), ``turn`` (n,).
    A zero sweep (end on start) is a full circle, as in LinuxCNC.
    """
    a0 = np.arctan2(start[:, 1] - center[:, 1], start[:, 0] - center[:, 0])
    a1 = np.arctan2(end[:, 1] - center[:, 1], end[:, 0] - center[:, 0])
    turn = np.asarray(turn)
    ccw = turn > 0
    step = a1 - a0
    step = np.where(ccw, step, -step)  # -(a1 - a0) is exactly a0 - a1
    ang = np.fmod(step, 2 * np.pi, out=step)  # np.mod is fmod, + 2 pi when negative (and
    ang[ang < 0] += 2 * np.pi  # +0 for -0, made 2 pi just below anyway), at half the cost
    ang[ang <= 1e-12] = 2 * np.pi
    extra = np.abs(turn) - 1
    if extra.any():  # adding 0.0 to a positive angle changes nothing
        ang = ang + extra * 2 * np.pi
    return np.where(ccw, ang, -ang)


def segments(radius, angle, tolerance: float):
    """Chords needed so no chord strays more than ``tolerance`` from its arc (arrays)."""
    radius = np.maximum(np.asarray(radius, float), 1e-12)
    ratio = np.clip(1.0 - tolerance / radius, -1.0, 1.0)
    step = 2.0 * np.arccos(ratio)
    step = np.where(step <= 0, np.pi / 2, np.minimum(step, np.pi / 2))
    return np.maximum(1, np.ceil(np.abs(angle) / step)).astype(np.int64)


def _frame(start3, end3, center3, plane_axes, turn):
    """Arcs in their planes: (start, end, centre (n, 2), (normal at start, at end),
    sweep, radius at the start, radius at the end)."""
    s, c, e, normals = in_plane(plane_axes, start3, center3, end3)  # normals: at the start, at the end
    ang = sweep(s, e, c, turn)
    r = np.hypot(s[:, 0] - c[:, 0], s[:, 1] - c[:, 1])
    r_end = np.hypot(e[:, 0] - c[:, 0], e[:, 1] - c[:, 1])
    return s, e, c, normals, ang, r, r_end


def chord_counts(start3, end3, center3, plane_axes, turn, tolerance):
    """The number of chords ``chord_points`` gives each arc (arrays as there): 1 for
    the arcs ``_one_chord`` is sure of, the rest worked out as ``chord_points`` does."""
    s, c, e, _ = in_plane(plane_axes, start3, center3, end3)
    turn = np.asarray(turn)
    count = np.ones(len(s), np.int64)
    rest = np.flatnonzero(~_one_chord(s, e, c, turn, tolerance))
    if len(rest):
        s, e, c = s[rest], e[rest], c[rest]
        r = np.maximum(np.hypot(*(s - c).T), np.hypot(*(e - c).T))
        count[rest] = segments(r, sweep(s, e, c, turn[rest]), tolerance)
    return count


SURE = 1e-6  # how far (in sines and cosines) ``_one_chord`` stays from each edge of ``segments``


def _one_chord(s, e, c, turn, tolerance):
    """Mask of the arcs (plane coordinates) that ``segments`` surely makes one chord,
    found without an arctangent: one turn, the short way round by more than ``SURE``,
    less than a quarter turn, and within ``tolerance`` at the middle (cos^2 of half the
    sweep over (1 - tolerance / radius)^2), each by a margin a million times any
    rounding. Zero radii, near-full circles and the like are left out (False)."""
    ux, uy, vx, vy = s[:, 0] - c[:, 0], s[:, 1] - c[:, 1], e[:, 0] - c[:, 0], e[:, 1] - c[:, 1]
    uu, vv = ux * ux + uy * uy, vx * vx + vy * vy
    with np.errstate(divide="ignore", invalid="ignore"):
        norm = np.sqrt(uu * vv)
        cos = (ux * vx + uy * vy) / norm
        sin = (ux * vy - uy * vx) / norm * turn
        q = 1.0 - tolerance / np.sqrt(np.maximum(uu, vv))
        near = (q <= 0) | ((1.0 + cos) / 2 > q * q + SURE)
    return (np.abs(turn) == 1) & (sin > SURE) & (cos > SURE) & near


def chord_points(start3, end3, center3, plane_axes, turn, tolerance):
    """Points (k, 3) along arcs, excluding each start: returns (points, owner index).

    ``start3``/``end3``/``center3`` are (n, 3) in XYZ; ``plane_axes`` gives per arc
    the (first, second, normal) axis indices; the normal axis moves linearly (helix).
    An arc of one chord has one point, its end: only arcs of several chords are worked
    out point by point (at the coarse tolerance of a first picture, nearly every arc is
    one chord).
    """
    s, e, c, (n_start, n_end), ang, r, r_end = _frame(start3, end3, center3, plane_axes, turn)
    count = segments(np.maximum(r, r_end), ang, tolerance)
    owner = np.repeat(np.arange(len(s)), count)
    last = np.cumsum(count) - 1
    pts = np.empty((len(owner), 3))
    many = np.flatnonzero(count > 1)
    if len(many):
        few = len(many) < 0.75 * len(count)  # else the gathers cost more than they save
        k = many if few else slice(None)  # (a one-chord arc's point is overwritten below)
        at = np.repeat(count > 1, count) if few else slice(None)
        sub = count[k]
        frac = np.arange(1, int(sub.sum()) + 1, dtype=float)
        frac -= np.repeat(np.cumsum(sub) - sub, sub)
        frac /= np.repeat(sub, sub)  # (j+1)/count for the j-th chord end of its arc
        sk, ck = s[k], c[k]
        theta0 = np.arctan2(sk[:, 1] - ck[:, 1], sk[:, 0] - ck[:, 0])
        theta = np.repeat(theta0, sub) + np.repeat(ang[k], sub) * frac
        rad = np.repeat(r[k], sub) + np.repeat((r_end - r)[k], sub) * frac  # spiral slightly if r1 != r2
        first_axis = np.repeat(ck[:, 0], sub) + rad * np.cos(theta)
        second_axis = np.repeat(ck[:, 1], sub) + rad * np.sin(theta)
        normal = np.repeat(n_start[k], sub) + np.repeat((n_end - n_start)[k], sub) * frac
        axes = np.asarray(plane_axes)
        if not len(axes) or (axes == (0, 1, 2)).all():  # all in XY: the columns as they are
            pts[at] = np.column_stack([first_axis, second_axis, normal])
        else:
            rows = np.arange(len(owner))[at]
            sub_owner = np.repeat(np.arange(len(sub)), sub)
            for column, values in zip(axes[k].T, (first_axis, second_axis, normal), strict=True):
                pts[rows, column[sub_owner]] = values
    pts[last] = end3  # land exactly on the programmed end (the one point of a one-chord arc)
    return pts, owner


def arc_box(start, end, center, plane_axes, turn):
    """Per arc, (low xyz, high xyz) of the whole arc: its ends and every quadrant point
    it sweeps through (arrays as in ``chord_points``)."""
    low, high = np.minimum(start, end), np.maximum(start, end)
    axes = np.asarray(plane_axes)
    idx = np.arange(len(start))
    s = np.stack([start[idx, axes[:, 0]], start[idx, axes[:, 1]]], axis=1)
    e = np.stack([end[idx, axes[:, 0]], end[idx, axes[:, 1]]], axis=1)
    c = np.stack([center[idx, axes[:, 0]], center[idx, axes[:, 1]]], axis=1)
    ang = sweep(s, e, c, turn)
    a0 = np.arctan2(s[:, 1] - c[:, 1], s[:, 0] - c[:, 0])
    # an arc whose ends lie at slightly different radii is drawn as a spiral between them
    r = np.maximum(np.hypot(*(s - c).T), np.hypot(*(e - c).T))
    for k, (axis, sign) in enumerate(((0, 1), (1, 1), (0, -1), (1, -1))):
        cardinal = k * np.pi / 2
        rel = np.where(ang > 0, np.mod(cardinal - a0, 2 * np.pi), np.mod(a0 - cardinal, 2 * np.pi))
        hit = rel <= np.abs(ang)
        which = axes[idx, axis]
        value = c[:, axis] + sign * r
        sel = np.flatnonzero(hit)
        tgt = high if sign > 0 else low
        op = np.maximum if sign > 0 else np.minimum
        tgt[sel, which[sel]] = op(tgt[sel, which[sel]], value[sel])
    return low, high


def in_plane(plane_axes, *points3):
    """Each (n, 3) array of ``points3`` as (n, 2) in its row's plane, then the (n,) normal.

    Returns ``[p1_2d, p2_2d, ..., (first point's normal, last point's normal)]``; when
    every row is in the XY plane the columns are taken as they are (no gather)."""
    axes = np.asarray(plane_axes)
    if not len(axes) or (axes[:, 0] == 0).all() and (axes[:, 1] == 1).all():
        flat = [p[:, :2] for p in points3]
        return [*flat, (points3[0][:, 2], points3[-1][:, 2])]
    idx = np.arange(len(axes))
    a1, a2, a3 = axes[:, 0], axes[:, 1], axes[:, 2]
    flat = [np.stack([p[idx, a1], p[idx, a2]], axis=1) for p in points3]
    return [*flat, (points3[0][idx, a3], points3[-1][idx, a3])]


def arc_length(start3, end3, center3, plane_axes, turn):
    """Length of each (helical) arc, arrays as in ``chord_points``."""
    if len(start3) == 0:
        return np.empty(0)
    s, c, e, (z0, z1) = in_plane(plane_axes, start3, center3, end3)
    ang = sweep(s, e, c, turn)
    r = np.hypot(s[:, 0] - c[:, 0], s[:, 1] - c[:, 1])
    return np.hypot(np.abs(ang) * r, z1 - z0)
