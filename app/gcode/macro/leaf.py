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

A call line that always calls the same leaf (a constant ``P``, a named sub) gets its
own handler (``direct``): the leaf's rows computed straight from the line's values, its
locals never built.
"""

from __future__ import annotations

import math
import re
import struct

from . import block as bk
from .batch import ROW, compile_rows
from .expr import NAMESPACE
from .frame import DEPTH_LIMIT, Frame
from .loop import CALL
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


_LOCAL = re.compile(r"S\.frame\.locals\.get\((\d+)(?:, 0\.0)?\)")


def _direct_rows(codes: list[str], index: dict | None):
    """``fn(S, where, iteration, values)``: the rows of a leaf's row ``codes`` with its
    locals read straight from the call's ``values`` (Fanuc: the tuple of the line's
    words, ``index``: local -> place of its word; LinuxCNC: the dict of the arguments),
    or None when the codes read their frame otherwise (a named local)."""
    def local(found) -> str:
        n = int(found.group(1))
        if index is None:
            return f"v.get({n}, 0.0)"
        return f"v[{index[n]}]" if n in index else "None"

    flat = ", ".join(_LOCAL.sub(local, code[1:-1]) for code in codes)
    if "S.frame" in flat or "S.named" in flat or "S.has" in flat:
        return None
    namespace = {**NAMESPACE, "nan": math.nan, "pack": struct.Struct(f"<{ROW * len(codes)}d").pack}
    return eval(f"lambda S, w, it, v: pack({flat})", namespace)  # noqa: S307


def direct(unit, start: int, name: str, file_id: int, index: dict | None, repeat: int, slow):
    """A handler for a call line that always calls the leaf at block ``start`` of
    ``unit``: its rows straight from the line's values (``_direct_rows``), or None when
    that body is not a leaf. ``repeat``: the place of a Fanuc ``L`` word (-1: none);
    ``slow(w, f, b, values)``: the call's general handler, for every other case."""
    found = _leaf(unit, start)
    rows = _direct_rows([m.fast_code for m in found.members], index) if found is not None else None
    if rows is None:
        return None
    linuxcnc = found.linuxcnc

    def run(w, f, b):
        values = b.values(w.scope)
        if (not w.fast_ok or len(w.frames) > DEPTH_LIMIT or _m73_waits(w)
                or (None in values.values() if linuxcnc else repeat >= 0 and _repeats(values[repeat]))):
            return slow(w, f, b, values)
        f.pc += 1
        try:
            made = rows(w.scope, w.where_id(file_id, name), f.iteration, values)
        except Exception:  # noqa: BLE001  (the general handler runs it as a frame, which reports it)
            f.pc -= 1
            return slow(w, f, b, values)
        _add(w, found, made)
        return None

    run.step = CALL  # a step of a compiled loop (loop.py)
    return run


def _repeats(count) -> bool:
    """True when an ``L`` word's value asks for anything but one call."""
    return count is not None and int(count) != 1


def _m73_waits(w) -> bool:
    """An ``M73`` saved the modal state for the return of a call level (``modal_state``)."""
    saved = w.state.saved
    return saved is not None and bool(saved.get("auto"))


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
    if len(frames) > DEPTH_LIMIT or _m73_waits(w):
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
    _add(w, leaf, made)
    return True


def _add(w, leaf: Leaf, made: bytes) -> None:
    """The rows ``made`` by a call of ``leaf`` into the batch, its blocks counted, its
    return done (LinuxCNC: no value returned)."""
    batch = w.batch
    batch.extend(made)
    batch.blocks.extend(leaf.members)
    w.blocks_run += leaf.dispatches
    if leaf.linuxcnc:
        w.scope.params.named["_value_returned"] = 0.0
    if len(batch.blocks) >= w.batch_limit:
        w.flush()
