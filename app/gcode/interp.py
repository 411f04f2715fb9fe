"""The general modal interpreter: one lexed line at a time, LinuxCNC semantics.

``interpret_line(state, words, line_no, ops, report)`` checks the whole line first
(unknown and refused words, two codes of one modal group, words with nothing to use
them), then applies it in rs274ngc's order: F, S, tool change (a pause), spindle,
dwell, plane, units, distance modes, motion, stop codes. A refused line changes
nothing: the state is copied and only committed when the line succeeds, so a file
with errors still loads as far as it can. Arcs are computed in ``motion.py``.
"""

from __future__ import annotations

from app.i18n import msg

from .diagnostics import Report
from .lexer import Word
from .motion import LineError, do_motion
from .ops import END, PAUSE, SPINDLE, OpBuffer
from .state import State
from .words import ALLOWED_LETTERS, G_CODES, M_CODES, REFUSED_G, REFUSED_LETTERS


def _gname(code: float) -> str:
    return f"G{code:g}"


def _check_letters(words: list[Word]) -> dict[str, Word]:
    params: dict[str, Word] = {}
    for w in words:
        if w.letter in REFUSED_LETTERS or w.letter not in ALLOWED_LETTERS:
            raise LineError(w.column, REFUSED_LETTERS.get(w.letter) or msg("unknown word {letter}",
                                                                                 letter=w.letter))
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
                raise LineError(w.column, msg("unknown M-code M{code:g}", code=code))
            table, name = mgroups, M_CODES[int(code)][0]
        else:
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


def _pause(line_no, column, message, ops: OpBuffer, state: State, report: Report) -> None:
    report.warning(line_no, column, message, message)
    ops.add(line_no, PAUSE, state.pos, message=msg("line {line}: {message}", line=line_no, message=message))


def _tool_change(state, mgroups, params, line_no, ops, report) -> None:
    if "toolchange" in mgroups:
        tool = f" T{params['T'].value:g}" if "T" in params else ""
        _pause(line_no, mgroups["toolchange"][1].column,
               msg("tool change{tool} M6: this machine has one tool; the job pauses here", tool=tool),
               ops, state, report)


def _stop(state, mgroups, line_no, ops, report) -> None:
    stop = mgroups.get("stop")
    if stop is None:
        return
    code = int(stop[0])
    if M_CODES[code][1] == "end":
        state.ended = line_no
        ops.add(line_no, END, state.pos)
    else:
        message = msg("M{code} program stop: the job pauses here", code=code)
        _pause(line_no, stop[1].column, message, ops, state, report)


def _modes(state: State, groups) -> None:
    for group in ("plane", "units", "distance", "ijk"):
        if group in groups:
            _, name, value = G_CODES[groups[group][0]]
            setattr(state, name, value)


class _Pending:
    """Warnings of a line, passed on only if the line is not refused."""

    def __init__(self) -> None:
        self.items: list[tuple] = []

    def warning(self, line: int, column: int, message: str, key: str = "") -> None:
        self.items.append((line, column, message, key))


def interpret_line(
    state: State, words: list[Word], line_no: int, ops: OpBuffer, report: Report
) -> tuple[State, bool]:
    """Apply one line; return (new state, refused?); ``state`` itself is left untouched."""
    new = state.copy()
    line_ops = OpBuffer()
    final, report = report, _Pending()
    try:
        groups, mgroups = _check_codes(words)
        params = _check_letters(words)
        if "coolant" in mgroups:
            report.warning(line_no, mgroups["coolant"][1].column,
                           msg("coolant M7/M8/M9 ignored: this machine has no coolant"), "coolant ignored")
        _set_feed_speed(new, params)
        _tool_change(new, mgroups, params, line_no, line_ops, report)
        _spindle(new, mgroups, params, line_no, line_ops, report)
        _modes(new, groups)
        do_motion(new, groups, params, line_no, line_ops)
        _stop(new, mgroups, line_no, line_ops, report)
    except LineError as exc:
        final.error(line_no, exc.column, exc.message)
        return state, True
    for item in report.items:
        final.warning(*item)
    ops.rows.extend(line_ops.rows)
    ops.messages.extend(line_ops.messages)
    return new, False
