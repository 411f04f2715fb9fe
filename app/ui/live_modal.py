"""The live modal state of a running job, computed on the host from the program's source
at the line the machine reports done (no Qt).

``ModalTracker(lines)`` reads the G-code words of each source line with the project's
lexer (``app/gcode/lexer.py``) in the order the job passes them: ``advance_to(line)``
reads the lines after the last one read up to ``line``; when the job jumps back (a
loop's next pass), only ``line`` itself is read again and what is in force is kept, as
executing the loop's body again does. It keeps the active code of each modal group
(motion, plane, units, distance, coordinate system, cutter compensation), the
programmed feed and spindle speed, the tool in the spindle (the last ``T`` made current
by ``M06``) and the ``G92`` offset while it is in force. Lines the lexer refuses
(parameters, expressions, o-words) change nothing here; the preview's interpreter reads
them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.gcode.lexer import lex_line

MOTION = (0, 1, 2, 3, 33, 38.2, 38.3, 38.4, 38.5, 73, 76, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89)
GROUPS = {
    "motion": MOTION,
    "plane": (17, 18, 19),
    "units": (20, 21),
    "distance": (90, 91),
    "wcs": (54, 55, 56, 57, 58, 59, 59.1, 59.2, 59.3),
    "compensation": (40, 41, 41.1, 42, 42.1),
}
DEFAULTS = {"plane": "G17", "units": "G21", "distance": "G90", "wcs": "G54", "compensation": "G40"}
G92_SET, G92_CANCEL, G92_SUSPEND, G92_RESTORE = 92.0, 92.1, 92.2, 92.3


def code_name(value: float) -> str:
    """``G1``, ``G38.2``, ``G59.1``: the code as an operator writes it."""
    return f"G{value:g}"


@dataclass
class ModalView:
    """What is in force after a line: the group codes, feed (program units per minute),
    speed (rpm), tool (0: none known), the G92 words while in force ("" none)."""

    codes: dict[str, str] = field(default_factory=lambda: {"motion": "", **DEFAULTS})
    feed: float | None = None
    speed: float | None = None
    tool: int = 0
    g92: str = ""


class ModalTracker:
    def __init__(self, lines: list[str]) -> None:
        self.lines = lines
        self.last = 0  # the last 1-based line read
        self.view = ModalView()
        self._selected = 0
        self._g92_words = ""
        self._g92_on = False

    def advance_to(self, line: int) -> ModalView:
        """The state in force once source line ``line`` (1-based) has been done."""
        line = min(max(line, 0), len(self.lines))
        first = self.last + 1 if line > self.last else line
        for number in range(max(first, 1), line + 1):
            self._read(number)
        self.last = line
        return self.view

    def _read(self, number: int) -> None:
        lexed = lex_line(self.lines[number - 1], number)
        if lexed.error is not None or lexed.skip:
            return
        words = lexed.words
        codes = [w.value for w in words if w.letter == "G"]
        for value in codes:
            for group, members in GROUPS.items():
                if any(abs(value - m) < 1e-6 for m in members):
                    self.view.codes[group] = code_name(value)
        axes = " ".join(f"{w.letter}{w.value:g}" for w in words if w.letter in "XYZ")
        if any(abs(v - G92_SET) < 1e-6 for v in codes):
            self._g92_words, self._g92_on = axes, True
        elif any(abs(v - G92_CANCEL) < 1e-6 or abs(v - G92_SUSPEND) < 1e-6 for v in codes):
            self._g92_on = False
            if any(abs(v - G92_CANCEL) < 1e-6 for v in codes):
                self._g92_words = ""
        elif any(abs(v - G92_RESTORE) < 1e-6 for v in codes):
            self._g92_on = bool(self._g92_words)
        self.view.g92 = self._g92_words if self._g92_on else ""
        for w in words:
            if w.letter == "F":
                self.view.feed = w.value
            elif w.letter == "S":
                self.view.speed = w.value
            elif w.letter == "T":
                self._selected = int(w.value)
            elif w.letter == "M" and abs(w.value - 6) < 1e-6:
                self.view.tool = self._selected


def actual_feed(previous, current) -> float | None:
    """mm/min between two statuses (``None`` without two distinct times)."""
    if previous is None or current is None or current.time <= previous.time:
        return None
    distance = sum((a - b) ** 2 for a, b in zip(current.position, previous.position, strict=True)) ** 0.5
    return distance / (current.time - previous.time) * 60.0


def machine_modes(words: str) -> ModalView:
    """The modal state a machine reports as one line of words (GRBL's ``$G``:
    ``G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0``); its ``T`` is the tool in the spindle."""
    tracker = ModalTracker([words])
    view = tracker.advance_to(1)
    view.tool = next((int(w[1:]) for w in words.split() if w[:1] == "T" and w[1:].isdigit()), 0)
    return view
