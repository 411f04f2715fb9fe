"""Innermost loops compiled into one Python function each: the walk runs their passes
without dispatching their blocks one at a time.

A Fanuc ``WHILE [c] DO m`` ... ``END m`` or a LinuxCNC ``o.. while`` ... ``endwhile``
whose body holds only straight steps (assignments to plain parameters, plain moves
and straight runs of them on the fast path, calls, empty lines) gets, at its head, a
handler generated from its body (on its first run; a loop never run is never
compiled). Each pass does what the blocks' own handlers do, in order, counted as
the walk counts them (the work budget, the loop limit, the loop pass of each row).
The function hands the walk back at the block where anything unusual happens, and
that block then runs through its own handler, which does and reports exactly what it
always did:

- a step whose expression raises (an assignment or a move has no effect before its
  values are known): the walk runs that block;
- a call that pushed a frame (not a leaf, ``leaf.py``), or after which the fast path is
  off: the walk runs the frame, then the rest of the pass block by block, and the
  loop's end comes back to the head;
- the loop limit reached: the walk runs the loop's end, which refuses it;
- the head's test raising: the head's own handler runs and raises it.
"""

from __future__ import annotations

from app.gcode.params import LAST

from . import block as bk
from .batch import compile_rows
from .errors import MacroError
from .expr import FANUC_SYSTEM, MACHINE_PARAMETERS
from .runs import _empty, runs

ASSIGN, MOVE, CALL = "assign", "move", "call"


def _safe_store(b, fanuc: bool) -> bool:
    """True when storing ``b``'s values cannot fail: fixed plain parameters only."""
    limit = min(FANUC_SYSTEM if fanuc else MACHINE_PARAMETERS, LAST + 1)
    return b.values is not None and all(type(t) is int and 0 < t < limit for t, _ in b.assigns)


def _straight(b, kind: str | None, fanuc: bool) -> bool:
    """True when block ``b``, whose handler is of ``kind``, can be a step of a compiled loop."""
    if kind == ASSIGN:
        return _safe_store(b, fanuc)
    return kind == CALL or kind == MOVE and b.fast is not None


def _end(unit, head: int) -> int | None:
    """The index of the block closing the loop whose head is ``head``, or None."""
    b, after = unit.blocks[head], unit.jump.get(head)
    if after is None or unit.back.get(after - 1) != head:
        return None
    if unit.fanuc and b.kind == bk.WHILE or b.kind == bk.OWORD and b.keyword == "while":
        return after - 1
    return None


def _steps(unit, head: int, end: int, kinds: dict) -> list[tuple] | None:
    """(kind, first index, span) per step of the body, or None when a block is not straight."""
    spans = {i: span for i, (_, span) in runs(unit).items()}
    steps, i = [], head + 1
    while i < end:
        b = unit.blocks[i]
        kind = kinds.get(b.run, getattr(b.run, "step", None))
        if i in spans and i + spans[i] <= end:
            steps.append((MOVE, i, spans[i]))
            i += spans[i]
            continue
        if _empty(unit, i):
            steps.append(("", i, 1))
        elif _straight(b, kind, unit.fanuc):
            steps.append((kind, i, 1))
        else:
            return None
        i += 1
    return steps


_HEAD = """def loop(w, f, b):
    if not w.fast_ok:
        return slow(w, f, b)
    S, batch, frames, counts, wid = w.scope, w.batch, w.frames, f.counts, f.wid
    ext, blocks = batch.extend, batch.blocks
    more, app = blocks.extend, blocks.append
    count = counts.get({head}, 0)
    left, ran = w.work_left(), -1  # the walk counted this dispatch of the head
    try:
        while True:
            if ran > left:
                w.blocks_run += ran
                ran, left = 0, w.work_left()
                if left < 0:
                    raise w._over_budget()
            ran += 1
            try:
                v = test(S)
            except Exception:
                f.pc = {head}
                return slow(w, f, b)  # raises it as the head would
            if v is None or v == 0.0:
                counts.pop({head}, None)
                f.iteration, f.pc = 0, {exit}
                return
            f.iteration = it = count + 1
"""
_TAIL = """            ran += 1  # the loop's end
            count += 1
            if count > LOOP_LIMIT:  # the loop's end refuses it
                f.pc, ran = {end}, ran - 1
                return
            counts[{head}] = count
    finally:
        w.blocks_run += ran
"""
_FLUSH = """            if len(blocks) >= w.batch_limit:
                f.pc = {after}
                try:
                    w.flush()
                except MacroError as exc:
                    raise exc.at(B{i}.line, FILE) from None
                if not w.fast_ok:
                    return
"""
_VALUE = """            try:
                x = {code}
            except Exception:
                f.pc, ran = {i}, ran - 1
                return
"""


def _step(kind: str, i: int, span: int, namespace: dict, unit) -> str:
    b = unit.blocks[i]
    namespace[f"B{i}"] = b
    code = "            ran += 1\n"
    if kind == ASSIGN:
        code += _VALUE.format(code=f"B{i}.values(S)", i=i) + f"            B{i}.store(S, x)\n"
        if b.reads_machine:  # its read interpreted the batch: the fast path may be off
            code += f"            if not w.fast_ok:\n                f.pc = {i + 1}\n                return\n"
        return code
    if kind == MOVE and span == 1:
        return code + _VALUE.format(code=f"B{i}.fast(S, wid, it)", i=i) + (
            f"            ext(x)\n            app(B{i})\n" + _FLUSH.format(after=i + 1, i=i))
    if kind == MOVE:
        members = [m for m in unit.blocks[i:i + span] if m.kind == bk.WORDS]
        namespace[f"R{i}"], namespace[f"M{i}"] = compile_rows([m.fast_code for m in members]), tuple(members)
        return code + _VALUE.format(code=f"R{i}(S, wid, it)", i=i) + (
            f"            ext(x)\n            more(M{i})\n" + _FLUSH.format(after=i + span, i=i))
    if kind == CALL:
        return code + f"""            f.pc = {i}
            try:
                B{i}.run(w, f, B{i})  # its handler may be made for its program on a first run
            except MacroError as exc:
                raise exc.at(B{i}.line, FILE) from None
            except FAULTS as exc:
                raise fault(exc).at(B{i}.line, FILE) from None
            if frames[-1] is not f or not w.fast_ok:
                return
"""
    return code


def compile_loop(unit, head: int, kinds: dict, slow, file: str):
    """The handler running the loop whose head is block ``head`` of ``unit`` (see the
    module docstring), or None when its body is not straight. ``kinds``: the blocks'
    handlers that are steps (handler -> ASSIGN, MOVE or CALL); ``slow``: the head's own
    handler; ``file``: the unit's name in messages ("" for the main file)."""
    end = _end(unit, head)
    steps = _steps(unit, head, end, kinds) if end is not None else None
    if not steps:
        return None
    from .walker import FAULTS, LOOP_LIMIT, fault  # the walker imports the handlers

    namespace = {"slow": slow, "test": unit.blocks[head].args[0], "MacroError": MacroError,
                 "FAULTS": FAULTS, "fault": fault, "LOOP_LIMIT": LOOP_LIMIT, "FILE": file}
    said = dict(head=head, exit=unit.jump[head], end=end)
    source = _HEAD.format(**said) + "".join(_step(*s, namespace, unit) for s in steps) + _TAIL.format(**said)
    exec(source, namespace)  # noqa: S102  (code generated from the compiled blocks)
    return namespace["loop"]


def lazy_loop(unit, head: int, kinds: dict, slow):
    """The head's handler: compiles the loop on its first run (``compile_loop``), or
    falls back to ``slow`` for good when the body is not straight."""
    def first_run(w, f, b):
        compiled = compile_loop(unit, head, kinds, slow, f.unit.name if f.file_id else "")
        if compiled is None:
            unit.loops.discard(head)
        b.run = compiled or slow
        return b.run(w, f, b)

    return first_run
