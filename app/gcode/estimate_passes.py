"""The machine planner's rules over whole arrays: tangents, junction speeds, the look-ahead
passes and trapezoid times (the CNC MCU's ``backend_sim/motion/planner.py``, vectorised).

Contract: every function takes and returns numpy arrays over the planner's blocks in
queue order; speeds in mm/s, lengths in mm, ``accel`` in mm/s^2. A barrier (dwell,
spindle, stop, end) is a block of length 0 whose entry speed is 0. The planner keeps
``horizon`` blocks after the one it is moving in (its queue's length): the entry speed of
a block is the fastest from which the path can still stop by the end of that horizon.
Every pass works ``CHUNK`` blocks at a time, carrying what crosses a chunk's edge (the
path before it, ``s``; the forward pass's running minimum; the few blocks a horizon
reaches past it): small temporaries, the same bits as one whole-array pass (issue 24).
"""

from __future__ import annotations

import numpy as np

from .threads import in_order

CHUNK = 1 << 15  # blocks a pass works on at a time (small temporaries)
STRAIGHT = 0.999999  # the planner's cosine beyond which a corner is straight on / a reversal


def line_tangents(start: np.ndarray, end: np.ndarray) -> np.ndarray:
    """Unit directions (n, 3) of straight moves (zero vectors for zero lengths)."""
    d = end - start
    n = np.sqrt(_dot(d, d))
    n[~(n > 0)] = 1.0
    for k in range(3):  # column by column: a row of three over a column is a loop per row
        np.divide(d[:, k], n, out=d[:, k])
    return d


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise dot products of (n, 3) arrays: the bits of ``(a * b).sum(axis=1)`` (the same
    sums in the same order), a tenth of its time (a reduction over rows of three numbers
    costs numpy a loop per row; columns are one loop each)."""
    out = a[:, 0] * b[:, 0]
    out += a[:, 1] * b[:, 1]
    out += a[:, 2] * b[:, 2]
    return out


def helix_tangents(point, center, sweep_per_mm, dz_per_mm, out: np.ndarray, rows: np.ndarray) -> None:
    """Unit tangents of XY arcs/helices at ``point`` into rows ``rows`` of ``out`` (n, 3):
    the angle grows by ``sweep_per_mm`` (signed, rad/mm) and z by ``dz_per_mm`` along
    the path."""
    rx, ry = point[:, 0] - center[:, 0], point[:, 1] - center[:, 1]
    tx, ty = -ry * sweep_per_mm, rx * sweep_per_mm
    n = tx * tx  # the squared norm, summed in ``_dot``'s order
    n += ty * ty
    n += dz_per_mm * dz_per_mm
    np.sqrt(n, out=n)
    n[~(n > 0)] = 1.0
    for k, column in enumerate((tx, ty, dz_per_mm)):  # column by column: a scatter of rows of
        out[rows, k] = column / n  # three is a loop per row


def junction_speeds(end_dir: np.ndarray, start_dir: np.ndarray, accel: float, deviation: float) -> np.ndarray:
    """Largest speed through each corner from ``end_dir[i]`` into ``start_dir[i]`` (grbl's
    junction deviation, as the planner's ``junction_speed``); inf straight on, 0 reversed."""
    cos_theta = -_dot(end_dir, start_dir)
    sin_half = np.sqrt(np.clip(0.5 * (1.0 - cos_theta), 0.0, 1.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        v = np.sqrt(accel * deviation * sin_half / (1.0 - sin_half))
    v = np.where(cos_theta < -STRAIGHT, np.inf, v)
    return np.where(cos_theta > STRAIGHT, 0.0, v)


def path_before(length: np.ndarray) -> np.ndarray:
    """``s`` (n + 1): the path length before each block, then the whole path's."""
    s = np.empty(len(length) + 1)
    s[0] = 0.0
    np.cumsum(length, out=s[1:])
    return s


def _chunks(n: int):
    """(a, b) bounds of consecutive ``CHUNK``-block pieces of n blocks."""
    return ((a, min(a + CHUNK, n)) for a in range(0, n, CHUNK))


def _horizons(horizon, n: int, a: int, b: int) -> np.ndarray:
    """Blocks ``a..b``'s look-ahead (``horizon`` an int or one per block), within 1..n."""
    h = np.asarray(horizon)
    h = h[a:b] if h.ndim else np.full(b - a, int(h))
    return np.clip(h.astype(np.int64), 1, max(n, 1))


def entry_speeds_sq(length: np.ndarray, junction_sq: np.ndarray, accel: float, horizon,
                    queue_end: np.ndarray | None = None, s: np.ndarray | None = None,
                    each=in_order) -> np.ndarray:
    """Squared entry speed of each block as the planner's backward pass gives it while the
    previous block runs with ``horizon`` blocks (an int, or one per block) queued from this
    one on, the last of them stopping; ``s``: ``path_before(length)`` if known.

    With S the path length before each block, the backward recursion ``e[k]^2 =
    min(vj[k]^2, e[k+1]^2 + 2 a L[k])`` unrolls to ``min over j in [k, k+h) of (vj[j]^2 +
    2a S[j]) - 2a S[k]``, the queue's end adding ``2a S[k+h]`` (or ``2a queue_end[k]``
    when given, a path position within the last block): a sliding minimum, grown one
    block at a time up to the largest horizon, ``CHUNK`` blocks at a time (each chunk
    reading the few blocks after it its horizons reach; ``each`` maps over the chunks:
    ``threads.in_order`` or ``on_two_threads``)."""
    n = len(length)
    two_a = 2.0 * accel
    s = path_before(length) if s is None else s
    out = np.empty(n)

    def chunk(bounds) -> None:
        a, b = bounds
        h_of = _horizons(horizon, n, a, b)
        top = int(h_of.max())
        reach = min(b + top - 1, n)
        q = junction_sq[a:reach] + two_a * s[a:reach]
        window_min = q.copy()  # min of q[k .. k+h-1] (blocks past the end: none)
        m = reach - a
        part = out[a:b]
        for h in range(1, top + 1):
            if h > 1 and m - h + 1 > 0:
                np.minimum(window_min[: m - h + 1], q[h - 1:], out=window_min[: m - h + 1])
            group = np.flatnonzero(h_of == h)
            if len(group):
                part[group] = np.minimum(window_min[group], two_a * s[np.minimum(a + group + h, n)])
        if queue_end is not None:
            np.minimum(part, two_a * queue_end[a:b], out=part)
        part[:] = np.maximum(part - two_a * s[a:b], 0.0)

    each(chunk, _chunks(n), "entry")
    return out


def reached_speeds_sq(length: np.ndarray, entry_sq: np.ndarray, accel: float,
                      s: np.ndarray | None = None) -> np.ndarray:
    """Squared speed actually reached at each block's entry: the forward pass
    ``f[k] = min(e[k]^2, f[k-1] + 2a L[k-1])``, from rest, as a running minimum (carried
    from chunk to chunk)."""
    two_a = 2.0 * accel
    s = path_before(length) if s is None else s
    out = np.empty(len(length))
    low = np.inf
    for a, b in _chunks(len(length)):
        two_s = two_a * s[a:b]
        shifted = entry_sq[a:b].copy()
        if a == 0:
            shifted[0] = 0.0
        running = np.minimum.accumulate(shifted - two_s)
        np.minimum(running, low, out=running)
        low = running[-1]
        out[a:b] = np.maximum(running + two_s, 0.0)
    return out


def speeds_close(a: np.ndarray, b: np.ndarray, rtol: float, atol: float) -> bool:
    """``np.allclose(a, b, rtol, atol)`` a chunk at a time (small temporaries)."""
    return all(np.allclose(a[i:j], b[i:j], rtol=rtol, atol=atol) for i, j in _chunks(len(a)))


def trapezoid_times(length, v_in, v_out, v_nom, accel: float) -> np.ndarray:
    """Seconds to run ``length`` mm from ``v_in`` to ``v_out`` accelerating at ``accel``,
    never above ``v_nom`` (cruise when it is reached, a triangle when not); arrays of
    one length, worked out a chunk at a time."""
    out = np.empty(len(length))
    for a, b in _chunks(len(length)):
        out[a:b] = _trapezoid(length[a:b], v_in[a:b], v_out[a:b], v_nom[a:b], accel)
    return out


def _trapezoid(length, v_in, v_out, v_nom, accel: float) -> np.ndarray:
    peak_sq = np.minimum(v_nom * v_nom, (2.0 * accel * length + v_in * v_in + v_out * v_out) / 2.0)
    peak_sq = np.maximum(peak_sq, np.maximum(v_in, v_out) ** 2)
    peak = np.sqrt(peak_sq)
    ramps = (2.0 * peak - v_in - v_out) / accel
    cruise_mm = length - (2.0 * peak_sq - v_in * v_in - v_out * v_out) / (2.0 * accel)
    with np.errstate(divide="ignore", invalid="ignore"):
        cruise = np.where(peak > 0, np.maximum(cruise_mm, 0.0) / peak, 0.0)
    return np.where(length > 0, ramps + cruise, 0.0)


def queue_horizons(length: np.ndarray, speed: np.ndarray, trail_s: float, capacity: int,
                   s: np.ndarray | None = None):
    """Where the look-ahead ends when the path enters each block at ``speed``: the queue
    holds ``capacity`` blocks from the one the machine last reported finished, which trails
    the path by ``speed * trail_s`` mm (the S-curve's moving average, the refill), so every
    block it trails by takes a place from the look-ahead. Returns the blocks queued from
    each block on (int16: ``capacity`` < 16384) and, the trailing point taken within its
    block, the path position (mm) where the queue ends."""
    n = len(length)
    s = path_before(length) if s is None else s
    blocks, queue_end = np.empty(n, np.int16), np.empty(n)
    for a, b in _chunks(n):
        blocks[a:b], queue_end[a:b] = _queue_chunk(length, speed, trail_s, capacity, s, a, b)
    return blocks, queue_end


def _queue_chunk(length, speed, trail_s: float, capacity: int, s, a: int, b: int):
    """``queue_horizons`` of blocks ``a..b``."""
    n = len(length)
    trail = s[a:b] - speed[a:b] * trail_s
    head = np.minimum(_blocks_up_to(s[1:], trail), max(n - 1, 0))
    with np.errstate(divide="ignore", invalid="ignore"):
        frac = np.clip(np.where(length[head] > 0, (trail - s[head]) / length[head], 0.0), 0.0, 1.0)
    end = np.minimum(head + frac + capacity, n)
    whole = np.floor(end).astype(np.int64)
    last = np.where(whole < n, length[np.minimum(whole, n - 1)], 0.0)
    return np.clip(whole - np.arange(a, b), 1, capacity - 1), s[whole] + (end - whole) * last


def _blocks_up_to(ends: np.ndarray, points: np.ndarray) -> np.ndarray:
    """``np.searchsorted(ends, points, side="right")`` (``ends`` sorted), searched among
    the ends between the smallest and the largest point only: a chunk's trailing points
    lie within a few blocks of it, and a search of the whole path (a million ends) missed
    the cache at nearly every step."""
    low, high = (points.min(), points.max()) if len(points) else (0.0, 0.0)
    if not (np.isfinite(low) and np.isfinite(high)):  # NaN (or inf) anywhere: the whole path
        return np.searchsorted(ends, points, side="right")
    first, last = np.searchsorted(ends, [low, high], side="right")  # ends[:first] <= every point
    return first + np.searchsorted(ends[first:last], points, side="right")  # (ends[last:] > all)


def look_ahead_binds(length, entry_sq, accel: float, horizon, queue_end, s: np.ndarray | None = None) -> bool:
    """Whether a look-ahead of ``horizon`` blocks ending at ``queue_end`` (mm) would lower
    any of ``entry_sq`` (computed with a longer one). A shorter queue only drops terms of
    the backward pass that are at least its new end's, so it changes nothing unless the
    path cannot stop from the entry speed by that end."""
    n = len(length)
    s = path_before(length) if s is None else s
    return any(_binds_chunk(entry_sq, accel, _horizons(horizon, n, a, b), queue_end[a:b], s, a, b)
               for a, b in _chunks(n))


def queue_binds(length, speed, entry_sq, accel: float, trail_s: float, capacity: int, s, each=None) -> bool:
    """``look_ahead_binds`` of the ``queue_horizons`` at ``speed``, a chunk at a time
    (neither kept whole: where it binds, they are worked out again, whole); ``each``, when
    given, maps over every chunk (``on_two_threads``), else the chunks stop at the first
    that binds."""
    def binds(bounds) -> bool:
        a, b = bounds
        queue = _queue_chunk(length, speed, trail_s, capacity, s, a, b)
        return _binds_chunk(entry_sq, accel, *queue, s, a, b)

    chunks = _chunks(len(length))
    return any(map(binds, chunks) if each is None else each(binds, chunks, "queue"))


def _binds_chunk(entry_sq, accel: float, horizon, queue_end, s, a: int, b: int) -> bool:
    """``look_ahead_binds`` of blocks ``a..b`` (``horizon``, ``queue_end``: theirs)."""
    n = len(s) - 1
    need = entry_sq[a:b] * (1.0 - 1e-9) + 2.0 * accel * s[a:b]
    end = np.minimum(s[np.minimum(np.arange(a, b) + horizon, n)], queue_end)
    return bool((2.0 * accel * end < need).any())
