"""Fanuc macro B statements, run by the walker (``fn(walker, frame, block)``).

``M98 Pn Lk`` (and the packed ``M98 Pkkknnnn``) runs program ``On`` k times with the
caller's locals; ``G65 Pn Lk`` with new locals from its arguments (specification I);
``M99`` returns (``M99 Pn``: to the caller's block ``Nn``), and runs the program again
while repetitions are left. ``GOTO n`` / ``IF [c] GOTO n`` jump to block ``Nn`` of the
same program (a jump back counts toward the loop limit), ``IF [c] THEN`` assigns,
``WHILE [c] DO m`` / ``DO m`` / ``END m`` loop. An ``O`` line met in the flow ends the
program it does not start (the main program stops; a subprogram returns).
"""

from __future__ import annotations

from app.gcode.lexer import Word
from app.i18n import msg

from . import leaf
from .block import WHILE, constant
from .calls import FANUC_ARGUMENTS, fanuc_arguments
from .errors import MacroError
from .frame import Frame

_G65_WORDS = frozenset(FANUC_ARGUMENTS) | {"G", "P", "L"}


def dwell_words(words: list) -> list:
    """A Fanuc ``G04`` line's words as the interpreter reads them: Fanuc gives the dwell
    as ``X`` in seconds or ``P`` in milliseconds, the interpreter as ``P`` in seconds."""
    if not any(word.letter == "G" and word.value == 4.0 for word in words):
        return words
    return [Word("P", word.value / 1000.0, word.column) if word.letter == "P"
            else Word("P", word.value, word.column) if word.letter == "X" else word for word in words]


def main_m99() -> MacroError:
    """M99 reached in the main program."""
    return MacroError(msg("M99 ends the main program: a Fanuc control starts it again, for ever "
                          "(the loop is stopped here after one pass; end the program with M30)"))


def call(w, f: Frame, b, letter: str, code: float, column: int, by_letter: dict, pairs=None) -> None:
    """Run ``M98``/``G65`` (a call) or ``M99`` (a return); ``by_letter``: the other words
    (``pairs``: all of them as (letter, value) in line order, when a letter may repeat)."""
    if letter == "M" and code == 99.0:
        if len(w.frames) == 1:
            raise main_m99()
        leave(w, f, by_letter.get("P"))
        return
    if "P" not in by_letter:
        raise MacroError(msg("{letter}{code:g} needs P (the program number)", letter=letter,
                             code=float(code)),
                         b.line, column)
    number, count = int(by_letter["P"]), int(by_letter.get("L", 1))
    if letter == "M" and "L" not in by_letter and number > 9999:
        number, count = number % 10000, number // 10000  # packed M98 Pkkknnnn
    if count < 1:
        return
    file_id, start = w.library.program(number, f.file_id)
    if letter == "M":
        locals_ = f.locals  # M98 keeps the caller's local level
    else:
        locals_ = fanuc_arguments(pairs if pairs is not None else by_letter.items())
        extra = [] if by_letter.keys() <= _G65_WORDS else sorted(set(by_letter) - _G65_WORDS)
        if extra:
            said = msg("G65 cannot pass {words} (argument specification I)", words=", ".join(extra))
            raise MacroError(said, b.line)

    unit = w.library.units[file_id]
    program = unit.program_of[start] if unit.program_of else 0
    leaf.enter(w, unit, start, locals_, f"O{number:04d}", file_id, program, count, b.line)


def g65_plan(b) -> tuple | None:
    """For a ``G65 P..`` line of distinct argument letters and no assignments: (index of
    P, index of L or -1, fn(values) -> the locals its arguments set, a cache of the
    programs it called) for ``g65``; else None."""
    letters = [w.letter for w in b.words]
    if b.assigns or len(set(letters)) != len(letters) or "P" not in letters:
        return None
    if not _G65_WORDS.issuperset(letters):
        return None
    args = fanuc_arguments((c, i) for i, c in enumerate(letters))  # local -> index of its word
    given = eval("lambda v: {" + "".join(f"{n}: v[{i}], " for n, i in args.items()) + "}")  # noqa: S307
    return letters.index("P"), letters.index("L") if "L" in letters else -1, given, {}


def g65(w, f: Frame, b) -> None:
    """The handler of a ``G65`` line planned by ``g65_plan``: ``call``'s rules, fewer steps."""
    g65_with(w, f, b, b.values(w.scope))


def g65_with(w, f: Frame, b, values) -> None:
    """``g65`` with the line's ``values`` computed."""
    f.pc += 1
    p, repeat, given, called = b.plan
    number = values[p]
    if number is None:
        raise MacroError(msg("G65 needs P (the program number)"), b.line, b.call.column)
    count = 1 if repeat < 0 or values[repeat] is None else int(values[repeat])
    if count < 1:
        return
    key = (int(number), f.file_id)
    target = called.get(key)
    if target is None:
        target = called[key] = _program(w, *key)
    unit, start, program, name, file_id = target
    if not b.specialized and count == 1 and constant(b.words[p].code) is not None:
        b.specialized = True  # the line always calls this program: straight to its rows if a leaf
        index = fanuc_arguments((word.letter, i) for i, word in enumerate(b.words))
        b.run = leaf.direct(unit, start, name, file_id, index, repeat, g65_with) or b.run
    locals_ = given(values)
    if None in locals_.values():  # a vacant argument sets nothing
        locals_ = {n: v for n, v in locals_.items() if v is not None}
    leaf.enter(w, unit, start, locals_, name, file_id, program, count, b.line)


def _program(w, number: int, caller: int) -> tuple:
    """(unit, first block, program start, trace name, file id) of program ``O<number>``."""
    file_id, start = w.library.program(number, caller)
    unit = w.library.units[file_id]
    return unit, start, unit.program_of[start] if unit.program_of else 0, f"O{number:04d}", file_id


def leave(w, f: Frame, label) -> None:
    """The end of a subprogram: again while repetitions are left, else back to the caller."""
    if f.calls_left > 1:
        f.calls_left -= 1
        w.loop_back(f, f.program)
        f.pc = f.program
        return
    w._pop()
    caller = w.frames[-1]
    if label is not None:
        caller.pc = _label(caller, int(label))


def _label(f: Frame, n: int) -> int:
    target = f.unit.labels.get((f.program, n))
    if target is None:
        raise MacroError(msg("GOTO {n}: no block N{n} in this program", n=n))
    return target


def _jump(w, f: Frame, value) -> None:
    if value is None:
        raise MacroError(msg("GOTO to a vacant label"))

    target = _label(f, int(round(value)))
    if target <= f.pc:
        w.loop_back(f, target)
    f.pc = target


def goto(w, f: Frame, b) -> None:
    _jump(w, f, b.args[-1](w.scope))


def if_goto(w, f: Frame, b) -> None:
    if w.test(b.args[0]):
        _jump(w, f, b.args[1](w.scope))
    else:
        f.pc += 1


def if_then(w, f: Frame, b) -> None:
    if w.test(b.args[0]):
        b.store(w.scope, b.values(w.scope))
    f.pc += 1


def while_do(w, f: Frame, b) -> None:
    w.loop_test(f, w.test(b.args[0]))


def do(w, f: Frame, b) -> None:
    w.loop_pass(f, f.pc)
    f.pc += 1


def end(w, f: Frame, b) -> None:
    """Back to the loop's head; a ``WHILE`` head is tested at once (as the walk would
    run it next: one dispatch fewer per pass, the block counted all the same)."""
    head = f.unit.back[f.pc]
    w.loop_back(f, head)
    f.pc = head
    top = f.unit.blocks[head]
    if top.kind == WHILE and head not in f.unit.loops:  # a compiled loop tests in its handler
        w.blocks_run += 1
        w.loop_test(f, w.test(top.args[0]))


def program(w, f: Frame, b) -> None:
    if f.pc == f.program:
        f.pc += 1
    elif len(w.frames) == 1:
        w.frames.clear()  # the main program ran into the next program's O line
    else:
        leave(w, f, None)
