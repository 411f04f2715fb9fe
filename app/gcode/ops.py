"""The interpreted program as columns: one row per operation, in program order.

An operation is a move (RAPID, FEED, ARC_CW, ARC_CCW), a DWELL, or an event the
normaliser needs (SPINDLE on/off, PAUSE, END). Every row has the 1-based source
line, the end position in absolute machine-program millimetres (the position after
the row; events keep the position), the arc centre (NaN for non-arcs), the plane
(XY, XZ, YZ), the signed number of turns of an arc (< 0 clockwise), and ``value``:
the feed in mm/min for moves, seconds for a dwell, rpm for SPINDLE (0 = off).
``OpBuffer`` gathers rows from the fast path (whole arrays) and the general path
(one row at a time) and ``finish()`` returns one ``Ops`` of numpy arrays.

Rows of an expanded program (``macro``) also carry a ``Source``: per row the file
(0 = the program, else an index into ``files``), the line of the main program that
made it (the calling line for rows of a subprogram), the subprogram (an index into
``names``, 0 = none) and the loop iteration (0 = not in a loop). A plain program
has no ``Source``: every row comes from its own line of the main file.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

RAPID, FEED, ARC_CW, ARC_CCW, DWELL, SPINDLE, PAUSE, END = range(8)
MOTION_KINDS = (RAPID, FEED, ARC_CW, ARC_CCW)
XY, XZ, YZ = range(3)
PLANE_NAMES = ("XY", "XZ", "YZ")
# (first, second, normal) axis index per plane, in LinuxCNC's order: XZ is (Z, X).
PLANE_AXES = ((0, 1, 2), (2, 0, 1), (1, 2, 0))

_NAN3 = (float("nan"),) * 3
HANDED = ("line", "end", "center")  # the columns ``Ops.hand_over`` gives to the Toolpath
HANDED_KINDS = DWELL  # rows of these kinds and below are the Toolpath's


@dataclass
class Source:
    """Where the rows of an expanded program come from (see the module docstring)."""

    file: np.ndarray  # int32 per row
    call_line: np.ndarray  # int64 per row
    context: np.ndarray  # int32 per row
    iteration: np.ndarray  # int32 per row
    files: list[str]
    names: list[str]


@dataclass
class Ops:
    """Columns of the interpreted program (see the module docstring)."""

    line: np.ndarray
    kind: np.ndarray
    end: np.ndarray
    center: np.ndarray
    plane: np.ndarray
    turn: np.ndarray
    value: np.ndarray
    messages: list[str]  # one per PAUSE row, in order
    _starts: np.ndarray | None = field(default=None, repr=False)
    source: Source | None = None  # set for expanded programs
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)  # where the first row starts (start.py)

    def __len__(self) -> int:
        return len(self.line)

    def main_lines(self) -> np.ndarray:
        """Per row, the line of the main program it belongs to (the calling line)."""
        return self.line if self.source is None else self.source.call_line

    def starts(self) -> np.ndarray:
        """Start point of every row: the previous row's end (``origin`` for the first).

        Computed once; treat the result as read-only. When ``end`` is the tail of an
        array of points whose first row is the origin (as ``OpBuffer.finish`` makes it),
        the starts are a view of that array: no copy."""
        if self._starts is None:
            points = self.end.base
            if (isinstance(points, np.ndarray) and points.shape == (len(self.end) + 1, 3)
                    and points[1:].ctypes.data == self.end.ctypes.data and points.flags.writeable):
                points[0] = self.origin  # the spare first row is the origin's (start.py)
                self._starts = points[:-1]
                return self._starts
            start = np.empty_like(self.end)
            if len(start):
                start[0] = self.origin
                start[1:] = self.end[:-1]
            self._starts = start
        return self._starts

    def forget_starts(self) -> None:
        """Free the cached starts (a later ``starts()`` computes them again)."""
        self._starts = None

    def hand_over(self, moves) -> None:
        """Let ``moves`` (a ``Toolpath`` built from these rows, with its own copies) hold
        the positions of the move rows: this object drops its ``end`` and ``center``
        (and ``line``, when every row is from the main program) and keeps only the event
        rows' own; on first use they are put back together (``__getattr__``). A program
        whose events stand between its moves thus holds its positions once, not twice."""
        if np.may_share_memory(moves.center, self.center):  # its columns are views of these
            return
        events = np.flatnonzero(self.kind > HANDED_KINDS)
        names = HANDED if self.source is None else HANDED[1:]
        own = {name: getattr(self, name)[events] for name in names}
        self._starts = None
        for name in names:
            delattr(self, name)
        for column in (moves.end, moves.center, moves.source_line):
            column.flags.writeable = False  # the rows' own now: nobody changes them
        self.__dict__["_handed"] = (moves, events, own)

    @property
    def handed_to(self):
        """The ``Toolpath`` that holds the moves' positions (``hand_over``), or None."""
        handed = self.__dict__.get("_handed")
        return None if handed is None else handed[0]

    def __getattr__(self, name: str):
        handed = self.__dict__.get("_handed")
        if handed is None or name not in HANDED:
            raise AttributeError(name)
        moves, events, own = handed
        rows = np.flatnonzero(self.kind <= HANDED_KINDS)
        of_moves = {"line": moves.source_line, "end": moves.end, "center": moves.center}[name]
        if name == "end":  # the tail of an array of points, as ``OpBuffer.finish`` makes it
            column = np.empty((len(self.kind) + 1, 3))[1:]
        else:
            column = np.empty((len(self.kind), *of_moves.shape[1:]), of_moves.dtype)
        column[rows] = of_moves
        column[events] = own[name]
        self.__dict__[name] = column
        return column


@dataclass
class OpBuffer:
    """Collects rows; single rows are batched and flushed before each array block."""

    blocks: list[tuple] = field(default_factory=list)
    rows: list[tuple] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)

    def add(self, line, kind, end, center=_NAN3, plane=XY, turn=0, value=0.0, message=None):
        """Append one row (the general path)."""
        self.rows.append((line, kind, *end, *center, plane, turn, value))
        if message is not None:
            self.messages.append(message)

    def extend(self, other: OpBuffer) -> None:
        """Append the single rows (and messages) ``other`` gathered (one interpreted line's)."""
        self.rows.extend(other.rows)
        self.messages.extend(other.messages)

    def clear(self) -> None:
        """Drop every row collected so far."""
        self.blocks, self.rows, self.messages = [], [], []

    def add_block(self, line, kind, end, center, turn, value) -> None:
        """Append many XY rows at once (the fast path); arrays of equal length."""
        self._flush()
        n = len(line)
        plane = np.zeros(n, np.int8)
        self.blocks.append((line, kind, end, center, plane, turn, value))

    def flush(self) -> None:
        """Turn the single rows gathered so far into one array block (a caller that adds
        many rows one at a time keeps its memory in arrays, not tuples of floats)."""
        self._flush()

    def _flush(self) -> None:
        if not self.rows:
            return
        a = np.array(self.rows, dtype=np.float64).reshape(-1, 11)
        self.rows = []
        self.blocks.append(
            (a[:, 0].astype(np.int64), a[:, 1].astype(np.int8), a[:, 2:5], a[:, 5:8],
             a[:, 8].astype(np.int8), a[:, 9].astype(np.int32), a[:, 10])
        )

    def finish(self) -> Ops:
        """All rows as one ``Ops``."""
        self._flush()
        if not self.blocks:
            empty = np.empty((0, 3))
            return Ops(np.empty(0, np.int64), np.empty(0, np.int8), empty, empty.copy(),
                       np.empty(0, np.int8), np.empty(0, np.int32), np.empty(0), [])
        cols = list(zip(*self.blocks, strict=True))
        self.blocks = []
        dtypes = (np.int64, np.int8, np.float64, np.float64, np.int8, np.int32, np.float64)
        arrays = []
        for i, dtype in enumerate(dtypes):
            if i == 2:  # the ends after a row of zeros: ``Ops.starts`` is then a view
                points = np.empty((sum(len(part) for part in cols[i]) + 1, 3))
                points[0] = 0.0
                arrays.append(np.concatenate(cols[i], out=points[1:]))
            else:
                arrays.append(np.concatenate(cols[i]).astype(dtype, copy=False))
            cols[i] = None  # free each column's pieces once joined
        return Ops(*arrays, messages=self.messages)


class Enough(BaseException):
    """Raised by ``CappedBuffer`` once it holds the rows a reading asked for."""


@dataclass
class CappedBuffer(OpBuffer):
    """An ``OpBuffer`` that stops the reading (``Enough``) once it holds ``cap`` rows
    (the start probe reads only a program's first rows: ``start.probe``)."""

    cap: int = 0
    count: int = 0

    def add(self, *args, **kwargs) -> None:
        super().add(*args, **kwargs)
        self._count(1)

    def add_block(self, line, *rest) -> None:
        super().add_block(line, *rest)
        self._count(len(line))

    def extend(self, other: OpBuffer) -> None:
        super().extend(other)
        self._count(len(other.rows))

    def _count(self, n: int) -> None:
        self.count += n
        if self.count >= self.cap:
            raise Enough
