"""Writing the device lines of a normaliser ``Plan``, vectorised (see normalize.py).

Each interpreted row becomes ``plan.count`` device rows (arcs turned into chords
become several G01 rows; a pause is its stop line, ``M00``/``M01``/``M06 T..``).
Per device row: a code, a target in whole thousandths of a millimetre, I J for arcs,
and a value (feed, seconds or rpm). Which words a line needs follows from the
previous row's target (what the device already knows) and the last feed sent; every
distinct number is formatted once.
"""

from __future__ import annotations

import numpy as np

from .arcs import chord_points
from .numbers import milli, rounded, texts
from .ops import ARC_CCW, ARC_CW, DWELL, END, FEED, PAUSE, PLANE_AXES, RAPID, SPINDLE, Ops
from .stops import device_line

G00, G01, G02, G03, G04, M03, M02, M00 = range(8)
_CODE_OF_KIND = np.zeros(8, np.int8)
_KINDS = [RAPID, FEED, ARC_CW, ARC_CCW, DWELL, SPINDLE, END, PAUSE]
_CODE_OF_KIND[_KINDS] = [G00, G01, G02, G03, G04, M03, M02, M00]
_CODE_TEXT = np.array(["G00", "G01", "G02", "G03", "G04", "M03", "M02", "M00"], dtype=object)
ROUNDING = 0.001


def chord_ends(start, end, center, plane, turn, tolerance: float) -> np.ndarray:
    """(k, 3) ends of the G01 chords the arcs (rows of ``Ops`` columns) are sent as, in
    order, ``normalize.plan``'s ``count`` of them per arc (``tolerance``: the profile's arc
    tolerance; the rounding of the sent numbers is taken from it)."""
    axes = np.array(PLANE_AXES)[plane]
    return chord_points(start, end, center, axes, turn, tolerance - ROUNDING)[0]


def _rows(ops: Ops, count: np.ndarray, chords: np.ndarray, tolerance: float, default_rpm: float):
    """Per device row: op index, code, target (milli), value."""
    op = np.repeat(np.arange(len(ops)), count)
    code = _CODE_OF_KIND[ops.kind[op]]
    target = milli(ops.end)[op]
    value = ops.value[op]
    chord_ops = np.flatnonzero(chords)
    if len(chord_ops):
        pts = chord_ends(ops.starts()[chord_ops], ops.end[chord_ops], ops.center[chord_ops],
                         ops.plane[chord_ops], ops.turn[chord_ops], tolerance)
        dev = np.flatnonzero(chords[op])
        target[dev] = milli(pts)
        code[dev] = G01
    spindle = code == M03
    value[spindle] = np.where(value[spindle] < 0, default_rpm, value[spindle])
    return op, code, target, value


def _words(code, target, feed_code, free):
    """Masks of the X, Y, Z and F words each row needs. ``free`` (per row and axis):
    the machine keeps its own position there (start.py), so the word is left out; an
    axis is written where its value changes and where it stops being free."""
    n = len(code)
    prev = np.empty_like(target)
    known = ~free
    was_known = np.zeros_like(known)
    if n:
        prev[0] = target[0]
        prev[1:] = target[:-1]
        was_known[1:] = known[:-1]
        was_known[: int(np.argmax(code <= G03)) + 1] = False  # nothing sent before the first move
    changed = ((target != prev) | ~was_known) & known
    straight = code <= G01
    emit = changed & straight[:, None]
    none = np.flatnonzero(straight & ~emit.any(axis=1))  # a move to where it is: one known axis
    emit[none, np.argmax(known[none], axis=1)] = True
    arc = (code == G02) | (code == G03)
    emit[arc, 0] = emit[arc, 1] = True
    emit[arc, 2] = changed[arc, 2]
    feeds = np.flatnonzero((code == G01) | arc)
    send_f = np.zeros(n, bool)
    if len(feeds):
        f = feed_code[feeds]
        send_f[feeds] = np.concatenate(([True], f[1:] != f[:-1]))
    return emit, send_f


GIL_SLICE = 16_384  # strings joined per numpy call (a few milliseconds)


def _append(line, mask, prefix: str, numbers) -> None:
    """``line[i] += prefix + text of numbers[i]`` where ``mask`` (numbers in whole
    thousandths). Each distinct number is formatted once; the strings are gathered and
    joined in slices, because numpy handles object arrays one item at a time holding the
    GIL: a GUI thread then waits one slice at most."""
    idx = np.flatnonzero(mask)
    if not len(idx):
        return
    uniq, inverse = np.unique(numbers[idx], return_inverse=True)
    table = _sliced(lambda part: texts(uniq[part], prefix), len(uniq), object)
    inverse = inverse.reshape(-1)
    for start in range(0, len(idx), GIL_SLICE):
        part = idx[start : start + GIL_SLICE]
        line[part] = line[part] + table[inverse[start : start + GIL_SLICE]]


def render(ops: Ops, count, chords, tolerance: float, default_rpm: float, free=None):
    """(device lines, line map, pauses) of interpreted rows and their plan. ``free``:
    (rows, 3) bool, the axes a row leaves where the machine stands (``StartInfo.free_rows``;
    None: every axis is known)."""
    op, code, target, value = _rows(ops, count, chords, tolerance, default_rpm)
    number = milli(value)
    free = np.zeros((len(ops), 3), bool) if free is None else free[op]
    still = (code <= G01) & free.all(axis=1)  # no axis set yet, none moved: nothing to name
    code[still], number[still] = G04, 0  # a pause of no time keeps the device line
    emit, send_f = _words(code, target, number, free)
    line = _sliced(lambda part: _CODE_TEXT[code[part]], len(code), object)
    for axis, prefix in enumerate((" X", " Y", " Z")):
        col = target[:, axis]
        if prefix == " Z":
            arc = (code == G02) | (code == G03)
            _append(line, emit[:, axis] & ~arc, prefix, col)
        else:
            _append(line, emit[:, axis], prefix, col)
    arc = (code == G02) | (code == G03)
    ij = milli(np.nan_to_num(ops.center[:, :2] - rounded(ops.starts()[:, :2])))[op]
    _append(line, arc & emit[:, 2], " Z", target[:, 2])
    _append(line, arc, " I", ij[:, 0])
    _append(line, arc, " J", ij[:, 1])
    _append(line, send_f, " F", number)
    _append(line, code == G04, " P", number)
    off = (code == M03) & (value == 0)
    _append(line, (code == M03) & ~off, " S", number)
    line[off] = "M05"
    first = np.cumsum(count) - count
    pause_rows = np.flatnonzero(ops.kind == PAUSE)
    stops = np.flatnonzero(code == M00)
    line[stops] = [device_line(v) for v in ops.value[op[stops]].tolist()]
    pauses = list(zip(first[pause_rows].tolist(), ops.messages, strict=True))
    return _sliced(lambda part: line[part].tolist(), len(line)), ops.line[op], pauses


def _sliced(fn, n: int, dtype=None):
    """``fn(slice)`` over ``range(n)`` in ``GIL_SLICE`` pieces, joined: an array of
    ``dtype``, or a list when ``dtype`` is None (object items are handled one at a time
    holding the GIL: a GUI thread then waits one piece at most)."""
    pieces = [slice(start, start + GIL_SLICE) for start in range(0, n, GIL_SLICE)]
    if dtype is None:
        joined: list = []
        for part in pieces:
            joined.extend(fn(part))
        return joined
    out = np.empty(n, dtype)
    for part in pieces:
        out[part] = fn(part)
    return out

