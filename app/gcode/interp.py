"""The general modal interpreter: one lexed line at a time, LinuxCNC semantics.

``interpret_line(state, words, line_no, ops, report)`` checks the whole line first
(unknown and refused words, two codes of one modal group, words with nothing to use
them), then applies it in rs274ngc's order: F, S, T, tool change (a pause), spindle,
modal state save/restore (M70-M73), dwell, plane, units, cutter compensation, tool
length offset, coordinate system, distance modes, retract mode, G10/G92/G52/G28/G30,
motion, stop codes. A refused line changes nothing: the state is copied and only committed
(parameters included) when the line succeeds, so a file with errors still loads as
far as it can. Arcs are in ``motion.py``, cycles in ``cycles.py``, offsets in
``offsets.py``, tools in ``tooling.py``, compensation in ``comp.py``.
"""

from __future__ import annotations

from app.i18n import msg

from . import comp, modal_state, offsets, tooling
from .diagnostics import Report
from .errors import LineError
from .lexer import Word
from .limits import word_problem
from .motion import do_motion, go_stored
from .ops import END, PAUSE, SPINDLE, OpBuffer
from .state import State
from .stops import stop_value
from .usage import check_usage
from .words import ALLOWED_LETTERS, G_CODES, M_CODES, REFUSED_G, REFUSED_LETTERS

__all__ = ["LineError", "interpret_line", "finish_program"]


def _gname(code: float) -> str:
    return f"G{code:g}"


def _check_letters(words: list[Word]) -> dict[str, Word]:
    """Letter -> word of the line's non-G/M words; refuses unknown letters, repeats and
    numbers no word may hold (``limits.word_problem``: the lexer checks typed numbers,
    this also checks those a macro computed)."""
    params: dict[str, Word] = {}
    for w in words:
        if w.letter in REFUSED_LETTERS or w.letter not in ALLOWED_LETTERS:
            raise LineError(w.column, REFUSED_LETTERS.get(w.letter) or msg("unknown word {letter}",
                                                                           letter=w.letter))
        problem = word_problem(w.letter, w.value)
        if problem:
            raise LineError(w.column, problem)
        if w.letter in "GM":
            continue
        if w.letter in params:
            raise LineError(w.column, msg("two {letter} words on one line", letter=w.letter))
        params[w.letter] = w
    return params


def _check_codes(words: list[Word]) -> tuple[dict[str, tuple], dict[str, tuple]]:
    """Group -> (code, word) for the G and M words; refuses unknown and conflicts."""
    groups: dict[str, tuple] = {}
    mgroups: dict[str, tuple] = {}
    for w in words:
        if w.letter == "G":
            code = round(w.value, 4)
            if code in REFUSED_G:
                reason = msg(REFUSED_G[code])
                raise LineError(w.column, msg("{code}: {reason}", code=_gname(code), reason=reason))
            if code not in G_CODES:
                raise LineError(w.column, msg("unknown G-code {code}", code=_gname(code)))
            table, name = groups, G_CODES[code][0]
        elif w.letter == "M":
            code = w.value
            if code != int(code) or int(code) not in M_CODES:
                raise LineError(w.column, msg("unknown M-code {code}", code=f"M{code:g}"))
            table, name = mgroups, M_CODES[int(code)][0]
        else:
            continue
        if name == "motion" and name in table and 80 in (code, table[name][0]):
            if code != 80:  # rs274ngc: G80 beside another motion code gives way to it
                table[name] = (code, w)
            continue
        if name in table:
            other = table[name][1]
            first, second = f"{other.letter}{other.value:g}", f"{w.letter}{w.value:g}"
            raise LineError(w.column, msg("two codes of one modal group on one line: {first} and {second}",
                                          first=first, second=second))
        table[name] = (code, w)
    return groups, mgroups


def _set_feed_speed(state: State, params) -> None:
    """F and S come first, as in rs274ngc: F is read in the units before this line's G20/G21."""
    if "F" in params:
        state.feed = params["F"].value * state.scale
    if "S" in params:
        state.speed = params["S"].value


def _spindle(state: State, mgroups, params, line_no, ops: OpBuffer, report: Report) -> None:
    spin = mgroups.get("spindle")
    if spin is None:
        if "S" in params and state.spindle_on:
            ops.add(line_no, SPINDLE, state.pos, value=state.speed)
        return
    kind = M_CODES[int(spin[0])][1]
    if kind == "ccw":
        report.warning(line_no, spin[1].column,
                       msg("M4 (counter-clockwise) runs as M3: the spindle turns one way"), "M4 runs as M3")
    state.spindle_on = kind != "off"
    ops.add(line_no, SPINDLE, state.pos, value=(state.speed or -1.0) if state.spindle_on else 0.0)


def _pause(line_no, column, message, ops: OpBuffer, state: State, report: Report, stop: float = 0.0) -> None:
    report.warning(line_no, column, message, message)
    ops.add(line_no, PAUSE, state.pos, value=stop,
            message=msg("line {line}: {message}", line=line_no, message=message))


def _tool_change(state, mgroups, params, line_no, ops, report) -> None:
    if not tooling.select(state, params):
        report.warning(line_no, params["T"].column,
                       msg("tool {tool} is not in the tool table: its length and diameter read 0",
                           tool=f"T{state.selected}"), "tool not in the table")
    if "toolchange" not in mgroups:
        return
    code, word = mgroups["toolchange"]
    if state.comp is not None:
        raise LineError(word.column, msg("cannot change tools with cutter radius compensation on"))
    kind = M_CODES[int(code)][1]
    tooling.change(state, kind, params, word.column)
    if kind == "change":
        named = "T" in params or state.selected
        tool = f" T{state.selected}" if named else ""
        _pause(line_no, word.column,
               msg("tool change{tool} M6: this machine has one tool; the job pauses here", tool=tool),
               ops, state, report, stop_value(6, state.selected if named else None))


def _stop(state, mgroups, line_no, ops, report) -> None:
    stop = mgroups.get("stop")
    if stop is None:
        return
    code = int(stop[0])
    if M_CODES[code][1] == "end":
        finish_program(state, ops)
        state.ended = line_no
        ops.add(line_no, END, state.pos)
    else:
        comp.flush(state, ops)
        message = msg("M{code} program stop: the job pauses here", code=code)
        _pause(line_no, stop[1].column, message, ops, state, report, stop_value(code))


def finish_program(state: State, ops: OpBuffer) -> None:
    """End of program (M2/M30, or the last line): the held compensated move is written
    and compensation ends, as rs274ngc does at program end."""
    comp.flush(state, ops)
    state.comp = None


def _modes(state: State, groups) -> None:
    """Plane (not while compensating, as rs274) and units (allowed: rs274 accepts it)."""
    for group in ("plane", "units"):
        if group in groups:
            _, name, value = G_CODES[groups[group][0]]
            if group == "plane" and state.comp is not None and state.plane != value:
                raise LineError(groups[group][1].column,
                                msg("Cannot change planes with cutter radius compensation on"))
            setattr(state, name, value)


def _offset_modes(state: State, groups, params, ops: OpBuffer) -> None:
    """Cutter compensation, tool length, coordinate system, distance, retract."""
    if "cutter" in groups:
        code, word = groups["cutter"]
        comp.select(state, code, params, word.column, ops)
    if "toollength" in groups:
        code, word = groups["toollength"]
        tooling.length_offset(state, code, params, word.column)
    if "coords" in groups:
        code, word = groups["coords"]
        offsets.select_system(state, G_CODES[code][2], word.column)
    for group in ("distance", "ijk", "retract"):
        if group in groups:
            _, name, value = G_CODES[groups[group][0]]
            setattr(state, name, value)


def _nonmodal(state: State, groups, params, line_no: int, ops: OpBuffer) -> None:
    """G10 (offsets and tool table), G92 family, G52, G28/G30 and their stores."""
    code, word = groups.get("nonmodal", (None, None))
    if code == 10:
        level = params["L"].value if "L" in params else None
        if level in (2, 20):
            offsets.set_system(state, params, int(level), word.column)
        elif level in (1, 10, 11, 12, 13):
            tooling.set_entry(state, int(level), params, word.column)
        else:
            raise LineError(word.column,
                            msg("Line with G10 does not have L1, L10, L11, L12, L13, L2, or L20"))
    elif code in (92, 92.1, 92.2, 92.3, 52):
        offsets.axis_offsets(state, code, params, word.column)
    elif code in (28.1, 30.1):
        offsets.store_position(state, int(code))
    elif code in (28, 30):
        go_stored(state, int(code), params, line_no, ops, word.column)


class _LineOps(OpBuffer):
    """The rows of one line; while compensation holds a move back, the line's events
    (spindle, dwell, pause) wait behind it in its queue (``comp.py``)."""

    def __init__(self, state: State) -> None:
        super().__init__()
        self.state = state

    def add(self, line, kind, end, *args, **kw) -> None:
        held = self.state.comp
        if held is not None and held.queue:
            held.queue.append({"kind": "event", "args": (line, kind, end, *args), "kw": kw})
        else:
            super().add(line, kind, end, *args, **kw)

    def add_direct(self, *args, **kw) -> None:
        super().add(*args, **kw)


class _Pending:
    """Warnings of a line, passed on only if the line is not refused."""

    def __init__(self) -> None:
        self.items: list[tuple] = []

    def warning(self, line: int, column: int, message: str, key: str = "") -> None:
        self.items.append((line, column, message, key))


def _apply(new: State, words, line_no, line_ops: OpBuffer, report) -> None:
    groups, mgroups = _check_codes(words)
    params = _check_letters(words)
    axes_taken = check_usage(new, groups, mgroups, params)
    if "coolant" in mgroups:
        report.warning(line_no, mgroups["coolant"][1].column,
                       msg("coolant M7/M8/M9 ignored: this machine has no coolant"), "coolant ignored")
    _set_feed_speed(new, params)
    _tool_change(new, mgroups, params, line_no, line_ops, report)
    _spindle(new, mgroups, params, line_no, line_ops, report)
    if "modal_state" in mgroups:
        code, word = mgroups["modal_state"]
        modal_state.apply(new, M_CODES[int(code)][1], word.column, line_no, line_ops)
    _modes(new, groups)
    _offset_modes(new, groups, params, line_ops)
    _nonmodal(new, groups, params, line_no, line_ops)
    try:
        do_motion(new, groups, params, line_no, line_ops, axes_taken)
    except LineError as exc:
        if exc.column == 0 and "motion" in groups:  # a cycle, spline or arc refused: its G word
            exc.column = groups["motion"][1].column
        raise
    _stop(new, mgroups, line_no, line_ops, report)


def interpret_line(
    state: State, words: list[Word], line_no: int, ops: OpBuffer, report: Report
) -> tuple[State, bool]:
    """Apply one line; return (new state, refused?); ``state`` itself is left untouched."""
    new = state.copy()
    line_ops = _LineOps(new)
    final, pending = report, _Pending()
    try:
        _apply(new, words, line_no, line_ops, pending)
    except LineError as exc:
        final.error(line_no, exc.column, exc.message)
        return state, True
    new.commit()
    for item in pending.items:
        final.warning(*item)
    ops.extend(line_ops)
    return new, False
