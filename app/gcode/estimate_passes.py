"""The machine planner's rules over whole arrays: tangents, junction speeds, the look-ahead
passes and trapezoid times (the CNC MCU's ``backend_sim/motion/planner.py``, vectorised).

Contract: every function takes and returns numpy arrays over the planner's blocks in
queue order; speeds in mm/s, lengths in mm, ``accel`` in mm/s^2. A barrier (dwell,
spindle, stop, end) is a block of length 0 whose entry speed is 0. The planner keeps
``horizon`` blocks after the one it is moving in (its queue's length): the entry speed of
a block is the fastest from which the path can still stop by the end of that horizon.
"""

from __future__ import annotations

import numpy as np

STRAIGHT = 0.999999  # the planner's cosine beyond which a corner is straight on / a reversal


def line_tangents(start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Unit directions (n, 3) of straight moves (zero vectors for zero lengths)."""
    d = end - start
    n = np.sqrt((d * d).sum(axis=1))
    return d / np.where(n > 0, n, 1.0)[:, None]


def helix_tangents(point, center, sweep_per_mm, dz_per_mm) -> np.ndarray:
    """Unit tangents (n, 3) of XY arcs/helices at ``point``: the angle grows by
    ``sweep_per_mm`` (signed, rad/mm) and z by ``dz_per_mm`` along the path."""
    rx, ry = point[:, 0] - center[:, 0], point[:, 1] - center[:, 1]
    t = np.stack([-ry * sweep_per_mm, rx * sweep_per_mm, dz_per_mm], axis=1)
    n = np.sqrt((t * t).sum(axis=1))
    return t / np.where(n > 0, n, 1.0)[:, None]


def junction_speeds(end_dir: np.ndarray, start_dir: np.ndarray, accel: float, deviation: float) -> np.ndarray:
    """Largest speed through each corner from ``end_dir[i]`` into ``start_dir[i]`` (grbl's
    junction deviation, as the planner's ``junction_speed``); inf straight on, 0 reversed."""
    cos_theta = -(end_dir * start_dir).sum(axis=1)
    sin_half = np.sqrt(np.clip(0.5 * (1.0 - cos_theta), 0.0, 1.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        v = np.sqrt(accel * deviation * sin_half / (1.0 - sin_half))
    v = np.where(cos_theta < -STRAIGHT, np.inf, v)
    return np.where(cos_theta > STRAIGHT, 0.0, v)


def entry_speeds_sq(length: np.ndarray, junction_sq: np.ndarray, accel: float, horizon,
                    queue_end: np.ndarray | None = None) -> np.ndarray:
    """Squared entry speed of each block as the planner's backward pass gives it while the
    previous block runs with ``horizon`` blocks (an int, or one per block) queued from this
    one on, the last of them stopping.

    With S the path length before each block, the backward recursion ``e[k]^2 =
    min(vj[k]^2, e[k+1]^2 + 2 a L[k])`` unrolls to ``min over j in [k, k+h) of (vj[j]^2 +
    2a S[j]) - 2a S[k]``, the queue's end adding ``2a S[k+h]`` (or ``2a queue_end[k]``
    when given, a path position within the last block): a sliding minimum, grown one
    block at a time up to the largest horizon."""
    n = len(length)
    two_a = 2.0 * accel
    s = np.concatenate(([0.0], np.cumsum(length)))  # s[k]: path before block k
    q = junction_sq + two_a * s[:n]
    h_of = np.clip(np.broadcast_to(np.asarray(horizon, dtype=np.int64), (n,)), 1, max(n, 1))
    top = int(h_of.max(initial=1))
    by_h = np.argsort(h_of, kind="stable")
    bounds = np.searchsorted(h_of[by_h], np.arange(1, top + 2))
    window_min = q.copy()  # min of q[k .. k+h-1] (blocks past the end: none)
    out = np.empty(n)
    for h in range(1, top + 1):
        if h > 1:
            np.minimum(window_min[: n - h + 1], q[h - 1:], out=window_min[: n - h + 1])
        group = by_h[bounds[h - 1]:bounds[h]]
        if len(group):
            out[group] = np.minimum(window_min[group], two_a * s[np.minimum(group + h, n)])
    if queue_end is not None:
        np.minimum(out, two_a * queue_end, out=out)
    return np.maximum(out - two_a * s[:n], 0.0)


def reached_speeds_sq(length: np.ndarray, entry_sq: np.ndarray, accel: float) -> np.ndarray:
    """Squared speed actually reached at each block's entry: the forward pass
    ``f[k] = min(e[k]^2, f[k-1] + 2a L[k-1])``, from rest, as a running minimum."""
    two_a = 2.0 * accel
    s = np.concatenate(([0.0], np.cumsum(length)))[: len(length)]
    shifted = entry_sq.copy()
    if len(shifted):
        shifted[0] = 0.0
    return np.maximum(np.minimum.accumulate(shifted - two_a * s) + two_a * s, 0.0)


def trapezoid_times(length, v_in, v_out, v_nom, accel: float) -> np.ndarray:
    """Seconds to run ``length`` mm from ``v_in`` to ``v_out`` accelerating at ``accel``,
    never above ``v_nom`` (cruise when it is reached, a triangle when not)."""
    peak_sq = np.minimum(v_nom * v_nom, (2.0 * accel * length + v_in * v_in + v_out * v_out) / 2.0)
    peak_sq = np.maximum(peak_sq, np.maximum(v_in, v_out) ** 2)
    peak = np.sqrt(peak_sq)
    ramps = (2.0 * peak - v_in - v_out) / accel
    cruise_mm = length - (2.0 * peak_sq - v_in * v_in - v_out * v_out) / (2.0 * accel)
    with np.errstate(divide="ignore", invalid="ignore"):
        cruise = np.where(peak > 0, np.maximum(cruise_mm, 0.0) / peak, 0.0)
    return np.where(length > 0, ramps + cruise, 0.0)


def queue_horizons(length: np.ndarray, speed: np.ndarray, trail_s: float, capacity: int):
    """Where the look-ahead ends when the path enters each block at ``speed``: the queue
    holds ``capacity`` blocks from the one the machine last reported finished, which trails
    the path by ``speed * trail_s`` mm (the S-curve's moving average, the refill), so every
    block it trails by takes a place from the look-ahead. Returns the blocks queued from
    each block on (int) and, the trailing point taken within its block, the path position
    (mm) where the queue ends."""
    n = len(length)
    s = np.concatenate(([0.0], np.cumsum(length)))
    trail = s[:n] - speed * trail_s
    head = np.minimum(np.searchsorted(s[1:], trail, side="right"), max(n - 1, 0))
    with np.errstate(divide="ignore", invalid="ignore"):
        frac = np.clip(np.where(length[head] > 0, (trail - s[head]) / length[head], 0.0), 0.0, 1.0)
    end = np.minimum(head + frac + capacity, n)
    whole = np.floor(end).astype(np.int64)
    queue_end = s[whole] + (end - whole) * np.append(length, 0.0)[whole]
    return np.clip(whole - np.arange(n), 1, capacity - 1), queue_end


def look_ahead_binds(length, entry_sq, accel: float, horizon, queue_end) -> bool:
    """Whether a look-ahead of ``horizon`` blocks ending at ``queue_end`` (mm) would lower
    any of ``entry_sq`` (computed with a longer one). A shorter queue only drops terms of
    the backward pass that are at least its new end's, so it changes nothing unless the
    path cannot stop from the entry speed by that end."""
    n = len(length)
    s = np.concatenate(([0.0], np.cumsum(length)))
    need = entry_sq * (1.0 - 1e-9) + 2.0 * accel * s[:n]
    end = np.minimum(s[np.minimum(np.arange(n) + horizon, n)], queue_end)
    return bool((2.0 * accel * end < need).any())
