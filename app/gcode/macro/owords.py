"""LinuxCNC o-word statements, run by the walker (``oword(walker, frame, block)``).

``sub`` met in the flow is skipped to after its ``endsub``; ``call`` pushes a frame
whose ``#1``.. hold the arguments (the others read 0) and whose named locals start
empty; ``return``/``endsub`` pop it and leave their value in ``#<_value>`` (and
``#<_value_returned>`` = 1, else 0). ``if``/``elseif``/``else``/``endif``, ``while``/
``endwhile``, ``do``/``while``, ``repeat``/``endrepeat``, ``break`` and ``continue``
use the jump tables of ``structure.Unit``; every jump back counts toward the loop limit.
"""

from __future__ import annotations

from app.i18n import msg

from . import leaf
from .errors import MacroError
from .frame import Frame


def _sub(w, f: Frame, b) -> None:
    f.pc = f.unit.jump[f.pc]


def _computed_name(w, b) -> str:
    """The o-word number of ``o[expr] call``, computed now."""
    value = b.onumber(w.scope)
    if value is None or value != int(value) or value < 0:
        raise MacroError(msg("o[...] call: {value} is not an o-word number", value=value))
    return str(int(value))


def _call(w, f: Frame, b) -> None:
    call_with(w, f, b, b.values(w.scope))


def call_with(w, f: Frame, b, locals_: dict) -> None:
    """``call`` with the arguments' values ``locals_`` computed."""
    name = b.oname if b.onumber is None else _computed_name(w, b)
    key = f.file_id if b.onumber is None else (f.file_id, name)
    target = b.called.get(key)
    if target is None:
        file_id, start = w.library.subroutine(name, f.file_id)
        target = b.called[key] = (w.library.units[file_id], start + 1, file_id)
    f.pc += 1
    if None in locals_.values():
        locals_ = {i: (0.0 if v is None else v) for i, v in locals_.items()}
    unit, start, file_id = target
    if not b.specialized and b.onumber is None:
        b.specialized = True  # the line always calls this sub: straight to its rows if a leaf
        b.run = leaf.direct(unit, start, b.context, file_id, None, -1, call_with) or b.run
    context = b.context if b.onumber is None else f"o{name}"
    leaf.enter(w, unit, start, locals_, context, file_id, caller_line=b.line)


def _return(w, f: Frame, b) -> None:
    named = w.scope.params.named
    if b.args:
        value = b.args[0](w.scope)
        named["_value"] = 0.0 if value is None else float(value)
        named["_value_returned"] = 1.0
    else:
        named["_value_returned"] = 0.0
    if len(w.frames) == 1:
        raise MacroError(msg("o{name} {keyword} reached outside a call", name=b.oname, keyword=b.keyword))

    w._pop()


def _if(w, f: Frame, b) -> None:
    if w.test(b.args[0]):
        f.pc += 1
        return
    blocks, jump = f.unit.blocks, f.unit.jump
    target = jump[f.pc]
    while blocks[target].keyword == "elseif":
        if w.test(blocks[target].args[0]):
            f.pc = target + 1
            return
        target = jump[target]
    f.pc = target + 1  # past 'else' into its branch, or past 'endif'


def _branch_end(w, f: Frame, b) -> None:
    f.pc = f.unit.back[f.pc]  # the end of a taken branch: past endif


def _next(w, f: Frame, b) -> None:
    f.pc += 1


def _do(w, f: Frame, b) -> None:
    w.loop_pass(f, f.pc)
    f.pc += 1


def _do_while(w, f: Frame, b) -> None:
    back = f.unit.back[f.pc]  # the 'while' closing a 'do'
    v = b.args[0](w.scope)
    if v is not None and v != 0.0:
        w.loop_back(f, back - 1)
        f.pc = back
    else:
        w.loop_done(f, back - 1)
        f.pc += 1


def _while(w, f: Frame, b) -> None:
    w.loop_test(f, w.test(b.args[0]))


def _endwhile(w, f: Frame, b) -> None:
    """Back to the ``while`` and its test at once (see ``fanuc.end``)."""
    head = f.unit.back[f.pc]
    w.loop_back(f, head)
    f.pc = head
    if head not in f.unit.loops:  # a compiled loop tests in its handler
        w.blocks_run += 1
        w.loop_test(f, w.test(f.unit.blocks[head].args[0]))


def _repeat(w, f: Frame, b) -> None:
    count = b.args[0](w.scope) or 0.0
    if count >= 1:
        f.repeat_left[f.pc] = int(count)
        w.loop_pass(f, f.pc)
        f.pc += 1
    else:
        f.pc = f.unit.jump[f.pc]


def _endrepeat(w, f: Frame, b) -> None:
    head = f.unit.back[f.pc]
    left = f.repeat_left[head] - 1
    if left > 0:
        f.repeat_left[head] = left
        w.loop_back(f, head)
        f.pc = head + 1
    else:
        f.repeat_left.pop(head, None)
        w.loop_done(f, head)
        f.pc += 1


def _break(w, f: Frame, b) -> None:
    head = f.unit.back[f.pc]
    f.repeat_left.pop(head, None)
    w.loop_done(f, head)
    f.pc = f.unit.jump[head]


def _continue(w, f: Frame, b) -> None:
    head = f.unit.back[f.pc]
    keyword = f.unit.blocks[head].keyword
    if keyword == "while":
        w.loop_back(f, head)
        f.pc = head
    else:  # do: the closing while tests; repeat: endrepeat counts
        f.pc = f.unit.jump[head] - 1


HANDLERS = {
    "sub": _sub, "call": _call, "return": _return, "endsub": _return, "if": _if,
    "elseif": _branch_end, "else": _branch_end, "endif": _next, "while": _while, "do-while": _do_while,
    "endwhile": _endwhile, "do": _do, "repeat": _repeat, "endrepeat": _endrepeat,
    "break": _break, "continue": _continue,
}


def handler(b):
    """The function that runs o-word statement ``b``."""
    return HANDLERS[b.keyword]
