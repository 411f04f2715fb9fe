"""Toolpath: the moves of a program as numpy arrays, for the preview and estimates.

One row per move or dwell, in program order (spindle, pause and end events are not
rows): ``start``/``end`` (n, 3) mm, ``kind`` (RAPID, FEED, ARC_CW, ARC_CCW, DWELL),
``center`` (n, 3) (NaN except for arcs), ``plane``, ``turn``, ``source_line``
(1-based), ``device_index`` (first device line of the move), ``feed`` mm/min (rapids
at the profile's rapid rate, feeds capped at its maximum), ``length`` mm and ``time``
s. The time of a move is a trapezoid: accelerate at ``accel_mm_s2`` to the feed,
cruise, decelerate to a stop (a triangle when the move is too short); a dwell takes its
seconds. ``Program.planned`` replaces ``time`` with the machine planner's (``estimate.py``).
``polyline(tolerance)`` gives drawable points with arcs as chords.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from functools import cached_property, partial

import numpy as np

from app.profile import MachineProfile

from .arcs import arc_box, arc_length, chord_counts, chord_points, in_plane
from .ops import ARC_CCW, ARC_CW, DWELL, FEED, PLANE_AXES, RAPID, Ops, run_of
from .threads import in_order, on_two_threads

KIND_NAMES = {RAPID: "rapid", FEED: "feed", ARC_CW: "arc", ARC_CCW: "arc", DWELL: "dwell"}
PARALLEL_ARCS = 50_000  # arcs from which chords are computed on two threads
PIECE_ARCS = 65_536  # arcs per call when chords are computed in the background
BLOCK = 1 << 16  # rows whose lengths and times are worked out at a time (small temporaries)
TAIL_SHARE = 1 / 8  # build_in_place: the share of the moves that may follow an event among them
TAIL_RUNS = 64  # and in how many runs at most


def move_times(length, feed_mm_min, accel: float) -> np.ndarray:
    """Trapezoidal time (s) of moves of ``length`` mm at ``feed`` mm/min from rest to rest."""
    v = np.asarray(feed_mm_min, float) / 60.0
    length = np.asarray(length, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        cruise = length / v + v / accel
        short = 2.0 * np.sqrt(length / accel)
    return np.where(length * accel >= v * v, cruise, short)


@dataclass
class Toolpath:
    """Arrays of the moves (see the module docstring)."""

    start: np.ndarray
    end: np.ndarray
    kind: np.ndarray
    center: np.ndarray
    plane: np.ndarray
    turn: np.ndarray
    source_line: np.ndarray
    device_index: np.ndarray
    _timing: object = field(repr=False)  # () -> (feed, length, time); once used, [feed, length, time]
    _cache: dict = field(default_factory=dict, repr=False)
    _timing_lock: threading.Lock = field(default_factory=threading.Lock, repr=False, compare=False)

    def __len__(self) -> int:
        return len(self.kind)

    @property
    def _timed(self) -> list[np.ndarray]:
        """[feed, length, time], worked out once, whichever thread asks first (the first
        picture needs none of them: the window's loader has them worked out beside it)."""
        with self._timing_lock:
            if not isinstance(self._timing, list):
                self._timing = list(self._timing())
            return self._timing

    @property
    def feed(self) -> np.ndarray:
        return self._timed[0]

    @property
    def length(self) -> np.ndarray:
        return self._timed[1]

    @property
    def time(self) -> np.ndarray:
        return self._timed[2]

    @time.setter
    def time(self, seconds: np.ndarray) -> None:
        self._timed[2] = seconds

    @cached_property
    def _length_by_kind(self) -> np.ndarray:
        """Millimetres moved by each kind of row, in one pass over the moves (the window's
        summary reads them when a program opens: worked out beside its first picture)."""
        return np.bincount(self.kind, weights=self.length, minlength=ARC_CCW + 1)

    @property
    def cut_length(self) -> float:
        """Millimetres moved at feed (lines and arcs)."""
        return float(self._length_by_kind[[FEED, ARC_CW, ARC_CCW]].sum())

    @property
    def rapid_length(self) -> float:
        """Millimetres moved at rapid rate."""
        return float(self._length_by_kind[RAPID])

    @property
    def estimated_time(self) -> float:
        """Seconds for the whole program, dwells included."""
        return float(self.time.sum())

    @cached_property
    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(min xyz, max xyz) of everything the tool visits, exactly: the ends of every
        move and the quadrant points of arcs (chords drawn within a tolerance lie inside)."""
        moves = np.flatnonzero(self.kind != DWELL)
        if not len(moves):
            zero = np.zeros(3)
            return zero, zero.copy()
        ends = self.end.T  # a dwell ends where it starts: every row's end is a visited point
        low = np.minimum(self.start[moves[0]], [column.min() for column in ends])
        high = np.maximum(self.start[moves[0]], [column.max() for column in ends])
        all_arcs = moves[(self.kind[moves] == ARC_CW) | (self.kind[moves] == ARC_CCW)]
        for first in range(0, len(all_arcs), BLOCK):  # a block at a time: small temporaries
            arcs = all_arcs[first : first + BLOCK]
            arcs = arcs[self._may_bulge_out(arcs, low, high)]  # only these can widen the box
            if len(arcs):
                axes = np.array(PLANE_AXES)[self.plane[arcs]]
                ends = (self.start[arcs], self.end[arcs], self.center[arcs])
                arc_low, arc_high = arc_box(*ends, axes, self.turn[arcs])
                low, high = np.minimum(low, arc_low.min(axis=0)), np.maximum(high, arc_high.max(axis=0))
        return low, high

    def _may_bulge_out(self, arcs: np.ndarray, low: np.ndarray, high: np.ndarray) -> np.ndarray:
        """Mask of the arcs whose whole circle reaches past the box (low, high)."""
        plane = self.plane[arcs]
        s, e, c = (points.take(arcs, axis=0) for points in (self.start, self.end, self.center))
        if (plane == 0).all():  # all in XY: the columns as they are (no gather per row)
            first, second = 0, 1
        else:
            axes = np.array(PLANE_AXES)[plane]
            s, e, c, _ = in_plane(axes, s, e, c)
            first, second = axes[:, 0], axes[:, 1]
        r = np.maximum(np.hypot(s[:, 0] - c[:, 0], s[:, 1] - c[:, 1]),
                       np.hypot(e[:, 0] - c[:, 0], e[:, 1] - c[:, 1]))
        out = (c[:, 0] + r > high[first]) | (c[:, 0] - r < low[first])
        out |= (c[:, 1] + r > high[second]) | (c[:, 1] - r < low[second])
        return out

    def polyline(self, tolerance: float = 0.01, threads: int = 2) -> tuple[np.ndarray, np.ndarray]:
        """Points (m, 3) to draw, arcs as chords within ``tolerance``, and per point the
        index of the move that ends there (the first point, the start, gets 0). ``threads``:
        1 for work in the background, which then leaves the GIL to one other thread."""
        key = round(tolerance, 9)
        if key not in self._cache:
            self._cache[key] = self._polyline(tolerance, threads)
        return self._cache[key]

    def _chords(self, arcs: np.ndarray, tolerance: float, threads: int, counts: bool = False):
        """``arcs.chord_points`` of these rows (``counts``: ``arcs.chord_counts``); many
        arcs in two halves on two threads (numpy's arithmetic lets them run at once)
        unless ``threads`` is 1."""
        def of(rows):
            work = chord_counts if counts else chord_points
            return work(self.start.take(rows, axis=0), self.end.take(rows, axis=0),
                        self.center.take(rows, axis=0), np.take(PLANE_AXES, self.plane[rows], axis=0),
                        self.turn[rows], tolerance)

        join = (lambda parts, _sizes: np.concatenate(parts)) if counts else _joined
        if threads < 2:  # in pieces: no numpy call holds the GIL for long while a window redraws
            pieces = [arcs[i:i + PIECE_ARCS] for i in range(0, len(arcs), PIECE_ARCS)] or [arcs]
            return join([of(piece) for piece in pieces], [len(piece) for piece in pieces])
        if len(arcs) < PARALLEL_ARCS:
            return of(arcs)
        half = len(arcs) // 2
        return join(on_two_threads(of, (arcs[:half], arcs[half:]), "chords"), [half, len(arcs) - half])

    def _polyline(self, tolerance: float, threads: int):
        """Every move's end, and an arc of several chords its chord ends in its place
        (counted first: at a first picture's tolerance nearly every arc is one chord,
        its end, and needs no more work)."""
        moves = np.flatnonzero(self.kind != DWELL)
        if not len(moves):
            return np.empty((0, 3)), np.empty(0, np.int64)
        arc = (self.kind[moves] == ARC_CW) | (self.kind[moves] == ARC_CCW)
        count = np.ones(len(moves), np.int64)
        if arc.any():
            count[arc] = self._chords(moves[arc], tolerance, threads, counts=True)
        index = np.concatenate([moves[:1], np.repeat(moves, count)])
        many = count > 1
        pts = _points(self.start, self.end) if len(moves) == len(self.kind) and not many.any() else None
        if pts is None:  # a line's end is its point (a take lets the GIL go: repeat of rows would
            pts = np.empty((len(index), 3))  # hold it for tens of ms while a window redraws)
            pts[0] = self.start[moves[0]]
            self.end.take(index[1:], axis=0, out=pts[1:], mode="clip")  # (in range: see ``_ends``)
        if many.any():
            pts_arc, _ = self._chords(moves[many], tolerance, threads)
            pts[1:][np.repeat(many, count)] = pts_arc  # an arc's rows are its chord points, in order
        pts.flags.writeable = index.flags.writeable = False  # cached: every caller reads the same
        return pts, index


def _points(start: np.ndarray, end: np.ndarray) -> np.ndarray | None:
    """The first start and every end as one read-only (n + 1, 3) view, when ``start``
    and ``end`` are one array of points a row apart (``_ends``, ``Ops.starts``), else None."""
    base = end.base
    arrays = (start, end, base)
    if (not isinstance(base, np.ndarray) or start.base is not base or start.shape != end.shape
            or start.dtype != end.dtype or not all(a.flags.c_contiguous for a in arrays)):
        return None
    first = start.__array_interface__["data"][0]
    if end.__array_interface__["data"][0] - first != end.strides[0]:
        return None
    offset = first - base.__array_interface__["data"][0]
    points = np.ndarray((len(end) + 1, *end.shape[1:]), end.dtype, buffer=base, offset=offset)
    points.flags.writeable = False
    return points


def _picker(rows: np.ndarray):
    """(``pick(column)``: those rows of a column, whether it gives views). When the rows
    are one run (events such as the spindle only before and after the moves) it gives
    read-only views, so the Toolpath shares the interpreted rows' memory (60 MB of a
    1 M-move file) instead of copying it; else copies (``take``: a faster gather)."""
    run = run_of(rows)
    if isinstance(run, slice):

        def view(column: np.ndarray) -> np.ndarray:
            part = column[run]
            part.flags.writeable = False
            return part

        return view, True
    return (lambda column: column.take(rows, axis=0)), False


def build(ops: Ops, device_first, profile: MachineProfile, timed_ahead=None) -> Toolpath:
    """The Toolpath of interpreted rows; ``device_first`` from the normaliser's plan, or a
    function that gives it (called last: the plan may be worked out meanwhile). Its
    position, kind and line columns may be read-only views of ``ops``'s and ``device_first``.
    ``timed_ahead``: the moves' feed, length and time are worked out before ``device_first``
    is called, their blocks mapped by it (as ``_timings``'s ``each``); else on first use."""
    rows = np.flatnonzero(ops.kind <= DWELL)
    pick, views = _picker(rows)
    start, end = _ends(ops, rows, pick) if len(rows) and not views else (pick(ops.starts()), pick(ops.end))
    center = pick(ops.center)
    kind, plane, turn = pick(ops.kind), pick(ops.plane), pick(ops.turn)
    timing = partial(_timings, start, end, center, kind, plane, turn, pick(ops.value), profile.motion)
    if timed_ahead is not None:  # worked out now, before waiting for the plan
        timing = list(timing(timed_ahead))
    source = pick(ops.main_lines())
    device = pick(device_first() if callable(device_first) else device_first)
    return Toolpath(start, end, kind, center, plane, turn, source, device, timing)


def closable(ops: Ops) -> tuple[np.ndarray, np.ndarray] | None:
    """(the move rows, the places in them after which a row is skipped) when
    ``build_in_place`` can build the Toolpath of ``ops`` without a copy of its
    positions, else None: the moves are not one run (``build`` shares them then), but at
    most ``TAIL_SHARE`` of them, in at most ``TAIL_RUNS`` runs, come after the first
    event among them (a CAM program's footer: spindle off, a last retract, the end), the
    events keep the position, and the starts and ends are one array (``_points``)."""
    rows = np.flatnonzero(ops.kind <= DWELL)
    breaks = np.flatnonzero(np.diff(rows) != 1)
    if not len(breaks) or len(breaks) > TAIL_RUNS or (len(rows) - breaks[0] - 1) > TAIL_SHARE * len(rows):
        return None
    starts, events = ops.starts(), np.flatnonzero(ops.kind > DWELL)
    if _points(starts, ops.end) is None or not np.array_equal(ops.end[events], starts[events]):
        return None
    return rows, breaks


def timed_before_closing(ops: Ops, closing: tuple[np.ndarray, np.ndarray],
                         profile: MachineProfile, each=in_order) -> list[np.ndarray]:
    """[feed, length, time] of the Toolpath ``build_in_place`` will make of ``closing``
    (``closable``'s rows), worked out on ``ops``'s columns before they are closed up (a
    caller waiting for the plan meanwhile, and about to read them: ``cnc-gcode check``).
    The events among the moves are worked out too, and left out. ``each`` as for ``_timings``."""
    rows = closing[0]
    span = slice(int(rows[0]), int(rows[-1]) + 1)
    columns = (ops.starts(), ops.end, ops.center, ops.kind, ops.plane, ops.turn, ops.value)
    timed = _timings(*(column[span] for column in columns), profile.motion, each)
    if len(rows) == span.stop - span.start:
        return list(timed)
    picked = rows - span.start
    return [column.take(picked) for column in timed]


def build_in_place(ops: Ops, closing: tuple[np.ndarray, np.ndarray], device_first: np.ndarray,
                   profile: MachineProfile, timed: list[np.ndarray] | None = None) -> Toolpath:
    """``build`` of rows ``closable`` found (``closing``, what it returned): the moves after
    the first event are moved up in ``ops``'s own position columns, over the events, so
    that the moves are one run of them, and the Toolpath's positions are views of that
    run; ``ops`` hands them over (the events' own values kept first). Nothing else may
    read ``ops`` meanwhile. ``timed``: ``timed_before_closing``'s, if worked out."""
    rows, breaks = closing
    owned = ops.events_own()
    columns = [getattr(ops, name) for name in ops.handed_names()]
    source = None if "line" in owned[1] else ops.main_lines().take(rows)
    for column in columns:
        _close_up(column, rows, breaks)
    part = slice(int(rows[0]), int(rows[0]) + len(rows))
    start, end, center = ops.starts()[part], ops.end[part], ops.center[part]
    for column in (start, end, center):
        column.flags.writeable = False
    source = ops.line[part] if source is None else source
    kind, plane, turn = (column.take(rows) for column in (ops.kind, ops.plane, ops.turn))
    timing = timed if timed is not None else partial(_timings, start, end, center, kind, plane, turn,
                                                     ops.value.take(rows), profile.motion)
    moves = Toolpath(start, end, kind, center, plane, turn, source, device_first.take(rows), timing)
    ops.hand_over(moves, owned)
    return moves


def _close_up(column: np.ndarray, rows: np.ndarray, breaks: np.ndarray) -> None:
    """Move the rows ``rows`` of ``column`` after the first of ``breaks`` (places in
    ``rows`` after which a row is skipped) up, run by run, behind those before it."""
    bounds = [*(breaks + 1).tolist(), len(rows)]
    to = int(rows[breaks[0]]) + 1
    for first, stop in zip(bounds[:-1], bounds[1:], strict=True):
        source = int(rows[first])
        column[to : to + stop - first] = column[source : source + stop - first]
        to += stop - first


def _timings(start, end, center, kind, plane, turn, value, motion, each=in_order) -> tuple[np.ndarray, ...]:
    """(feed, length, time) of every row, a block at a time (small temporaries; ``each``
    maps over the blocks: ``threads.in_order`` or ``on_two_threads``)."""
    feed, length, time = (np.empty(len(kind)) for _ in range(3))

    def block(a: int) -> None:
        part = slice(a, a + BLOCK)
        feed[part], length[part], time[part] = _timing(start[part], end[part], center[part], kind[part],
                                                       plane[part], turn[part], value[part], motion)

    each(block, range(0, len(kind), BLOCK), "timing")
    return feed, length, time


def _ends(ops: Ops, rows: np.ndarray, pick) -> tuple[np.ndarray, np.ndarray]:
    """(start, end) of the rows: views of one (n + 1, 3) array of points, each move
    starting where the one before ended (the rows left out, the events, keep the
    position: checked, else the starts are a copy of their own)."""
    events = np.flatnonzero(ops.kind > DWELL)
    before = np.maximum(events - 1, 0)
    still = np.where(events[:, None] > 0, ops.end[before], 0.0)
    if not np.array_equal(ops.end[events], still):  # an event that moves: not the case today
        return pick(ops.starts()), pick(ops.end)
    points = np.empty((len(rows) + 1, 3))
    points[0] = ops.starts()[rows[0]]
    ops.end.take(rows, axis=0, out=points[1:], mode="clip")  # (rows are in range: "raise", the default,
    # would gather into a temporary copy first and copy that over)
    start, end = points[:-1], points[1:]
    start.flags.writeable = end.flags.writeable = False  # they share their memory
    return start, end


def _timing(start, end, center, kind, plane, turn, value, motion):
    """(feed, length, time) of some rows of a Toolpath (see the module docstring)."""
    feed = np.minimum(value, motion.max_feed_mm_min)
    feed[~(feed > 0)] = motion.max_feed_mm_min
    feed[kind == RAPID] = motion.rapid_mm_min
    length = np.zeros(len(kind))
    for axis in range(3):
        step = end[:, axis] - start[:, axis]
        step *= step
        length += step
    np.sqrt(length, out=length)
    arc = np.flatnonzero((kind == ARC_CW) | (kind == ARC_CCW))
    if len(arc):
        length[arc] = arc_length(start.take(arc, axis=0), end.take(arc, axis=0), center.take(arc, axis=0),
                                 np.take(PLANE_AXES, plane[arc], axis=0), turn[arc])
    time = move_times(length, feed, motion.accel_mm_s2)
    dwell = kind == DWELL
    time[dwell] = value[dwell]
    feed[dwell] = 0.0
    return feed, length, time


def _joined(parts: list[tuple[np.ndarray, np.ndarray]], sizes: list[int]) -> tuple[np.ndarray, np.ndarray]:
    """``chord_points`` results of consecutive slices of ``sizes`` arcs as one: points in
    order, each point's owner counted from the first arc of the first slice."""
    firsts = np.cumsum([0, *sizes[:-1]])
    return (np.concatenate([pts for pts, _ in parts]),
            np.concatenate([owner + first for (_, owner), first in zip(parts, firsts, strict=True)]))
