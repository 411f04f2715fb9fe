"""Where a job starts: which rows depend on the position the machine stands at.

rs274 reads a program from (0, 0, 0) of its own frame, but a machine starts a job
wherever it stands (after homing, a jog, the last job). The rows are read from an
``origin`` (work mm: (0, 0, 0) unless the loader is given the machine's position), and
``probe`` finds out, per axis, from which row on the rows no longer depend on it, by
reading the program's first rows a second time from a shifted origin (any reading of
the program, G91, cycles, rotations and macros included, gives the same answer for
rows that do not depend on the start; rows that do move with the shift).

- An axis that no move has given a value yet keeps the machine's position: its device
  lines leave it out (``free_rows``), so ``G00 Z-5`` as a first move is ``G00 Z-5``.
- An axis moved relative to the start before it is known (``G91`` first moves, an arc
  or a canned cycle from where the tool stands) is ``relative``: its device lines are
  right only when the rows were read from the machine's position, so the job is read
  again from it (``Program.from_start``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from app.i18n import joined, msg

from .ops import ARC_CCW, ARC_CW, PLANE_AXES, Ops

SHIFT = np.array([1024.0, 2048.0, 4096.0])  # the second origin's offset (mm)
PROBE_ROWS = 512  # rows of the first probe; each further probe reads 8 times as many
PROBE_MAX = 32_768  # past this many rows an axis still moving with the origin counts as relative
TOLERANCE = 1e-6  # mm: a row that moved less with the shift does not depend on the start
SAME_PLACE = 0.0005  # mm: the machine reports thousandths
NEVER = 1 << 62  # ``known_from`` of an axis no row gives a value


@dataclass(frozen=True)
class StartInfo:
    """Per axis X, Y, Z: the origin the rows were read from (work mm), the first row
    whose value no longer depends on it (``NEVER``: none), whether a row moves
    the axis relative to the start before that (``relative``) and the line of the first
    such row (0: none)."""

    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)
    known_from: tuple[int, int, int] = (0, 0, 0)
    relative: tuple[bool, bool, bool] = (False, False, False)
    relative_line: tuple[int, int, int] = (0, 0, 0)
    known_line: tuple[int, int, int] = (0, 0, 0)  # line of the row that first sets the axis
    free_until: tuple[int, int, int] = (0, 0, 0)  # rows before it keep the machine's position

    @property
    def depends(self) -> bool:
        """True when a device line depends on where the machine stands (a relative axis)."""
        return any(self.relative)

    def free_rows(self, ops: Ops) -> np.ndarray:
        """(n, 3) bool: the rows whose axis still keeps the machine's position (no
        move has given it a value or moved it yet), to be left out of device lines."""
        return np.arange(len(ops))[:, None] < np.array(self.free_until)[None, :]

    def needs_reading_from(self, position) -> bool:
        """Whether the rows must be read again from ``position`` (work mm, as the machine
        reports it) for the device lines to be right."""
        return any(rel and abs(float(p) - o) > SAME_PLACE
                   for rel, p, o in zip(self.relative, position, self.origin, strict=True))

    def note(self) -> str:
        """Where the job starts, for the preview and the preflight (a core message)."""
        parts = []
        for k, axis in enumerate("XYZ"):
            if self.relative[k]:
                parts.append(msg("{axis} moves relative to where the machine stands from line {line} "
                                 "(read from {axis}{origin:.3f}; read again from the machine's "
                                 "position at Start)", axis=axis, line=self.relative_line[k],
                                 origin=self.origin[k]))
            elif self.known_line[k] == 0 and self.known_from[k]:
                parts.append(msg("{axis} stays where the machine stands (the program never sets it)",
                                 axis=axis))
            elif self.known_from[k]:
                parts.append(msg("{axis} stays where the machine stands until line {line}",
                                 axis=axis, line=self.known_line[k]))
        if not parts:
            return msg("the job starts with a move that sets X, Y and Z")
        return msg("the job starts where the machine stands: {what}", what=joined(parts))


Reader = Callable[[np.ndarray, int], tuple[Ops, bool]]


def probe(read: Reader, origin) -> StartInfo:
    """``read(origin, limit)`` reads the program from ``origin`` far enough for at least
    ``limit`` rows (the flag: it read the whole program). Reads more until every axis
    is known or the program has been read whole."""
    origin = np.asarray(origin, float)
    limit = PROBE_ROWS
    while True:
        ops, complete = read(origin, limit)
        shifted, complete2 = read(origin + SHIFT, limit)
        info = _compare(ops, shifted, origin, complete and complete2, limit >= PROBE_MAX)
        if info is not None:
            return info
        limit *= 8


def _compare(ops: Ops, shifted: Ops, origin: np.ndarray, complete: bool, last: bool) -> StartInfo | None:
    """The start info from two readings, or None when the rows read are too few to say.
    ``last``: say it anyway; an axis still moving with the origin at the last row read
    is relative from there on (the job is read again from the machine's position)."""
    n = min(len(ops), len(shifted))
    same_kind = ops.kind[:n] == shifted.kind[:n]
    diverge = n if same_kind.all() else int(np.argmin(same_kind))
    if complete:
        n = len(ops)  # rows one reading made and the other did not depend on the start
    dep = np.abs(shifted.end[:diverge] - ops.end[:diverge]) > TOLERANCE
    dep = np.vstack([dep, np.ones((n - diverge, 3), bool)])  # rows read differently: all depend
    # once a row's axis no longer moves with the origin, no later row's does
    known = np.array([int(np.argmin(dep[:, a])) if not dep[:, a].all() else n for a in range(3)])
    undecided = (known >= n) & (not complete)
    if undecided.any() and not last:
        return None  # an axis still depends on the start at the last row read: read more
    known = np.where(known >= n, NEVER, known)
    lines = ops.main_lines()
    moved = dep & (np.abs(ops.end[:n] - origin[None, :]) > TOLERANCE)
    arcs = np.flatnonzero((ops.kind[:n] == ARC_CW) | (ops.kind[:n] == ARC_CCW))
    relative, first, free = [], [], []
    for a in range(3):
        rows_a = np.flatnonzero(moved[:, a])
        in_plane = np.array([a in PLANE_AXES[p][:2] for p in ops.plane[arcs].tolist()], bool)
        arcs_a = arcs[in_plane & (arcs <= known[a])] if len(arcs) else arcs
        hits = [int(rows[0]) for rows in (rows_a, arcs_a) if len(rows)]  # (sorted: their firsts are
        hits += [n - 1] if undecided[a] and n else []  # enough; a set operation imports numpy.ma, 6 ms)
        hit = min(hits, default=None)  # the first row that moves relative to the start
        relative.append(hit is not None)
        free.append(int(min(known[a], hit)) if hit is not None else int(known[a]))
        first.append(int(lines[hit]) if hit is not None else 0)
    known_line = tuple(int(lines[k]) if k < n else 0 for k in known.tolist())
    return StartInfo(tuple(float(v) for v in origin), tuple(int(k) for k in known),
                     tuple(relative), tuple(first), known_line, tuple(free))
