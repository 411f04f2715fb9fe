"""What a parsed block does in the simulated GRBL: the parser state (modes, offsets,
position) and the motions it asks for, in GRBL machine millimetres (MPos).

``GcodeState.execute(block)`` updates the state and returns the ``Action`` list for
the machine (``("move", kind, target, feed, extra)``, ``("dwell", seconds)``,
``("spindle", rpm)``, ``("coolant", letters)``, ``("pause",)``, ``("end",)``), or
raises ``GrblError`` with GRBL's code: feed never set (22), axis words missing (26)
or unused (31), an arc without its offsets or radius (35, 34), G10 without ``L2``/``L20``
and ``P1``-``P6`` (28), words no command uses (36), a tool number over 255 (38).
Nothing changes when a block is refused. Unsupported here (refused with 20): G28/G30,
G38.x probing, G93 inverse time, G43.1, G18/G19 arcs, M4 on this spindle.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field

from backend_sim.grbl.parser import Block, GrblError

INCH = 25.4


@dataclass
class GcodeState:
    motion: int = 0  # G number x10
    absolute: bool = True
    inches: bool = False
    wcs: int = 0  # 0..5: G54..G59
    feed: float = 0.0
    rpm: float = 0.0
    spindle: int = 5
    coolant: str = ""
    tool: int = 0
    position: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])  # MPos
    offsets: list[list[float]] = field(default_factory=lambda: [[0.0, 0.0, 0.0] for _ in range(6)])
    g92: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])

    def wco(self) -> tuple[float, float, float]:
        return tuple(o + g for o, g in zip(self.offsets[self.wcs], self.g92, strict=True))

    def modes_text(self) -> str:
        """The ``$G`` line: ``G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0``."""
        motion = {0: "G0", 10: "G1", 20: "G2", 30: "G3", 800: "G80"}[self.motion]
        coolant = " ".join(f"M{7 if c == 'M' else 8}" for c in self.coolant) or "M9"
        return (f"{motion} G{54 + self.wcs} G17 {'G20' if self.inches else 'G21'} "
                f"{'G90' if self.absolute else 'G91'} G94 M{self.spindle} {coolant} T{self.tool} "
                f"F{self.feed:g} S{self.rpm:g}")

    def execute(self, block: Block) -> list[tuple]:
        """Apply ``block`` (all or nothing); the actions for the machine."""
        trial = copy.deepcopy(self)
        actions = trial._apply(block)
        self.__dict__.update(trial.__dict__)
        return actions

    # ------------------------------------------------------------------ the steps

    def _apply(self, b: Block) -> list[tuple]:
        values, actions, used = dict(b.values), [], set()
        scale = INCH if b.g.get("units", 200 if self.inches else 210) == 200 else 1.0
        if "units" in b.g:
            self.inches = b.g["units"] == 200
        if b.g.get("plane", 170) != 170 or b.g.get("feed_mode", 940) != 940 or "tool_length" in b.g:
            raise GrblError(20)
        if "F" in values:
            self.feed = values["F"] * scale
            used.add("F")
        if "S" in values:
            self.rpm = values["S"]
            used.add("S")
        if "T" in values:
            if values["T"] > 255 or values["T"] != int(values["T"]):
                raise GrblError(38 if values["T"] > 255 else 23)
            self.tool = int(values["T"])
            used.add("T")
        if "N" in values:
            used.add("N")
        if "spindle" in b.m:
            if b.m["spindle"] == 4:
                raise GrblError(20)
            self.spindle = b.m["spindle"]
            actions.append(("spindle", self.rpm if self.spindle == 3 else 0.0))
        elif "S" in values and self.spindle == 3:
            actions.append(("spindle", self.rpm))
        if "coolant" in b.m:
            self.coolant = {7: "M", 8: "F", 9: ""}[b.m["coolant"]]
            actions.append(("coolant", self.coolant))
        if "distance" in b.g:
            self.absolute = b.g["distance"] == 900
        if "wcs" in b.g:
            self.wcs = (b.g["wcs"] - 540) // 10
        non_modal = b.g.get("non_modal")
        if non_modal == 40:
            if "P" not in values or values["P"] < 0:
                raise GrblError(28)
            actions.append(("dwell", values["P"]))
            used.add("P")
        elif non_modal == 100:
            self._g10(values, scale)
            used |= {"L", "P", "X", "Y", "Z"}
        elif non_modal in (920, 921):
            self._g92(values, scale, non_modal == 921)
            used |= {"X", "Y", "Z"}
        if "motion" in b.g:
            self.motion = b.g["motion"]
        axes = {k: v for k, v in values.items() if k in "XYZ"}
        if axes and non_modal not in (100, 920):
            actions.append(self._motion(axes, values, scale, non_modal == 530, used))
        elif "motion" in b.g and b.g["motion"] != 800 and non_modal is None:
            raise GrblError(26)
        if set(values) - used:
            raise GrblError(36)
        stop = b.m.get("stopping")
        if stop in (0, 1):
            actions.append(("pause",))
        elif stop in (2, 30):
            actions.append(("end",))
            self.motion, self.absolute, self.spindle, self.coolant, self.wcs = 10, True, 5, "", 0
            self.g92 = [0.0, 0.0, 0.0]
        return actions

    def _g10(self, values: dict, scale: float) -> None:
        l_word, p_word = values.get("L"), values.get("P")
        if l_word not in (2, 20) or p_word is None or not 0 <= p_word <= 6 or p_word != int(p_word):
            raise GrblError(28)
        index = self.wcs if p_word == 0 else int(p_word) - 1
        for k, axis in enumerate("XYZ"):
            if axis in values:
                if l_word == 2:
                    self.offsets[index][k] = values[axis] * scale
                else:
                    self.offsets[index][k] = self.position[k] - self.g92[k] - values[axis] * scale

    def _g92(self, values: dict, scale: float, clear: bool) -> None:
        for k, axis in enumerate("XYZ"):
            if clear:
                self.g92[k] = 0.0
            elif axis in values:
                self.g92[k] = self.position[k] - self.offsets[self.wcs][k] - values[axis] * scale
        if not clear and not any(a in values for a in "XYZ"):
            raise GrblError(26)

    def _motion(self, axes: dict, values: dict, scale: float, machine: bool, used: set) -> tuple:
        used |= set(axes)
        if self.motion == 800:
            raise GrblError(31)
        wco = (0.0, 0.0, 0.0) if machine else self.wco()
        target = list(self.position)
        for k, axis in enumerate("XYZ"):
            if axis in axes:
                value = axes[axis] * scale
                target[k] = value + wco[k] if self.absolute or machine else self.position[k] + value
        if self.motion == 0:
            self.position = target
            return ("move", "rapid", tuple(target), 0.0, None)
        if self.feed <= 0:
            raise GrblError(22)
        if self.motion == 10:
            self.position = target
            return ("move", "line", tuple(target), self.feed, None)
        centre = self._arc_centre(target, values, scale, used)
        self.position = target
        return ("move", "arc", tuple(target), self.feed, (centre, self.motion == 20))

    def _arc_centre(self, target, values: dict, scale: float, used: set) -> tuple[float, float]:
        x0, y0 = self.position[0], self.position[1]
        if "R" in values:
            used.add("R")
            return _radius_centre((x0, y0), (target[0], target[1]), values["R"] * scale, self.motion == 20)
        if "I" not in values and "J" not in values:
            raise GrblError(35)
        used |= {"I", "J"}
        cx, cy = x0 + values.get("I", 0.0) * scale, y0 + values.get("J", 0.0) * scale
        r0, r1 = math.hypot(x0 - cx, y0 - cy), math.hypot(target[0] - cx, target[1] - cy)
        if abs(r0 - r1) > 0.005 and abs(r0 - r1) > 0.001 * r0:
            raise GrblError(33)
        return (cx, cy)


def _radius_centre(start, end, r: float, clockwise: bool) -> tuple[float, float]:
    dx, dy = end[0] - start[0], end[1] - start[1]
    chord = math.hypot(dx, dy)
    if chord == 0 or abs(r) < chord / 2 - 1e-9:
        raise GrblError(34 if chord else 33)
    h = math.sqrt(max(r * r - chord * chord / 4, 0.0))
    side = -1.0 if clockwise else 1.0
    if r < 0:
        side = -side
    mx, my = (start[0] + end[0]) / 2, (start[1] + end[1]) / 2
    return (mx - side * h * dy / chord, my + side * h * dx / chord)
