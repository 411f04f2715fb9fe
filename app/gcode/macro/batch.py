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


def simple_shape(letters: list[str]) -> bool:
    """True when a block of these word letters may go to the fast path."""
    return len(set(letters)) == len(letters) and SIMPLE_LETTERS.issuperset(letters)


class Batch:
    """Collects plain motion blocks (see the module docstring)."""

    def __init__(self) -> None:
        self.g: list[int] = []
        self.columns = {c: [] for c in LETTERS}
        self.blocks: list[tuple] = []  # (block, words values, file id, call line, context, iteration, report)

    def __len__(self) -> int:
        return len(self.g)

    def add(self, block, values: list, meta: tuple) -> bool:
        """Add a block whose word ``values`` (None: left out) are all known; False
        (nothing added) when its G word is not G0-G3."""
        row = dict.fromkeys(LETTERS, _NAN)
        g = -1
        for w, v in zip(block.words, values, strict=False):
            if v is None:
                continue
            if w.letter == "G":
                if v not in (0.0, 1.0, 2.0, 3.0):
                    return False
                g = int(v)
            else:
                row[w.letter] = v
        self.g.append(g)
        for c in LETTERS:
            self.columns[c].append(row[c])
        self.blocks.append((block, values, *meta))
        return True

    def flush(self, state, ops, trace):
        """Interpret every collected block; return the new state."""
        if not self.g:
            return state
        n = len(self.g)
        values = {c: np.asarray(self.columns[c], np.float64) for c in LETTERS}
        values["M"] = values["S"] = np.full(n, np.nan)
        scan = Scan(np.ones(n, bool), np.asarray(self.g, np.int8), np.full(n, -1, np.int8), values)
        before = len(ops.blocks)
        state, stop = vector.run(scan, 0, n, state, ops)
        if len(ops.blocks) > before:
            self._trace_block(ops, trace)
        for i in range(stop, n):
            state = self._one(i, state, ops, trace)
            if state.ended:
                break
        self.__init__()
        return state

    def _trace_block(self, ops, trace) -> None:
        line, *rest = ops.blocks[-1]
        index = line - 1  # vector.run numbers rows by their place in the batch
        meta = [self.blocks[i] for i in index.tolist()]
        ops.blocks[-1] = (np.fromiter((m[0].line for m in meta), np.int64, len(meta)), *rest)
        trace.file.extend(m[2] for m in meta)
        trace.call_line.extend(m[3] for m in meta)
        trace.context.extend(m[4] for m in meta)
        trace.iteration.extend(m[5] for m in meta)

    def _one(self, i: int, state, ops, trace):
        block, values, file_id, call_line, context, iteration, report = self.blocks[i]
        words = [Word(w.letter, v, w.column) for w, v in zip(block.words, values, strict=False) if v is not None]
        before = len(ops.rows)
        state, _ = interpret_line(state, words, block.line, ops, report)
        n = len(ops.rows) - before
        trace.file.extend([file_id] * n)
        trace.call_line.extend([call_line] * n)
        trace.context.extend([context] * n)
        trace.iteration.extend([iteration] * n)
        return state
