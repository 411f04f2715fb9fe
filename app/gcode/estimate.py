"""Run time of a program as the machine's own planner will run it (issue 21).

Contract: ``estimate(toolpath, device_lines, profile)`` gives an ``Estimate``: seconds per
device line (``line_seconds``, what the remaining time of a running job is summed from),
the total and its parts (motion, dwells, spindle spin-up waits), and apart from the total
the program stops (M00, M01, M06): how many, and the seconds of what the machine does
around them (spindle off and back up, the Z lift and return at a tool change; never the
operator's wait). Pure numpy over the toolpath's arrays, no Qt, no simulator import.

The rules are the CNC MCU's planner's (``backend_sim/motion/planner.py``): nominal speed
(feed or rapid, arcs at most sqrt(a r)), junction deviation between blocks, a backward
pass over the queue the machine holds (``QUEUE_BLOCKS`` blocks from the last one it
reported finished, which trails the path: ``queue_horizons``; the end of the queue
stops), a forward pass from rest, trapezoids at ``accel``. The S-curve is a moving average
of the path distance over ``accel/jerk`` seconds: it delays every stop before a barrier
(dwell, spindle, stop, end) by that window and otherwise leaves the time unchanged.
Given the normaliser's plan, an arc it sends as G01 chords is timed as those chords
(``estimate_chords.py``), each a block on its own device line, as the machine runs it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .estimate_chords import as_sent, fold
from .estimate_passes import (
    entry_speeds_sq,
    helix_tangents,
    junction_speeds,
    line_tangents,
    path_before,
    queue_binds,
    queue_horizons,
    reached_speeds_sq,
    speeds_close,
    trapezoid_times,
)
from .estimate_spindle import spin_wait_ms
from .ops import ARC_CCW, ARC_CW, DWELL, RAPID, run_of
from .threads import each_on, in_order

QUEUE_BLOCKS = 16  # the CNC MCU's motion queue (MotionController capacity)
HORIZON_ROUNDS = 6
# The simulated CNC MCU reports finished blocks when it services its link (at the latest
# every 50 ms motion chunk) and the next line then crosses the UART: the queue is refilled
# this late on average, measured on the simulator (tests/gcode/test_estimate.py).
REFILL_S = 0.025
ZERO_MM = 1e-6  # the planner's zero-length move: transparent, no stop
BLOCK = 1 << 14  # moves whose geometry is worked out at a time (small temporaries)


@dataclass
class Estimate:
    """See the module docstring; seconds throughout."""

    line_seconds: np.ndarray  # per device line, stops excluded
    row_seconds: np.ndarray  # per toolpath row (a barrier's wait on the row before it)
    motion: float
    dwell: float
    spin_up: float
    stops: int = 0
    tool_changes: int = 0
    stop_seconds: float = 0.0  # what the stops make the machine do, excluded from ``total``

    @property
    def total(self) -> float:
        return self.motion + self.dwell + self.spin_up

    def remaining(self, lines_done: int) -> float:
        """Seconds left once the first ``lines_done`` device lines have finished."""
        done = float(self.line_seconds[: max(0, lines_done)].sum())
        return max(0.0, self.total - done)

    def per_source_line(self, line_map: np.ndarray, n_source: int) -> np.ndarray:
        """Seconds per 1-based source line, from the device lines' ``line_map``."""
        return np.bincount(np.asarray(line_map), weights=self.line_seconds, minlength=n_source + 1)


@dataclass
class _Barrier:
    line: int
    kind: str  # "dwell", "spindle", "stop", "end"
    ms: float = 0.0  # how long it holds the path, beyond the S-curve's settling
    stop_ms: float = 0.0  # what a program stop makes the machine do (reported apart)


def estimate(toolpath, device_lines, profile, start=None, plan=None, threads: int = 1,
             second=None) -> Estimate:
    """The planner's time for ``toolpath`` whose rows come from ``device_lines`` (in their
    order); ``start`` (work mm), where the machine is when the job starts, if known: the
    first move is a straight one from there rather than from where the program assumed;
    ``plan`` (the normaliser's), when given: the arcs it sends as chords are timed as those
    chords (``estimate_chords``), and each row's seconds are its chords' sum. ``threads`` 2:
    its blocks shared by a second thread, from when ``second`` (an Event) is set if given."""
    sent, begins = as_sent(toolpath, plan, profile.motion.arc_tolerance_mm)
    est = _as_planned(sent, device_lines, profile, start, each_on(threads, second))
    return est if begins is None else replace(est, row_seconds=fold(est.row_seconds, begins))


def _as_planned(toolpath, device_lines, profile, start, each=in_order) -> Estimate:
    """``estimate`` of the blocks the planner is sent, one per row of ``toolpath``. Kept
    whole: a few numbers per planner block; the rest is worked out in blocks (``each``
    maps a function over them: ``threads.in_order`` or ``on_two_threads``)."""
    mo = profile.motion
    accel = mo.accel_mm_s2
    window_s = max(1, round(accel / mo.jerk_mm_s3 * 1000)) / 1000.0
    row_length = toolpath.length
    first = _first_line_row(toolpath) if start is not None else None
    if first is not None:
        row_length = row_length.copy()
        row_length[first] = float(np.linalg.norm(toolpath.end[first] - np.asarray(start, float)))
    moves = _index(np.flatnonzero((toolpath.kind != DWELL) & (row_length >= ZERO_MM)))
    barriers = _barriers(toolpath, device_lines, profile)
    is_move = _chain(toolpath.device_index, moves, [b.line for b in barriers])
    at = _index(np.flatnonzero(is_move))  # each move's place in the queue
    first = None if first is None else (first, start)
    chain_len, junction_sq, nominal = _geometry(toolpath, moves, at, is_move, accel, row_length,
                                               mo.junction_deviation_mm, first, each)
    del at  # the passes need a few numbers per block only
    reached = _planned_speeds(chain_len, junction_sq, accel, window_s, each)
    del junction_sq
    times = _move_times(moves, is_move, chain_len, reached, nominal, accel, each)
    del reached, chain_len, nominal
    # the S-curve settles for its window where the path stops before a barrier
    barrier_at = np.flatnonzero(~is_move)
    settles = (barrier_at > 0) & is_move[np.maximum(barrier_at - 1, 0)]
    row_seconds = np.zeros(len(toolpath))
    row_seconds[moves] = times
    waits = np.zeros(len(barriers))  # seconds each barrier holds the path (stops: 0)
    waits[settles] += window_s
    spent = {"dwell": 0.0, "spindle": 0.0, "stop": 0.0}
    for k, b in enumerate(barriers):
        if b.kind in spent:
            spent[b.kind] += b.ms / 1000.0
        waits[k] = 0.0 if b.kind == "stop" else waits[k] + b.ms / 1000.0
    stop_settle = sum(window_s for k in np.flatnonzero(settles).tolist() if barriers[k].kind == "stop")
    lines = np.array([b.line for b in barriers], dtype=np.int64)
    rows = np.searchsorted(toolpath.device_index, lines, side="right") - 1
    rows = np.clip(rows, 0, max(len(toolpath) - 1, 0))
    if len(toolpath):
        np.add.at(row_seconds, rows, waits)  # a dwell row is its own line's row
    line_seconds = np.zeros(len(device_lines))
    for a in range(0, len(moves), BLOCK):  # in order: each line's sum as one bincount's, to the bit
        np.add.at(line_seconds, toolpath.device_index[moves[a : a + BLOCK]], times[a : a + BLOCK])
    np.add.at(line_seconds, lines, waits)
    stops = [b for b in barriers if b.kind == "stop"]
    return Estimate(
        line_seconds=line_seconds[: len(device_lines)], row_seconds=row_seconds,
        motion=float(times.sum()) + window_s * int(settles.sum()) - stop_settle,
        dwell=spent["dwell"], spin_up=spent["spindle"], stops=len(stops),
        tool_changes=sum(1 for b in stops if _is_tool_change(device_lines[b.line])),
        stop_seconds=stop_settle + sum(b.stop_ms for b in stops) / 1000.0)


def _move_times(moves, is_move, chain_len, reached, nominal, accel: float, each=in_order) -> np.ndarray:
    """Seconds of each move, a block at a time: from the speed reached at its entry to the
    next block's (0 after the last), never above its nominal speed (``nominal``, per move,
    kept from ``_geometry``: 8 bytes a move, against working them out twice)."""
    times = np.empty(len(moves))
    at = _index(np.flatnonzero(is_move))

    def block(a: int) -> None:
        place = run_of(at[a : a + BLOCK])
        if isinstance(place, slice):  # a run of blocks: each one's exit is the entry of the next
            v_in, v_out = reached[place], np.zeros(place.stop - place.start)
            exits = reached[place.start + 1 : place.stop + 1]  # (none after the last block)
            v_out[: len(exits)] = exits
        else:
            after = place + 1
            v_out = np.where(after < len(reached), reached[np.minimum(after, len(reached) - 1)], 0.0)
            v_in = reached[place]
        times[a : a + BLOCK] = trapezoid_times(_gather(chain_len, place), v_in, v_out, nominal[a : a + BLOCK],
                                               accel)

    each(block, range(0, len(at), BLOCK), "times")
    return times


def _index(rows: np.ndarray) -> np.ndarray:
    """Row numbers in 4 bytes each when they fit (half the memory of numpy's default)."""
    return rows.astype(np.int32) if len(rows) < 2**31 - 1 else rows


def _planned_speeds(length, junction_sq, accel: float, window_s: float, each=in_order) -> np.ndarray:
    """Speed at each block's entry. The look-ahead depends on the speed (``queue_horizons``)
    and the speed on the look-ahead: the passes run a few rounds from the full queue, each
    round moving the horizon half way to what the last speeds imply (undamped, it swings)."""
    trail_s = (window_s - 0.001) / 2.0 + REFILL_S  # a moving average of n ms trails by (n - 1) / 2 ms
    horizon, queue_end, before = QUEUE_BLOCKS - 1, None, None
    s = path_before(length)
    for _ in range(HORIZON_ROUNDS):
        entry = entry_speeds_sq(length, junction_sq, accel, horizon, queue_end, s=s, each=each)
        reached = reached_speeds_sq(length, entry, accel, s=s)
        np.sqrt(reached, out=reached)
        if before is not None and speeds_close(reached, before, rtol=1e-4, atol=1e-6):
            break  # the look-ahead no longer changes the speeds
        before = reached
        if queue_end is None and not queue_binds(length, reached, entry, accel, trail_s, QUEUE_BLOCKS, s,
                                                 each):
            break  # the queue is long enough everywhere: the full look-ahead's speeds hold
        del entry
        implied, end = queue_horizons(length, reached, trail_s, QUEUE_BLOCKS, s=s)
        horizon = (horizon + implied + 1) // 2
        del implied
        if queue_end is None:
            queue_end = end
        else:  # in place: the same numbers as (queue_end + end) / 2
            queue_end += end
            queue_end /= 2.0
        del end
    return reached


def _chain(device_index: np.ndarray, moves: np.ndarray, barrier_lines: list[int]) -> np.ndarray:
    """Whether each block of the queue is a move (else a barrier): the moves and the
    barriers merged by device line (the rows are in device line order; a barrier's line is
    no move's)."""
    bars = np.asarray(barrier_lines, dtype=np.int64)
    is_move = np.ones(len(moves) + len(bars), bool)
    rows_up_to = np.searchsorted(device_index, bars, side="right")  # the rows before each barrier
    is_move[np.arange(len(bars)) + np.searchsorted(moves, rows_up_to.astype(moves.dtype))] = False
    return is_move


def _first_line_row(tp) -> int | None:
    """The first row that moves, if it is a straight move (an arc's start is its own)."""
    rows = np.flatnonzero(tp.kind[: 1000] != DWELL)
    return int(rows[0]) if len(rows) and tp.kind[rows[0]] not in (ARC_CW, ARC_CCW) else None


def _geometry(tp, moves: np.ndarray, at: np.ndarray, is_move: np.ndarray, accel: float, row_length,
              deviation: float, first=None, each=in_order):
    """Per queue block its length and squared junction speed from the block before (0 at
    barriers and after them: from rest); ``first``:
    (row, start) that row starts from instead. Worked out ``BLOCK`` moves at a time (the
    same numbers as whole arrays, a few MB at a time; ``each`` as for ``_as_planned``),
    then each block's first tangent met with the last end tangent of the block before;
    and each move's nominal speed."""
    n = len(moves)
    chain_len, junction_sq, nominal = np.zeros(len(is_move)), np.zeros(len(is_move)), np.empty(n)
    none_dir, none_v = np.zeros((1, 3)), np.zeros(1)  # before the first block

    def block(a: int):
        """Block ``a``'s numbers, its junctions but the first with the block before; (that
        junction's queue block or None, its start tangent and speed, its end tangent and speed)."""
        part = slice(a, a + BLOCK)
        rows, place = run_of(moves[part]), run_of(at[part])
        length, v_nom, start_dir, end_dir = _block_geometry(tp, rows, accel, _gather(row_length, rows), first)
        chain_len[place], nominal[part] = length, v_nom
        ends, v = np.concatenate((none_dir, end_dir)), np.concatenate((none_v, v_nom))
        where, follows = _follows(place, is_move)
        vj = junction_speeds(_gather(ends, follows), _gather(start_dir, follows), accel, deviation)
        vj = np.minimum(np.minimum(vj, _gather(v[1:], follows)), _gather(v, follows))
        junction_sq[where] = vj * vj
        joins = _first_of(where, follows)
        return joins, start_dir[:1].copy(), v_nom[:1].copy(), end_dir[-1:].copy(), v_nom[-1:].copy()  # (a
        # view would keep the block's arrays)

    blocks = each(block, range(0, n, BLOCK), "geometry")
    for (_, _, _, end_dir, v), (joins, start_dir, v_nom, _, _) in zip(blocks, blocks[1:], strict=False):
        if joins is not None:  # (the first block's first junction is from rest, as worked out)
            vj = junction_speeds(end_dir, start_dir, accel, deviation)
            vj = np.minimum(np.minimum(vj, v_nom), v)
            junction_sq[joins] = vj[0] * vj[0]
    return chain_len, junction_sq, nominal


def _first_of(where, follows) -> int | None:
    """The queue block of the block's first move when it follows a move (its junction is
    with the last move of the block before), else None."""
    if isinstance(follows, slice):
        return where.start if follows.start == 0 else None
    return int(where[0]) if len(follows) and follows[0] == 0 else None


def _follows(place, is_move: np.ndarray):
    """(the queue blocks among ``place`` (a slice or numbers) that follow a move, and
    where they are in ``place``: a slice when ``place`` is one, as a run of moves with
    no barrier among them follows a move from its second block on)."""
    if isinstance(place, slice):
        skip = 0 if place.start > 0 and is_move[place.start - 1] else 1
        return slice(place.start + skip, place.stop), slice(skip, place.stop - place.start)
    follows = np.flatnonzero((place > 0) & is_move[np.maximum(place - 1, 0)])
    return place[follows], follows


def _gather(column: np.ndarray, rows) -> np.ndarray:
    """Those rows of ``column`` (``rows``: a slice, giving a view the caller must not
    write to, or row numbers, giving a copy)."""
    return column[rows] if isinstance(rows, slice) else column.take(rows, axis=0)


def _starts(tp, rows, first) -> np.ndarray:
    """Where these rows start (``first``: (row, start) that row starts from instead)."""
    start = _gather(tp.start, rows)
    if first is None:
        return start
    if isinstance(rows, slice):
        if not rows.start <= first[0] < rows.stop:
            return start
        start, rows = start.copy(), np.arange(rows.start, rows.stop)
    start[rows == first[0]] = first[1]
    return start


def _nominal_speeds(tp, rows, accel: float, start: np.ndarray):
    """(mm/s each of these moves runs at most: its feed, arcs at most sqrt(a r); their
    kinds; the arcs among them; the arcs' starts, centres and radii); ``start``: where
    they start."""
    kind, feed = _gather(tp.kind, rows), _gather(tp.feed, rows)
    v_nom = feed / 60.0
    arc = np.flatnonzero((kind == ARC_CW) | (kind == ARC_CCW))
    center = radius = None
    if len(arc):
        start = start.take(arc, axis=0)
        center = tp.center.take(arc + rows.start if isinstance(rows, slice) else rows[arc], axis=0)
        radius = np.hypot(start[:, 0] - center[:, 0], start[:, 1] - center[:, 1])
        v_nom[arc] = np.minimum(v_nom[arc], np.sqrt(accel * radius))
    rapid = kind == RAPID
    v_nom[rapid] = feed[rapid] / 60.0
    return v_nom, kind, arc, start, center, radius


def _block_geometry(tp, rows, accel: float, length: np.ndarray, first):
    """``_geometry`` of some moves (``rows``: row numbers, or a slice of them), and their
    nominal speeds."""
    start, end = _starts(tp, rows, first), _gather(tp.end, rows)
    v_nom, kind, arc, arc_start, center, radius = _nominal_speeds(tp, rows, accel, start)
    start_dir = line_tangents(start, end)
    end_dir = start_dir.copy()
    if len(arc):
        arc_end, arc_len = end.take(arc, axis=0), length[arc]
        dz = arc_end[:, 2] - arc_start[:, 2]
        sweep = np.sqrt(np.maximum(arc_len ** 2 - dz ** 2, 0.0))
        sweep = np.where(kind[arc] == ARC_CW, -1.0, 1.0) * sweep / np.where(radius > 0, radius, 1.0)
        arc_len = np.where(arc_len > 0, arc_len, 1.0)
        per_mm, dz_per_mm = sweep / arc_len, dz / arc_len
        helix_tangents(arc_start, center, per_mm, dz_per_mm, start_dir, arc)
        helix_tangents(arc_end, center, per_mm, dz_per_mm, end_dir, arc)
    return length, v_nom, start_dir, end_dir


def _is_tool_change(line: str) -> bool:
    return line.split(" ", 1)[0] in ("M06", "M6")


def _barriers(tp, device_lines, profile) -> list[_Barrier]:
    """The non-motion device lines in order, each with how long it holds the path."""
    taken = np.zeros(len(device_lines), bool)
    for a in range(0, len(tp), BLOCK):  # a block at a time: small temporaries
        part = slice(a, a + BLOCK)
        taken[tp.device_index[part][tp.kind[part] != DWELL]] = True
    out: list[_Barrier] = []
    rpm = 0.0
    z_at = _z_before(tp, len(device_lines), profile)
    spin_ms: dict[tuple[float, float], float] = {}  # (from, to) rpm: a program has few speeds
    for line in np.flatnonzero(~taken).tolist():
        text = device_lines[line]
        code = text.split(" ", 1)[0]
        if code in ("G04", "G4"):
            out.append(_Barrier(line, "dwell", float(round(max(_word(text, "P", 0.0), 0.0) * 1000))))
        elif code in ("M03", "M3", "M04", "M4", "M05", "M5"):
            new = _word(text, "S", rpm) if code[-1] != "5" else 0.0
            if (rpm, new) not in spin_ms:
                spin_ms[rpm, new] = spin_wait_ms(profile, rpm, new) - 1.0
            out.append(_Barrier(line, "spindle", spin_ms[rpm, new]))
            rpm = new
        elif code in ("M00", "M0", "M01", "M1", "M06", "M6"):
            tool_change = _is_tool_change(text)
            out.append(_Barrier(line, "stop", stop_ms=_stop_ms(profile, rpm, z_at(line), tool_change)))
        elif code in ("M02", "M2", "M30"):
            out.append(_Barrier(line, "end"))
    return out


def _word(text: str, letter: str, default: float) -> float:
    for word in text.split()[1:]:
        if word[:1] == letter:
            return float(word[1:])
    return default


def _z_before(tp, n_lines: int, profile):
    """Machine Z where the tool is before device line ``line`` (work Z plus the offset); the
    moves' lines and Z are gathered at the first stop that asks (most programs have none)."""
    moves: list = []
    offset_z = profile.travel.work_offset()[2]

    def at(line: int) -> float:
        if not moves:
            rows = np.flatnonzero(tp.kind != DWELL)
            moves[:] = [tp.device_index[rows], tp.end[rows, 2]]
        lines, z = moves
        k = int(np.searchsorted(lines, line)) - 1
        return float(z[k] if k >= 0 else (tp.start[0, 2] if len(tp) else 0.0)) + offset_z
    return at


def _stop_ms(profile, rpm: float, z: float, tool_change: bool) -> float:
    """What the machine does at a stop (the wait itself aside): at a tool change, spindle
    off, rapid up to the top of Z, spindle back up, rapid back down."""
    if not tool_change:
        return 0.0
    mo = profile.motion
    window_ms = max(1, round(mo.accel_mm_s2 / mo.jerk_mm_s3 * 1000))
    lift = max(0.0, profile.travel.limits()[2][1] - z)
    ms = 0.0
    if lift > 1e-6:
        v = np.array([mo.rapid_mm_min / 60.0])
        up = trapezoid_times(np.array([lift]), np.zeros(1), np.zeros(1), v, mo.accel_mm_s2)[0]
        ms += 2 * (up * 1000.0 + window_ms)
    if rpm > 0:
        ms += spin_wait_ms(profile, 0.0, rpm) - 1.0 + window_ms
    return ms
