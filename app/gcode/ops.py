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


def run_of(rows: np.ndarray):
    """Increasing row numbers ``rows`` as a slice when they are one run of consecutive
    rows (so that columns are read as views, not gathered), else ``rows`` themselves."""
    if len(rows) and int(rows[-1]) - int(rows[0]) + 1 == len(rows):
        return slice(int(rows[0]), int(rows[-1]) + 1)
    return rows


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

        Computed once; treat the result as read-only. When ``end`` starts at the second
        row of an array of points with a spare first row (as ``OpBuffer.finish`` makes it),
        the starts are a view of that array, the spare row the origin's: no copy."""
        if self._starts is None:
            points = self.end.base
            if (isinstance(points, np.ndarray) and points.ndim == 2 and points.shape[1] == 3
                    and points.flags.c_contiguous and self.end.flags.c_contiguous
                    and self.end.ctypes.data == points[1:].ctypes.data and points.flags.writeable):
                points[0] = self.origin  # the spare first row is the origin's (start.py)
                self._starts = points[: len(self.end)]
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

    def handed_names(self) -> tuple[str, ...]:
        """The columns ``hand_over`` gives to the Toolpath (``line`` only when every row
        is from the main program: it is then the moves' source line)."""
        return HANDED if self.source is None else HANDED[1:]

    def events_own(self) -> tuple[np.ndarray, dict]:
        """(the event rows, their own values of the handed columns), for ``hand_over``."""
        events = np.flatnonzero(self.kind > HANDED_KINDS)
        return events, {name: getattr(self, name)[events] for name in self.handed_names()}

    def hand_over(self, moves, owned: tuple[np.ndarray, dict] | None = None) -> None:
        """Let ``moves`` (a ``Toolpath`` built from these rows, with its own copies) hold
        the positions of the move rows: this object drops its ``end`` and ``center``
        (and ``line``, when every row is from the main program) and keeps only the event
        rows' own; on first use they are put back together (``__getattr__``). A program
        whose events stand between its moves thus holds its positions once, not twice.
        ``owned``: ``events_own()`` taken before the moves were closed up in these
        columns (``toolpath.build_in_place``: they are then views of them, and these
        columns' other rows are no longer the rows')."""
        if self.handed_to is moves:
            return
        if owned is None:
            if np.may_share_memory(moves.center, self.center):  # its columns are views of these
                return
            owned = self.events_own()
        events, own = owned
        names = tuple(own)
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


_DTYPES = (np.int64, np.int8, np.float64, np.float64, np.int8, np.int32, np.float64)  # Ops' columns
_WIDTHS = (1, 1, 3, 3, 1, 1, 1)
_END = 2  # the ends' column: stored after a spare first row (``Ops.starts`` is then a view)
FIRST_ROWS = 1024  # rows an OpBuffer makes room for when it was told of none


class _Columns:
    """Ops' columns written in place, in room made ahead (``reserve``) and doubled when
    full: ``take`` gives views of the rows written, with no copy. Room never written to
    is never touched, so it costs address space, not memory."""

    def __init__(self, reserve: int):
        self.n = 0
        self.arrays = self._room(max(reserve, 1))

    @staticmethod
    def _room(rows: int) -> list[np.ndarray]:
        arrays = [np.empty((rows + (i == _END),) + ((w,) if w > 1 else ()), d)
                  for i, (d, w) in enumerate(zip(_DTYPES, _WIDTHS, strict=True))]
        arrays[_END][0] = 0.0
        return arrays

    def write(self, columns) -> None:
        """Append rows: one array per column, all of one length."""
        n, k = self.n, len(columns[0])
        if n + k > len(self.arrays[0]):
            self._grow(n + k)
        for i, (array, column) in enumerate(zip(self.arrays, columns, strict=True)):
            at = n + (i == _END)
            array[at : at + k] = column
        self.n = n + k

    def _grow(self, needed: int) -> None:
        bigger = self._room(max(needed, 2 * len(self.arrays[0])))
        for i, (old, new) in enumerate(zip(self.arrays, bigger, strict=True)):
            rows = self.n + (i == _END)
            new[:rows] = old[:rows]
        self.arrays = bigger

    def take(self) -> list[np.ndarray]:
        """The columns of the rows written (views; the ends' view follows the spare row)."""
        n = self.n
        return [array[1 : n + 1] if i == _END else array[:n] for i, array in enumerate(self.arrays)]


@dataclass
class OpBuffer:
    """Collects rows; single rows are batched and written before each array block.
    ``reserve``: the rows to make room for at once (a guess; more are taken in stride)."""

    reserve: int = FIRST_ROWS
    rows: list[tuple] = field(default_factory=list)
    messages: list[str] = field(default_factory=list)
    _columns: _Columns | None = field(default=None, repr=False)

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
        self.rows, self.messages, self._columns = [], [], None

    def add_block(self, line, kind, end, center, turn, value, plane=None) -> None:
        """Append many rows at once (the fast path); arrays of equal length, ``plane``
        per row (None: all XY)."""
        self._flush()
        plane = np.zeros(len(line), np.int8) if plane is None else plane
        self._write((line, kind, end, center, plane, turn, value))

    def flush(self) -> None:
        """Turn the single rows gathered so far into array rows (a caller that adds
        many rows one at a time keeps its memory in arrays, not tuples of floats)."""
        self._flush()

    @property
    def written(self) -> int:
        """Rows written as arrays so far (single rows not yet flushed are not counted)."""
        return 0 if self._columns is None else self._columns.n

    def lines_from(self, first: int) -> np.ndarray:
        """The line column of the array rows from row ``first`` on, writable (a caller
        that numbered the rows of its own block puts their lines in)."""
        return self._columns.arrays[0][first : self.written]

    def _write(self, columns) -> None:
        if self._columns is None:
            self._columns = _Columns(self.reserve)
        self._columns.write(columns)

    def _flush(self) -> None:
        if not self.rows:
            return
        a = np.array(self.rows, dtype=np.float64).reshape(-1, 11)
        self.rows = []
        self._write((a[:, 0], a[:, 1], a[:, 2:5], a[:, 5:8], a[:, 8], a[:, 9], a[:, 10]))

    def finish(self) -> Ops:
        """All rows as one ``Ops`` (its columns views of the rows written here: the
        buffer is done with)."""
        self._flush()
        columns, self._columns = self._columns or _Columns(0), None
        return Ops(*columns.take(), messages=self.messages)


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

    def add_block(self, line, *rest, **named) -> None:
        super().add_block(line, *rest, **named)
        self._count(len(line))

    def extend(self, other: OpBuffer) -> None:
        super().extend(other)
        self._count(len(other.rows))

    def _count(self, n: int) -> None:
        self.count += n
        if self.count >= self.cap:
            raise Enough
