"""Calls of a leaf subprogram: a body of plain moves, run without a frame.

A subprogram (a Fanuc ``O`` program, a LinuxCNC ``sub``) whose body is plain G0-G3
moves with ``fast`` rows (no assignments, no reads of the machine's state) and empty
lines, ended by a bare ``M99`` (LinuxCNC: ``endsub`` or ``return`` without a value),
is a leaf: ``enter`` makes the rows of a call of it in one compiled function, with
the call's arguments as the locals, and adds them to the batch, without pushing a
frame and running its blocks one at a time. Everything else is what the call would
do: the rows' trace (the frame's where, the caller's loop pass), the blocks counted
toward the work budget (as many as the walk would run), ``#<_value_returned>``. A
call repeated (``L``), nested too deep, made while the fast path is off or an ``M73``
waits for a return, or whose expressions fail, is pushed as a frame as before, and
runs (and reports) as it always did: nothing of it was added.
"""

from __future__ import annotations

from . import block as bk
from .batch import compile_rows
from .frame import DEPTH_LIMIT, Frame
from .runs import _empty, runs


class Leaf:
    """A leaf subprogram's body (see the module docstring)."""

    __slots__ = ("members", "dispatches", "linuxcnc", "rows")

    def __init__(self, members: tuple, dispatches: int, linuxcnc: bool):
        self.members, self.dispatches, self.linuxcnc = members, dispatches, linuxcnc
        self.rows = None  # compiled on the first call


class Locals:
    """What a leaf's expressions read of their frame: its numbered locals (set per call)
    and named ones (none: a leaf assigns nothing)."""

    __slots__ = ("locals", "named")

    def __init__(self) -> None:
        self.locals: dict = {}
        self.named: dict = {}


def _is_return(b) -> bool:
    """``endsub``/``return`` without a value, or a line that is only ``M99``."""
    if b.kind == bk.OWORD:
        return b.keyword in ("endsub", "return") and not b.args
    call = b.call
    return (b.kind == bk.WORDS and call is not None and b.words == [call] and not b.sets
            and call.letter == "M" and bk.constant(call.code) == 99.0 and b.abort is None)


def find(unit, start: int) -> Leaf | None:
    """The leaf whose body starts at block ``start`` of ``unit`` (a Fanuc program's ``O``
    line is part of it), or None when that body is not a leaf."""
    blocks = unit.blocks
    spans = {i: span for i, (_, span) in runs(unit).items()}
    members, dispatches, i = [], 0, start
    if unit.fanuc and i < len(blocks) and blocks[i].kind == bk.PROGRAM:
        i, dispatches = i + 1, 1
    while i < len(blocks):
        b = blocks[i]
        if _is_return(b):
            return Leaf(tuple(members), dispatches + 1, b.kind == bk.OWORD) if members else None
        if b.kind == bk.WORDS and b.fast is not None and not b.reads_machine and b.abort is None:
            span = spans.get(i, 1)
            members.extend(m for m in blocks[i:i + span] if m.kind == bk.WORDS)
        elif _empty(unit, i):
            span = 1
        else:
            return None
        i, dispatches = i + span, dispatches + 1
    return None


def _leaf(unit, start: int) -> Leaf | None:
    known = unit.leaves
    if start not in known:
        known[start] = find(unit, start)
    return known[start]


def enter(w, unit, start: int, locals_: dict, name: str, file_id: int, program: int = 0,
          count: int = 1, caller_line: int = 0) -> None:
    """Run a call of ``name`` (block ``start`` of ``unit``, file ``file_id``): as a leaf
    when it is one and nothing stands in the way, else as a pushed frame."""
    leaf = _leaf(unit, start) if count == 1 and w.fast_ok else None
    if leaf is None or not _made(w, leaf, locals_, file_id, name):
        w._push(Frame(unit, start, locals_, name, file_id, program, count, caller_line))


def _made(w, leaf: Leaf, locals_: dict, file_id: int, name: str) -> bool:
    """Add the leaf's rows to the batch; False (nothing added) when it must run as a frame."""
    frames = w.frames
    saved = w.state.saved
    if len(frames) > DEPTH_LIMIT or (saved is not None and saved.get("auto")):
        return False
    if leaf.rows is None:
        leaf.rows = compile_rows([m.fast_code for m in leaf.members])
    scope, caller, held = w.scope, frames[-1], w.leaf_locals
    held.locals = locals_
    scope.frame = held
    try:
        made = leaf.rows(scope, w.where_id(file_id, name), caller.iteration)
    except Exception:  # noqa: BLE001  (run as a frame, which reports it with its line)
        return False
    finally:
        scope.frame = caller
    batch = w.batch
    batch.extend(made)
    batch.blocks.extend(leaf.members)
    w.blocks_run += leaf.dispatches
    if leaf.linuxcnc:
        w.scope.params.named["_value_returned"] = 0.0
    if len(batch.blocks) >= w.batch_limit:
        w.flush()
    return True
