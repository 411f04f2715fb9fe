"""Modal state at a line of a normalised program, and the preamble that restores it.

After the machine was reset (new boot id) and re-homed, a job restarts at line
``start`` from the home position. ``restart_preamble(lines, start)`` returns the
machine-dialect lines that put back what the lines before ``start`` left in force:
spindle (``M03 S..``), a retract to the highest Z seen, a rapid to the XY where line
``start - 1`` ended carrying the modal feed (``F``; the dialect keeps F modal from any
motion line), and a feed move down to its Z. Units need no line: the dialect is
absolute millimetres only. The same preamble starts a job from a chosen line.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

_WORD = re.compile(r"([A-Z])(-?\d+(?:\.\d*)?|-?\.\d+)")


@dataclass
class ModalState:
    """Where the tool is and what is in force after some lines of the dialect."""

    x: float | None = None
    y: float | None = None
    z: float | None = None
    feed: float | None = None
    spindle_rpm: float | None = None
    top_z: float | None = None

    def apply(self, line: str) -> None:
        """Fold one dialect line in (G00-G03 X Y Z F, M03 S, M05)."""
        words = dict(_WORD.findall(line.upper()))
        code = line.split(" ", 1)[0].upper()
        if code in ("G00", "G01", "G02", "G03", "G0", "G1", "G2", "G3"):
            self.x = _num(words, "X", self.x)
            self.y = _num(words, "Y", self.y)
            self.z = _num(words, "Z", self.z)
            if self.z is not None:
                self.top_z = self.z if self.top_z is None else max(self.top_z, self.z)
        if "F" in words:
            self.feed = float(words["F"])
        if code in ("M03", "M3", "M04", "M4"):
            self.spindle_rpm = _num(words, "S", self.spindle_rpm or 0.0)
        elif code in ("M05", "M5", "M02", "M2", "M30"):
            self.spindle_rpm = None


def _num(words: dict[str, str], letter: str, default: float | None) -> float | None:
    return float(words[letter]) if letter in words else default


def modal_state(lines: list[str], start: int) -> ModalState:
    """The state in force just before ``lines[start]``."""
    state = ModalState()
    for line in lines[:start]:
        state.apply(line)
    return state


def device_index_of(line_map, source_line: int) -> int | None:
    """The first device line of ``source_line`` (1-based), else of the next source line
    that has one; None past the end. ``line_map``: device index -> source line."""
    for index, line in enumerate(line_map):
        if line >= source_line:
            return index
    return None


def _fmt(value: float) -> str:
    return f"{value:.3f}"


def restart_preamble(lines: list[str], start: int) -> list[str]:
    """Dialect lines that restore the modal state before ``lines[start]`` (empty at 0)."""
    if start <= 0:
        return []
    return preamble_of(modal_state(lines, start))


def preamble_of(state: ModalState) -> list[str]:
    """Dialect lines that put back ``state`` from anywhere above the work: the spindle, a
    retract to its highest Z, a rapid over its XY (carrying its feed), a feed down to its Z."""
    out = []
    if state.spindle_rpm is not None:
        out.append(f"M03 S{state.spindle_rpm:.0f}")
    if state.top_z is not None:
        out.append(f"G00 Z{_fmt(state.top_z)}")
    feed = f" F{state.feed:g}" if state.feed is not None else ""
    if state.x is not None and state.y is not None:
        out.append(f"G00 X{_fmt(state.x)} Y{_fmt(state.y)}{feed}")
    if state.z is not None and state.z != state.top_z:
        out.append(f"G01 Z{_fmt(state.z)}{feed}" if feed else f"G00 Z{_fmt(state.z)}")
    elif feed and (state.x is None or state.y is None):
        out.append(f"G01{feed}")
    return out
