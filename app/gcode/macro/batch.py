"""Plain motion blocks of an expansion, interpreted many at a time on the fast path.

Most blocks a loop emits are ``G0``-``G3`` with X Y Z I J F: the walker collects
their values here instead of calling ``interpret_line`` for each one, and
``flush()`` runs them through the numpy fast path (``vector.run``) as the loader
does for a plain file, then gives the rows their own source line and trace. A
block the fast path refuses (and every block after it in the batch) goes through
``interpret_line`` one at a time, which reports it exactly as it would otherwise.
The walker flushes before any other block, so the interpreter's state is never
read out of order.
"""

from __future__ import annotations

import numpy as np

from app.gcode import vector
from app.gcode.bulk import Scan
from app.gcode.interp import interpret_line
from app.gcode.lexer import Word

LETTERS = "XYZIJF"
SIMPLE_LETTERS = frozenset("GXYZIJF")
MAX_ROWS = 1 << 16
_NAN = float("nan")
_MOTION = (0.0, 1.0, 2.0, 3.0)


def simple_shape(letters: list[str]) -> bool:
    """True when a block of these word letters may go to the fast path."""
    return bool(letters) and len(set(letters)) == len(letters) and SIMPLE_LETTERS.issuperset(letters)


def row_maker(letters: list[str], vacant: bool):
    """A compiled ``fn(values) -> (g, X, Y, Z, I, J, F) or None`` for a block of these words
    (``None`` when its G word is not G0-G3; ``vacant``: a ``None`` value leaves a word out)."""
    row = ["nan"] * 6
    g = "-1.0"
    for i, c in enumerate(letters):
        code = f"v[{i}]" if not vacant else f"(nan if v[{i}] is None else v[{i}])"
        if c == "G":
            g = f"v[{i}]" if not vacant else f"(-1.0 if v[{i}] is None else v[{i}])"
        else:
            row[LETTERS.index(c)] = code
    body = f"(({g}), {', '.join(row)})"
    check = "" if "G" not in letters else f" if {g} in MOTION else None"
    return eval(f"lambda v: {body}{check}", {"nan": _NAN, "MOTION": _MOTION})  # noqa: S307


class Batch:
    """Collects plain motion blocks (see the module docstring)."""

    def __init__(self) -> None:
        self.flat: list[float] = []  # G X Y Z I J F per block, one after the other, NaN when absent
        self.blocks: list[tuple] = []  # (block, words values, iteration, where: see ``add``)
        self.extend, self.append = self.flat.extend, self.blocks.append  # the walker's hot path

    def __len__(self) -> int:
        return len(self.blocks)

    def add(self, block, values, iteration: int, where: tuple) -> bool:
        """Add a block whose word ``values`` are all known; False (nothing added) when
        its G word is not G0-G3. ``where``: (file id, calling line or 0, subprogram, report)."""
        made = block.row(values)
        if made is None:
            return False
        self.flat.extend(made)
        self.blocks.append((block, values, iteration, where))
        return True

    def flush(self, state, ops, trace):
        """Interpret every collected block; return the new state."""
        if not self.blocks:
            return state
        n = len(self.blocks)
        table = np.array(self.flat, np.float64).reshape(n, 7)
        values = {c: table[:, i + 1] for i, c in enumerate(LETTERS)}
        values["M"] = values["S"] = np.full(n, np.nan)
        g = table[:, 0].astype(np.int8)
        scan = Scan(np.ones(n, bool), g, np.full(n, -1, np.int8), values)
        before = len(ops.blocks)
        state, stop = vector.run(scan, 0, n, state, ops)
        if len(ops.blocks) > before:
            self._trace_block(ops, trace)
        for i in range(stop, n):
            state = self._one(i, state, ops, trace)
            if state.ended:
                break
        self.flat.clear()
        self.blocks.clear()
        return state

    def _trace_block(self, ops, trace) -> None:
        line, *rest = ops.blocks[-1]
        index = line - 1  # vector.run numbers rows by their place in the batch
        meta = [self.blocks[i] for i in index.tolist()]
        lines = [m[0].line for m in meta]
        ops.blocks[-1] = (np.asarray(lines, np.int64), *rest)
        trace.file.extend(m[3][0] for m in meta)
        trace.call_line.extend([m[3][1] or line for m, line in zip(meta, lines, strict=True)])
        trace.context.extend(m[3][2] for m in meta)
        trace.iteration.extend(m[2] for m in meta)

    def _one(self, i: int, state, ops, trace):
        block, values, iteration, (file_id, call_line, context, report) = self.blocks[i]
        call_line = call_line or block.line
        pairs = zip(block.words, values, strict=False)
        words = [Word(w.letter, v, w.column) for w, v in pairs if v is not None]
        before = len(ops.rows)
        state, _ = interpret_line(state, words, block.line, ops, report)
        n = len(ops.rows) - before
        trace.file.extend([file_id] * n)
        trace.call_line.extend([call_line] * n)
        trace.context.extend([context] * n)
        trace.iteration.extend([iteration] * n)
        return state
