"""The CNC MCU's own parser of the device dialect (DESIGN.md), as firmware would have it.

Contract: ``DialectParser.parse(seq, line)`` turns one normalised line into a ``Move`` in
machine millimetres, or raises ``DialectError(code, text)``. Accepted lines (upper case,
absolute work millimetres, words separated by spaces or not):

    G00|G0 [X] [Y] [Z] [F]      rapid, at profile.motion.rapid_mm_min
    G01|G1 [X] [Y] [Z] [F]      line at the modal feed
    G02|G03 X Y I J [Z] [F]     arc in XY (helix with Z); I J relative to the start point
    G04 P<seconds>              dwell
    M03|M3 S<rpm>   M05|M5      spindle on / off
    M02|M2  M30                 end of program
    M00|M0  M01|M1              program stop, optional stop (the MCU holds there)
    M06|M6 [T<n>]               tool change (the MCU holds there, spindle off, Z up)

Every number is in the ranges of ``value_ranges`` (those of the host's loader), else
``BAD_VALUE``. Omitted axes keep their last value; the feed and the spindle speed are
modal. ``machine = work + offset``.
``parser.position`` is the machine position at the end of the last parsed move; the MCU
sets it after homing, jog or stop. Never imports ``app.gcode``: a normaliser bug must
not hide behind a shared parser.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from backend_sim import value_ranges

Vec3 = tuple[float, float, float]

_WORD = re.compile(r"\s*([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")
_ALLOWED = {
    "G0": "XYZF", "G1": "XYZF", "G2": "XYZIJF", "G3": "XYZIJF", "G4": "P",
    "M3": "S", "M5": "", "M2": "", "M30": "", "M0": "", "M1": "", "M6": "T",
}
_KINDS = {"G0": "rapid", "G1": "line", "G2": "arc", "G3": "arc", "G4": "dwell",
          "M3": "spindle", "M5": "spindle", "M2": "end", "M30": "end",
          "M0": "stop", "M1": "stop", "M6": "stop"}


class DialectError(ValueError):
    """A line the CNC MCU refuses: ``code`` (e.g. BAD_LINE) and a human ``text``."""

    def __init__(self, code: str, text: str):
        super().__init__(f"{code} {text}")
        self.code = code
        self.text = text


@dataclass(frozen=True)
class Move:
    """One parsed device line in machine millimetres."""

    seq: int
    kind: str
    target: Vec3
    feed: float = 0.0
    center: tuple[float, float] | None = None
    clockwise: bool = False
    seconds: float = 0.0
    rpm: float = 0.0
    source: str = ""
    tool: int = -1  # M06 T<n>; -1: not named
    stop_of: int = -1  # a program stop's wait: the seq of its stop line

    @property
    def moves_axes(self) -> bool:
        return self.kind in ("rapid", "line", "arc")

    def extent(self, start: Vec3) -> tuple[Vec3, Vec3]:
        """Bounding box (low, high) of the path from ``start``, arc bulge included."""
        pts = [start, self.target]
        if self.kind == "arc" and self.center is not None:
            pts += [(x, y, start[2]) for x, y in _arc_extremes(start, self)]
        lo = tuple(min(p[k] for p in pts) for k in range(3))
        hi = tuple(max(p[k] for p in pts) for k in range(3))
        return lo, hi  # type: ignore[return-value]


def arc_sweep(start: Vec3, move: Move) -> tuple[float, float, float]:
    """(radius, start angle, signed sweep in rad) of an arc move; a closed arc is a full turn."""
    cx, cy = move.center  # type: ignore[misc]
    a0 = math.atan2(start[1] - cy, start[0] - cx)
    a1 = math.atan2(move.target[1] - cy, move.target[0] - cx)
    sweep = a1 - a0
    if move.clockwise:
        if sweep >= -1e-12:
            sweep -= 2 * math.pi
    elif sweep <= 1e-12:
        sweep += 2 * math.pi
    return math.hypot(start[0] - cx, start[1] - cy), a0, sweep


def _arc_extremes(start: Vec3, move: Move) -> list[tuple[float, float]]:
    r, a0, sweep = arc_sweep(start, move)
    cx, cy = move.center  # type: ignore[misc]
    out = []
    for quarter in range(-8, 9):
        ang = quarter * math.pi / 2
        if min(a0, a0 + sweep) < ang < max(a0, a0 + sweep):
            out.append((cx + r * math.cos(ang), cy + r * math.sin(ang)))
    return out


class DialectParser:
    """Stateful parser: work offset, last position (machine mm) and modal feed."""

    def __init__(self, offset: Vec3 = (0.0, 0.0, 20.0), position: Vec3 = (0.0, 0.0, 30.0)):
        self.offset = tuple(float(v) for v in offset)
        self.position = tuple(float(v) for v in position)
        self.feed = 0.0
        self.rpm = 0.0  # modal spindle speed
        self.spindle = 0.0  # the speed in force at the end of the last line (0: off)

    def parse(self, seq: int, line: str) -> Move:
        """One line -> Move; updates position and modal feed only if the line is valid."""
        command, words = _split(line)
        kind = _KINDS[command]
        if kind == "dwell":
            return self._dwell(seq, words, line)
        if kind == "spindle":
            return self._spindle(seq, command, words, line)
        if kind == "end":
            self.spindle = 0.0
            return Move(seq, "end", self.position, source=line)
        if kind == "stop":
            return self._stop(seq, command, words, line)
        return self._motion(seq, command, kind, words, line)

    def _spindle(self, seq: int, command: str, words: dict[str, float], line: str) -> Move:
        if command == "M5":
            self.spindle = 0.0
            return Move(seq, "spindle", self.position, rpm=0.0, source=line)
        if "S" not in words and self.rpm <= 0:
            raise DialectError("BAD_LINE", "M03 needs S<rpm> (no speed set yet)")
        self.rpm = self.spindle = _nonneg(words, "S", self.rpm)
        return Move(seq, "spindle", self.position, rpm=self.rpm, source=line)

    def _stop(self, seq: int, command: str, words: dict[str, float], line: str) -> Move:
        tool = words.get("T", -1.0)
        if command == "M6" and "T" in words and not (tool >= 0 and tool == int(tool)):
            raise DialectError("BAD_VALUE", f"tool T{tool:g} must be a whole number >= 0")
        return Move(seq, "stop", self.position, source=line, tool=int(tool))

    def _dwell(self, seq: int, words: dict[str, float], line: str) -> Move:
        if "P" not in words:
            raise DialectError("BAD_LINE", "G04 needs P<seconds>")
        return Move(seq, "dwell", self.position, seconds=_nonneg(words, "P", 0.0), source=line)

    def _motion(self, seq: int, command: str, kind: str, words: dict[str, float], line: str) -> Move:
        feed = self.feed
        if "F" in words:
            feed = words["F"]
            if not feed > 0:
                raise DialectError("BAD_VALUE", f"feed F{feed:g} must be > 0")
        target = tuple(
            words[a] + self.offset[k] if a in words else self.position[k] for k, a in enumerate("XYZ")
        )
        if kind != "rapid" and feed <= 0:
            raise DialectError("NO_FEED", f"{command} without a feed (no F yet)")
        move = Move(seq, kind, target, feed=feed if kind != "rapid" else 0.0, source=line)  # type: ignore[arg-type]
        if kind == "arc":
            move = self._arc(move, command, words)
        self.feed = feed
        self.position = move.target
        return move

    def _arc(self, move: Move, command: str, words: dict[str, float]) -> Move:
        for axis in "XYIJ":
            if axis not in words:
                raise DialectError("BAD_LINE", f"{command} needs X Y I J (missing {axis})")
        sx, sy, _ = self.position
        cx, cy = sx + words["I"], sy + words["J"]
        r0 = math.hypot(sx - cx, sy - cy)
        r1 = math.hypot(move.target[0] - cx, move.target[1] - cy)
        if r0 < 1e-4:
            raise DialectError("BAD_ARC", "zero radius")
        if abs(r1 - r0) > 0.01 + 1e-3 * r0:
            raise DialectError("BAD_ARC", f"end radius {r1:.3f} differs from start radius {r0:.3f}")
        return Move(move.seq, "arc", move.target, move.feed, (cx, cy), command == "G2",
                    source=move.source)


def _split(line: str) -> tuple[str, dict[str, float]]:
    text = line.strip()
    pos, words, command = 0, {}, None
    while pos < len(text):
        m = _WORD.match(text, pos)
        if m is None:
            rest = text[pos:].strip()
            raise DialectError("BAD_LINE", f"cannot read {rest[:12]!r}")
        letter, number = m.group(1), m.group(2)
        pos = m.end()
        if letter in "GM":
            if command is not None:
                raise DialectError("BAD_LINE", "more than one G/M word")
            command = _command(letter, number)
            continue
        if letter in words:
            raise DialectError("BAD_LINE", f"word {letter} twice")
        words[letter] = value = float(number)
        problem = value_ranges.word_problem(letter, value)
        if problem:
            raise DialectError("BAD_VALUE", problem)
    if command is None:
        raise DialectError("BAD_LINE", "no G or M word" if text else "empty line")
    for letter in words:
        if letter not in _ALLOWED[command]:
            raise DialectError("BAD_LINE", f"unknown word {letter} for {_pretty(command)}")
    return command, words


def _command(letter: str, number: str) -> str:
    try:
        code = letter + str(int(number))
    except ValueError:
        raise DialectError("BAD_LINE", f"unsupported {letter}{number}") from None
    if code not in _ALLOWED:
        raise DialectError("BAD_LINE", f"unsupported {letter}{number}")
    return code


def _pretty(command: str) -> str:
    return command[0] + command[1:].zfill(2)


def _nonneg(words: dict[str, float], letter: str, default: float) -> float:
    value = words.get(letter, default)
    if value < 0 or not math.isfinite(value):
        raise DialectError("BAD_VALUE", f"{letter}{value:g} must be >= 0")
    return value


def soft_limit_violation(start: Vec3, move: Move, travel) -> str | None:
    """First axis the move would leave the travel on, e.g. ``"X+ 151.200 > 150"``; else None.

    ``travel`` is a ``Travel`` (profile section) or ((lo, hi), (lo, hi), (lo, hi)).
    """
    if not move.moves_axes:
        return None
    limits = travel.limits() if hasattr(travel, "limits") else travel
    lo, hi = move.extent(start)
    for k, axis in enumerate("XYZ"):
        low, high = limits[k]
        if lo[k] < low - 1e-6:
            return f"{axis}- {lo[k]:.3f} < {low:g}"
        if hi[k] > high + 1e-6:
            return f"{axis}+ {hi[k]:.3f} > {high:g}"
    return None
