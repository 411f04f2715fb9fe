"""The machine's six work coordinate systems as the host sees them (no Qt).

``WorkSystems`` keeps what the machine has answered (docs/protocol.md "Work coordinate
systems"): each system's offset (machine mm, ``None`` until read), the active system,
and whether the machine knows the six systems at all (a machine before them answers
``BAD_PARAM``: then only ``OFFSET_X..Z``, the one work offset, is shown). It turns a
work position into a machine position, and a target into the G-code of a safe move:
up to the top of the Z travel first (as the machine's own after-job lift), across in
X and Y, then down to the target's Z.
"""

from __future__ import annotations

import re

from app.comm.jobs import plain_number

SYSTEMS = tuple(range(54, 60))
AXES = "XYZ"
ROW_NAME = re.compile(r"G(5[4-9])_([XYZ])")
OFFSET_NAMES = ("OFFSET_X", "OFFSET_Y", "OFFSET_Z")
NO_SYSTEMS = frozenset({"", "BAD_PARAM", "UNSUPPORTED", "UNKNOWN_VERB"})  # GET WCS refused: not known


class WorkSystems:
    def __init__(self) -> None:
        self.rows: dict[int, list[float | None]] = {n: [None, None, None] for n in SYSTEMS}
        self.active: int | None = None
        self.supported: bool | None = None  # None until the machine has answered GET WCS

    @staticmethod
    def row_queries() -> list[str]:
        """The commands that read each system's row (once ``GET WCS`` has been answered:
        a machine with one offset only is not asked)."""
        return [f"GET G{n}_{a}" for n in SYSTEMS for a in AXES]

    @staticmethod
    def set_row(system: int, axis: str, value: float) -> str:
        return f"SET G{system}_{axis} {plain_number(value)}"

    @staticmethod
    def select(system: int) -> str:
        return f"SET WCS {system}"

    def take(self, verb: str, args: tuple, info: str, ok: bool, code: str = "") -> bool:
        """Read one command's answer; whether it changed what is shown. A ``GET WCS`` refused
        as unknown (``NO_SYSTEMS``) means a machine with one offset only; one that failed
        otherwise (a timeout, a lost link, GRBL's ``error:N`` or a reset) read nothing: the
        systems stay unknown, never shown as that one offset."""
        if verb == "ZERO" and ok:
            words = {w[0]: float(w[1:]) for w in info.split() if w[:1] in AXES}
            return self._write_active(words)
        if verb not in ("GET", "SET") or not args:
            return False
        name = args[0]
        if not ok:
            if name == "WCS" and verb == "GET" and code in NO_SYSTEMS:
                self.supported = False
                return True
            return False
        value = float(info.split()[1])
        if name == "WCS":
            self.supported, self.active = True, int(value)
            return True
        if name in OFFSET_NAMES and (self.active or self.supported is False):
            return self._write_active({name[-1]: value})
        match = ROW_NAME.fullmatch(name)
        if match is None:
            return False
        self.rows[int(match.group(1))][AXES.index(match.group(2))] = value
        return True

    def _write_active(self, words: dict[str, float]) -> bool:
        row = self.rows[self.active or 54]
        for axis, value in words.items():
            row[AXES.index(axis)] = value
        return bool(words)

    def for_programs(self):
        """``(active, {1..6: row})`` for ``app.gcode.load(systems=...)`` (G54 = 1), or
        ``None`` while any row is unknown or the machine has one offset only."""
        if not self.supported or self.active not in SYSTEMS:
            return None
        if any(None in row for row in self.rows.values()):
            return None
        return self.active - 53, {n - 53: tuple(row) for n, row in self.rows.items()}

    def offset(self) -> list[float | None]:
        """The active system's offset (machine mm of its work zero)."""
        return list(self.rows[self.active or 54])

    def machine(self, work: tuple[float, float, float]) -> list[float | None]:
        """The machine position of a work position (``None`` per axis whose offset is unknown)."""
        return [None if o is None else w + o for w, o in zip(work, self.offset(), strict=True)]

    def move_to(self, target: dict[str, float], top_z_machine: float) -> str:
        """G-code (work coordinates) that reaches ``target`` (axis -> work mm; axes left
        out stay) with a rapid at the top of the Z travel first."""
        offset_z = self.offset()[2]
        if offset_z is None:
            raise ValueError("the work offset is not known yet")
        lines = [f"G00 Z{plain_number(top_z_machine - offset_z)}"]
        across = " ".join(f"{a}{plain_number(target[a])}" for a in "XY" if a in target)
        if across:
            lines.append(f"G00 {across}")
        if "Z" in target:
            lines.append(f"G00 Z{plain_number(target['Z'])}")
        return "\n".join(lines)
