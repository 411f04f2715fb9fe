"""Plain motion blocks of an expansion, interpreted many at a time on the fast path.

Most blocks a loop emits are ``G0``-``G3`` with X Y Z I J F: the walker collects
their values here instead of calling ``interpret_line`` for each one, and
``flush()`` runs them through the numpy fast path (``vector.run``) as the loader
does for a plain file, then gives the rows their own source line and trace (a
batch of fewer than ``SMALL`` blocks, as when a macro reads the position after each
move, goes through ``interpret_line`` at once: a numpy pass costs more). A
block the fast path refuses (and every block after it in the batch) goes through
``interpret_line`` one at a time, which reports it exactly as it would otherwise.
The walker flushes before any other block, so the interpreter's state is never
read out of order.
"""

from __future__ import annotations

import functools
import struct

import numpy as np

from app.gcode import vector
from app.gcode.bulk import Scan
from app.gcode.interp import interpret_line
from app.gcode.lexer import Word

from .errors import Stopped
from .expr import NAMESPACE

LETTERS = "XYZIJF"
SIMPLE_LETTERS = frozenset("GXYZIJF")
ROW = 10  # per block: G X Y Z I J F, source line, where id, loop pass
MAX_ROWS = 1 << 16
SMALL = 24  # a batch this short goes through ``interpret_line``: numpy's set-up costs more
_NAN = float("nan")
_MOTION = (0.0, 1.0, 2.0, 3.0)


def simple_shape(letters: list[str]) -> bool:
    """True when a block of these word letters may go to the fast path."""
    return bool(letters) and len(set(letters)) == len(letters) and SIMPLE_LETTERS.issuperset(letters)


def _row_codes(letters: list[str], codes: list[str], vacant: bool, line: int) -> tuple[str, str]:
    """(the row's Python code, the code of its G word) for a block of these words."""
    row = ["nan"] * 6
    g = "-1.0"
    for c, code in zip(letters, codes, strict=True):
        if vacant and not _is_number(code):
            code = f"({'-1.0' if c == 'G' else 'nan'} if (t := {code}) is None else t)"
        if c == "G":
            g = code
        else:
            row[LETTERS.index(c)] = code
    return f"({g}, {', '.join(row)}, {line}, w, it)", g


def _is_number(code: str) -> bool:
    try:
        float(code)
    except ValueError:
        return False
    return True


def row_maker(letters: list[str], vacant: bool, line: int):
    """A compiled ``fn(values, where, iteration) -> row or None`` for a block of these words
    (``None`` when its G word is not G0-G3; ``vacant``: a ``None`` value leaves a word out).
    A row is ``ROW`` doubles packed as bytes (``_packer``). Compiled once per shape of
    block (its letters), the line bound after: a long program compiles a few shapes."""
    return _row_factory(tuple(letters), vacant)(line)


@functools.lru_cache(maxsize=256)
def _row_factory(letters: tuple[str, ...], vacant: bool):
    body, g = _row_codes(list(letters), [f"v[{i}]" for i in range(len(letters))], vacant, "line")
    check = "" if "G" not in letters else f" if {g} in MOTION else None"
    namespace = {"nan": _NAN, "MOTION": _MOTION, "pack": _packer(1)}
    return eval(f"lambda line: lambda v, w, it: pack{body}{check}", namespace)  # noqa: S307


def _packer(rows: int):
    """``struct`` packing of ``rows`` batch rows: the batch grows by bytes, which numpy
    reads without converting a float object at a time."""
    return struct.Struct(f"<{ROW * rows}d").pack


def fast_row_code(letters: list[str], codes: list[str], vacant: bool, line: int) -> str | None:
    """The code of a row read straight from the scope ``S`` (the words' value ``codes``),
    for a block whose G word, if any, is a constant G0-G3; else None."""
    if "G" in letters:
        g = codes[letters.index("G")]
        if not _is_number(g) or float(g) not in _MOTION:
            return None
    return _row_codes(letters, codes, vacant, line)[0]


@functools.lru_cache(maxsize=1 << 16)  # a block's row is part of up to RUN_LIMIT runs
def _literal_row(code: str) -> bytes | None:
    """The packed constant part (G X Y Z I J F, line) of a row code that reads no
    parameter, or None."""
    parts = code[1:-1].split(", ")
    if parts[-2:] != ["w", "it"]:
        return None
    try:
        return _CONSTANT_PART.pack(*(float(p) for p in parts[:-2]))
    except (ValueError, struct.error):
        return None


_CONSTANT_PART, _WHERE_PART = struct.Struct(f"<{ROW - 2}d"), struct.Struct("<2d")
_ROW = struct.Struct(f"<{ROW}d")


def compile_rows(row_codes: list[str]):
    """``fn(S, where, iteration)`` -> the rows of ``row_codes`` one after the other, packed.
    Rows of constants only (nearly every line of a long program) need no compiling: their
    bytes are packed once and the where and loop pass added at each call."""
    literal = [_literal_row(code) for code in row_codes]
    if None not in literal:
        tail = _WHERE_PART.pack
        if len(literal) == 1:
            head = literal[0]
            return lambda S, w, it: head + tail(w, it)
        return lambda S, w, it: b"".join([head + tail(w, it) for head in literal])
    flat = ", ".join(code[1:-1] for code in row_codes)
    namespace = {**NAMESPACE, "nan": _NAN, "pack": _packer(len(row_codes))}
    return eval(f"lambda S, w, it: pack({flat})", namespace)  # noqa: S307


class Batch:
    """Collects plain motion blocks (see the module docstring)."""

    def __init__(self) -> None:
        self.flat = bytearray()  # ROW doubles per block, one block after the other, NaN when absent
        self.blocks: list = []  # the compiled block of each row
        self.interpreted = 0  # blocks that went through ``interpret_line`` one at a time
        self.refused: set[tuple[int, int]] = set()  # (file id, line) the interpreter refused
        self.wheres: list[tuple] = []  # where id -> (file id, calling line or 0, subprogram id, report)
        self._where_ids: dict[tuple, int] = {}
        self._where_table: np.ndarray | None = None
        self.extend, self.append = self.flat.extend, self.blocks.append  # the walker's hot path

    def __len__(self) -> int:
        return len(self.blocks)

    def where_id(self, where: tuple) -> int:
        """The id of a frame's ``where`` (file id, calling line or 0, subprogram id, report)."""
        wid = self._where_ids.get(where)
        if wid is None:
            wid = self._where_ids[where] = len(self.wheres)
            self.wheres.append(where)
            self._where_table = None
        return wid

    def add(self, block, values, iteration: int, where: int) -> bool:
        """Add a block whose word ``values`` are all known; False (nothing added) when
        its G word is not G0-G3. ``where``: a ``where_id``."""
        made = block.row(values, where, iteration)
        if made is None:
            return False
        self.flat.extend(made)
        self.blocks.append(block)
        return True

    def flush(self, state, ops, trace):
        """Interpret every collected block; return the new state."""
        if not self.blocks:
            return state
        n = len(self.blocks)
        if n < SMALL:  # one at a time: the rows read back as tuples, no numpy table
            rows = list(_ROW.iter_unpack(self.flat))
            self.flat.clear()  # the same object for a caller that holds ``extend`` across a sync
            return self._each(rows, 0, state, ops, trace)
        table = np.frombuffer(bytes(self.flat), "<f8").reshape(n, ROW)  # a copy: ``flat`` is
        self.flat.clear()  # the same object for a caller that holds ``extend`` across a sync
        values = {c: table[:, i + 1] for i, c in enumerate(LETTERS)}
        values["M"] = values["S"] = np.full(n, np.nan)
        scan = Scan(np.ones(n, bool), table[:, 0].astype(np.int8), np.full(n, -1, np.int8), values)
        ops.flush()  # the rows vector.run writes are then the last
        before = ops.written
        state, stop = vector.run(scan, 0, n, state, ops)
        if ops.written > before:
            self._trace_block(ops.lines_from(before), trace, table)
        return self._each(table, stop, state, ops, trace)

    def _each(self, rows, stop: int, state, ops, trace):
        """Interpret the blocks from ``stop`` on one at a time (``rows``: their rows); the
        batch is empty after."""
        self.interpreted += len(self.blocks) - stop
        try:
            for i in range(stop, len(self.blocks)):
                row = rows[i] if type(rows) is list else rows[i].tolist()
                state = self._one(self.blocks[i], row, state, ops, trace)
                if state.ended:
                    break
        finally:
            self.blocks.clear()
        return state

    def refused_again(self, file_id: int, line: int, report) -> None:
        """The interpreter refused the block of ``line`` (reported already): the walk goes
        on, so that the lines after it are checked too, until a block is refused a second
        time (a loop repeating an error): then that report is taken back and the walk
        stops at once (``Stopped``)."""
        if (file_id, line) in self.refused:
            report.take_back(line)
            raise Stopped(line)
        self.refused.add((file_id, line))

    def _where_columns(self) -> np.ndarray:
        if self._where_table is None:
            self._where_table = np.array([w[:3] for w in self.wheres], np.int64).reshape(-1, 3)
        return self._where_table

    def _trace_block(self, line: np.ndarray, trace, table: np.ndarray) -> None:
        """``line``: the line column of the rows vector.run made, which it numbered by
        their place in the batch; they get their source lines, and the trace their rows."""
        rows = table[line - 1]
        lines = rows[:, 7].astype(np.int64)
        where = self._where_columns()[rows[:, 8].astype(np.intp)]
        line[:] = lines
        trace.file.add(where[:, 0].astype(np.int32))
        trace.call_line.add(np.where(where[:, 1] == 0, lines, where[:, 1]))
        trace.context.add(where[:, 2].astype(np.int32))
        trace.iteration.add(rows[:, 9].astype(np.int32))

    def _one(self, block, row, state, ops, trace):
        """Interpret one block of the batch, its words read back from its ``row``."""
        file_id, call_line, context, report = self.wheres[int(row[8])]
        words = []
        for w in block.words:
            v = row[0] if w.letter == "G" else row[1 + LETTERS.index(w.letter)]
            if v == v and not (w.letter == "G" and v == -1.0):  # NaN, or -1 for G: a vacant word
                words.append(Word(w.letter, v, w.column))
        before = len(ops.rows)
        state, refused = interpret_line(state, words, block.line, ops, report)
        trace.repeat(len(ops.rows) - before, file_id, context, int(row[9]), call_line or block.line)
        if refused:
            self.refused_again(file_id, block.line, report)
        return state
