"""Lines of G-code words (and assignments), run by the walker: ``fn(walker, frame, block)``.

``words`` is the general case: every value is read first, then the words go to the
batch (plain G0-G3 moves) or to ``interpret_line`` (``Walker.emit``), then the line's
assignments apply, then a Fanuc call on the line runs (``M98``/``M99``/``G65``; on
an ``M98``/``M99`` line the motion runs first). The others are the same rules for
lines of one shape, chosen once per block by ``handler``: moves only
(``simple_words``), assignments only, a call only, a planned ``G65`` (``fanuc.g65``), a
bare ``M99``.
A block that starts a straight run of moves runs the whole run (``runs.py``).
"""

from __future__ import annotations

import re

from app.gcode.lexer import Word
from app.gcode.percent import abort_message
from app.i18n import msg

from . import block as bk
from . import fanuc, loop, owords, predefined
from .errors import MacroError
from .frame import Frame
from .owords import handler as oword_handler
from .plain import run_chunk
from .runs import run_handler, runs


def words(w, f: Frame, b: bk.Block) -> None:
    values = b.values(w.scope) if b.values is not None else ()
    f.pc += 1
    call = None
    if not b.words or b.call_only:
        pass
    elif b.simple and w.fast_ok and w.batch.add(b, values, f.iteration, f.wid):
        if len(w.batch) >= w.batch_limit:
            w.flush()
    else:
        call = general(w, f, b, values)
    if b.assigns:
        b.store(w.scope, values)
    if b.call_only:
        call_words_of(w, f, b, values)
    elif call is not None:
        _computed_call(w, f, call)


def simple_words(w, f: Frame, b: bk.Block) -> None:
    """``words`` for a block of G0-G3 X Y Z I J F words: straight into the batch."""
    f.pc += 1
    batch = w.batch
    if b.fast is not None and w.fast_ok:  # no assignments, a constant G0-G3 or none
        batch.extend(b.fast(w.scope, f.wid, f.iteration))
        batch.append(b)
        if len(batch.blocks) >= w.batch_limit:
            w.flush()
        return
    values = b.values(w.scope)
    made = b.row(values, f.wid, f.iteration) if w.fast_ok else None
    call = None
    if made is None:
        call = general(w, f, b, values)
    else:
        batch.extend(made)
        batch.append(b)
        if len(batch.blocks) >= w.batch_limit:
            w.flush()
    if b.assigns:
        b.store(w.scope, values)
    if call is not None:  # a computed G65 (G#1 with #1 = 65)
        _computed_call(w, f, call)


def call_words(w, f: Frame, b: bk.Block) -> None:
    """``words`` for a Fanuc line that is only a call (``b.call_only``)."""
    values = b.values(w.scope)
    f.pc += 1
    if b.assigns:
        b.store(w.scope, values)
    call_words_of(w, f, b, values)


def call_words_of(w, f: Frame, b: bk.Block, values) -> None:
    call = b.call
    given = list(zip(b.words, values, strict=False))
    pairs = [(word.letter, v) for word, v in given if v is not None and word is not call]
    code = next(v for word, v in given if word is call)
    fanuc.call(w, f, b, call.letter, code, call.column, dict(pairs), pairs)


def return_only(w, f: Frame, b: bk.Block) -> None:
    """``call_words`` for a line that is only ``M99`` (no P, L, nor assignments)."""
    f.pc += 1
    if len(w.frames) == 1:
        raise fanuc.main_m99()
    fanuc.leave(w, f, None)


def assignments(w, f: Frame, b: bk.Block) -> None:
    """``words`` for a line of assignments only."""
    values = b.values(w.scope)
    f.pc += 1
    b.store(w.scope, values)


def general(w, f: Frame, b: bk.Block, values) -> tuple | None:
    """Interpret the line's words (their ``values`` known); returns the Fanuc call found
    among computed words, to run after the line's assignments: (block, call, other words)."""
    line_words = []
    for word, v in zip(b.words, values, strict=False):
        if v is None:
            if word.bare:
                continue  # Fanuc: a word whose parameter is vacant is left out
            v = 0.0
        line_words.append(Word(word.letter, v, word.column))
    if w.fanuc:
        line_words = fanuc.dwell_words(line_words)
    call = _call_word(line_words) if w.fanuc else None
    if call is None:
        if line_words:
            w.emit(f, b, line_words)
        return None
    if call.letter == "M":  # motion on an M98/M99 line runs first
        rest = [word for word in line_words if word is not call and word.letter not in "PL"]
        if rest:
            w.emit(f, b, rest)
    return b, call, [word for word in line_words if word is not call]


def _computed_call(w, f: Frame, pending: tuple) -> None:
    block, call, line_words = pending
    pairs = [(word.letter, word.value) for word in line_words]
    fanuc.call(w, f, block, call.letter, call.value, call.column, dict(pairs), pairs)


def _call_word(line_words: list[Word]) -> Word | None:
    """The M98/M99/G65 word of a Fanuc line whose values were computed, if any."""
    for word in line_words:
        if (word.letter == "M" and word.value in (98.0, 99.0)) or (word.letter == "G" and word.value == 65.0):
            return word
    return None


def skip(w, f: Frame, b: bk.Block) -> None:
    """A line that does not compile was reported before the walk; the program cannot run,
    but the walk goes on past it so that the lines after it are checked too (all of a
    file's problems at once, as the plain path finds them)."""
    if f.pc in f.unit.bad:
        f.pc += 1
        return
    if b.skip == "block delete":
        w.reports[f.file_id].warning(b.line, 0, msg("block delete '/': line skipped"), "block delete")
    f.pc += 1


HANDLERS = {
    bk.WORDS: words, bk.SKIP: skip, bk.PLAIN: run_chunk, bk.PROGRAM: fanuc.program, bk.IF_GOTO: fanuc.if_goto,
    bk.IF_THEN: fanuc.if_then, bk.GOTO: fanuc.goto, bk.WHILE: fanuc.while_do, bk.DO: fanuc.do,
    bk.END: fanuc.end,
}


_PARAMETER = re.compile(r"#(\d+)|#<([^>]+)>")


def abort(w, f: Frame, b: bk.Block) -> None:
    """An ``(ABORT, text)`` line: the program stops with the text, its parameters
    (``#1``, ``#<name>``) replaced by their values as LinuxCNC prints them (``%f``)."""
    def value(found) -> str:
        number, name = found.groups()
        name = (name or "").lower().replace(" ", "")
        v = w.scope.num(int(number)) if number else (
            w.scope.system(name) if name in predefined.FROM_STATE else w.scope.named(name))
        return found.group(0) if v is None else f"{v:f}"

    raise MacroError(abort_message(_PARAMETER.sub(value, b.abort)))


def handler(b: bk.Block):
    """The function that runs block ``b`` (chosen once per block)."""
    if b.abort is not None:
        return abort
    if b.kind == bk.OWORD:
        return oword_handler(b)
    if b.kind == bk.WORDS and not b.words and b.values is not None:
        return assignments
    if b.kind == bk.WORDS and b.simple and not b.call_only:
        return simple_words
    if b.kind == bk.WORDS and b.call_only and b.words:
        bare_m99 = len(b.words) == 1 and b.words[0] is b.call and b.call.letter == "M" and not b.assigns
        if bare_m99 and bk.constant(b.call.code) == 99.0:
            return return_only
        b.plan = fanuc.g65_plan(b) if b.call.letter == "G" else None
        return call_words if b.plan is None else fanuc.g65
    return HANDLERS[b.kind]


STEPS = {assignments: loop.ASSIGN, simple_words: loop.MOVE, call_words: loop.CALL, fanuc.g65: loop.CALL,
         owords.HANDLERS["call"]: loop.CALL}  # the handlers of blocks a compiled loop runs itself


def bind(unit) -> None:
    """Give every block of ``unit`` the handler that runs it (once per unit); a block
    that starts a straight run of moves runs the whole run (``runs.py``), the head of
    a loop the whole loop when its body is straight (``loop.py``)."""
    for i in unit.starts:
        unit.blocks[i].run = handler(unit.blocks[i])
    for i, (members, span) in runs(unit).items():
        unit.blocks[i].run = run_handler(members, span, unit.blocks[i].run)
    for i in unit.starts:
        b = unit.blocks[i]
        if b.kind == bk.WHILE or b.kind == bk.OWORD and b.keyword == "while":
            unit.loops.add(i)
            b.run = loop.lazy_loop(unit, i, STEPS, b.run)
    unit.bound = True
