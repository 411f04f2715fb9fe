"""Straight runs of motion blocks, emitted into the batch by one call.

A block with a ``fast`` row (G0-G3 words only, no assignments) followed by more
such blocks (and empty lines) is given, at bind time, a handler that computes the
rows of the whole run in one compiled function and adds them to the batch
together: the walk then dispatches once per run instead of once per block. Each
block of the run keeps its own handler for a jump that lands inside the run. A
block that reads the machine's parameters (``S.num``: #5000 and up, or a computed
number) is never part of a run: that read flushes the batch, and must see every
row before it. A run counts as one block toward the walk's block limit: its blocks
are moves, which the move limit bounds. When an expression of the run raises an
error, the run's first block runs alone (and the rest after it, each starting its
own shorter run): the rows before the failing block stay, and the error names its
line, as block by block.
"""

from __future__ import annotations

from .batch import compile_rows
from .block import SKIP
from .errors import MacroError

RUN_LIMIT = 8  # blocks of one run


def _may_join(b) -> bool:
    return b.fast is not None and not b.reads_machine


def _empty(unit, i: int) -> bool:
    b = unit.blocks[i]
    return b.kind == SKIP and not b.skip and b.abort is None and i not in unit.bad


def runs(unit) -> dict[int, tuple]:
    """Block index -> (motion blocks of the run starting there, blocks it spans)."""
    found: dict[int, tuple] = {}
    blocks = unit.blocks
    for i in unit.starts:
        b = blocks[i]
        if not _may_join(b):
            continue
        members, j = [b], i + 1
        while j < len(blocks) and len(members) < RUN_LIMIT:
            if _may_join(blocks[j]):
                members.append(blocks[j])
            elif not _empty(unit, j):
                break
            j += 1
        while j - 1 > i and all(m is not blocks[j - 1] for m in members):  # end the span at its last move
            j -= 1
        if len(members) > 1:
            found[i] = (tuple(members), j - i)
    return found


def run_handler(members: tuple, span: int, one):
    """The handler of a run (see the module docstring); ``one``: the single-block handler
    used while the fast path is off."""
    compiled = []  # on the first run: a run the walk never starts is never compiled

    def run(w, f, b):
        if not w.fast_ok:
            return one(w, f, b)
        if not compiled:
            compiled.append(compile_rows([m.fast_code for m in members]))
        try:
            made = compiled[0](w.scope, f.wid, f.iteration)
        except MacroError:
            return one(w, f, b)
        f.pc += span
        batch = w.batch
        batch.extend(made)
        batch.blocks.extend(members)
        if len(batch.blocks) >= w.batch_limit:
            w.flush()
        return None

    return run
