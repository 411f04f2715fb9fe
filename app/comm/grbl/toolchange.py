"""A tool change on a GRBL machine made safe by the host (GRBL refuses ``M6``).

``safe_tool_changes(lines, before, lift)``: GRBL leaves the spindle running and the tool
where it is at a stop the host makes, so before an ``M6`` stop the spindle stops
(``M05``, where it runs) and the tool is lifted (``lift``: ``G53 G00 Z..`` near the top of
the travel once homed, or the program's highest Z so far if that is higher or the machine
is not homed; never down); after it, the tool goes back where the change started, as a
restart would (``modal.preamble_of``: the ``G53`` lift again, the spindle at its speed,
the program's highest Z, its XY, a feed down to its Z), before the program goes on. The
lines added carry the index of the line before the stop (before it) or the stop's own
(after it), so progress and the line map stay the program's.

``state_after(state, texts)`` is ``ModalState.apply`` over ``texts`` without applying each
line: the last lines that set each word, found from the end of the text, and the highest
Z by one regular expression over it, so a program of a million lines with a tool change
starts without the host going silent for seconds (its silence timer would call the link
lost).
"""

from __future__ import annotations

import re
from dataclasses import replace

from app.comm.grbl.dialect import GrblLine
from app.comm.modal import ModalState, preamble_of

_NUMBER = r"(-?\d+(?:\.\d*)?|-?\.\d+)"
_Z_WORD = re.compile(r"Z" + _NUMBER)  # in the dialect, a move's Z
_SPINDLE = frozenset({"M03", "M3", "M04", "M4", "M05", "M5", "M02", "M2", "M30"})  # what ModalState reads


def safe_tool_changes(lines: list[GrblLine], before: ModalState,
                      lift: tuple[str, float] | None) -> list[GrblLine]:
    """``lines`` with every tool change made safe (see the module); ``before``: the modal
    state before the first line (it is not changed); ``lift``: the ``G53`` line and the
    work Z it reaches (None: not homed)."""
    stops = [k for k, line in enumerate(lines) if line.stop is not None and line.stop.code == 6]
    if not stops:
        return lines
    out, state, done = [], before, 0
    for k in stops:
        state = state_after(state, [line.text for line in lines[done:k] if line.text])
        out += lines[done:k]
        up, machine = _lift(state, lift)
        ahead = (["M05"] if state.spindle_rpm else []) + ([up] if up else [])
        back = ([up] if machine else []) + preamble_of(state)  # the operator may have jogged it down
        stop = lines[k]
        out += [GrblLine(stop.index - 1, text) for text in ahead]
        out.append(stop)
        out += [GrblLine(stop.index, text) for text in back]
        done = k + 1
    return out + lines[done:]


def state_after(state: ModalState, texts: list[str]) -> ModalState:
    """A copy of ``state`` after ``texts`` (dialect lines), as ``ModalState.apply`` on each
    would leave it (see the module). In the dialect only moves carry X, Y and Z, so the
    last line with each word is found with ``rfind``."""
    text = ("\n" + "\n".join(texts)).upper()
    starts = {text.rfind("\n", 0, at) for at in (text.rfind(w) for w in "XYZF") if at >= 0}
    at = len(text)
    while (at := text.rfind("\nM", 0, at)) >= 0:  # the last spindle line
        if _spindle(_line_at(text, at)):
            starts.add(at)
            break
    after = replace(state)
    for start in sorted(starts):
        after.apply(_line_at(text, start))
    zs = set(_Z_WORD.findall(text))  # the highest Z: each value once, in C
    highest = [z for z in (after.top_z, max(map(float, zs), default=None)) if z is not None]
    after.top_z = max(highest, default=None)
    return after


def _line_at(text: str, start: int) -> str:
    """The line that begins after the newline at ``start``."""
    end = text.find("\n", start + 1)
    return text[start + 1:] if end < 0 else text[start + 1:end]


def _spindle(text: str) -> bool:
    return text[:1] == "M" and text.split(" ", 1)[0] in _SPINDLE


def _lift(state: ModalState, lift: tuple[str, float] | None) -> tuple[str | None, bool]:
    """The line that takes the tool up for a change, and whether it is the ``G53`` one: the
    higher of ``lift`` and the program's highest Z so far (the only one on a machine not
    homed, whose machine coordinates say nothing of the travel); None where the tool is
    as high already."""
    heights = [(lift[1], lift[0], True)] if lift is not None else []
    if state.top_z is not None:
        heights.append((state.top_z, f"G00 Z{state.top_z:.3f}", False))
    if not heights:
        return None, False
    height, text, machine = max(heights, key=lambda h: h[0])
    if state.z is not None and state.z >= height:
        return None, False
    return text, machine
