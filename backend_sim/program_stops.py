"""Program stops and tool changes on the CNC MCU (docs/protocol.md, "Program stops").

``StopSettings`` holds the ``SET`` names ``OPTSTOP``, ``STOPSPINDLE`` and ``AFTERJOB``.
``expand(move, parser, settings, clearance_z)`` turns one parsed stop line (``M00``,
``M01``, ``M06 T..``) into the moves the motion queue runs:

    [spindle off] [rapid up to clearance] wait [spindle back on] [rapid down]

Only the last carries the stop line's seq, so ``F <seq>`` follows once the job has
gone on; the wait carries it as ``stop_of`` for the ``L STOP`` notice. An ``M01``
with the optional stop off is a zero dwell. Positions are the parser's (where the
previous line ends), so a stop puts the tool back exactly where it took it from.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from backend_sim.motion.dialect import DialectParser, Move

SETTINGS = {"OPTSTOP": "optional", "STOPSPINDLE": "spindle_off", "AFTERJOB": "after_job"}
AFTER_JOB = ("STAY", "LIFT", "ZERO", "HOME")
MAX_MOVES = 5


@dataclass
class StopSettings:
    """Machine settings for stops: ``optional`` (M01 holds), ``spindle_off`` (M00/M01
    stop the spindle too), ``after_job`` (index into ``AFTER_JOB``)."""

    optional: bool = True
    spindle_off: bool = False
    after_job: int = 1

    def set(self, name: str, value: float) -> bool:
        """Set ``name`` if it is one of ours; ValueError for a bad value."""
        field = SETTINGS.get(name)
        if field is None:
            return False
        if field == "after_job":
            if value not in range(len(AFTER_JOB)):
                raise ValueError(f"AFTERJOB {value:g}: 0 stay, 1 lift Z, 2 work zero, 3 home")
            self.after_job = int(value)
        else:
            setattr(self, field, bool(value))
        return True

    def get(self, name: str) -> float | None:
        field = SETTINGS.get(name)
        return None if field is None else float(getattr(self, field))


def slots_needed(line: str) -> int:
    """Queue slots a device line may take: ``MAX_MOVES`` for a stop line, else 1."""
    if line[:1] == "M" and line[1:].lstrip("0")[:1] in ("", " ", "1", "6"):
        return MAX_MOVES
    return 1


def is_tool_change(line: str) -> bool:
    return line.split(" ", 1)[0] in ("M06", "M6")


def expand(move: Move, parser: DialectParser, settings: StopSettings, clearance_z: float) -> list[Move]:
    """The queue moves of the stop line ``move`` (see the module docstring)."""
    code = move.source.split(" ", 1)[0]
    if code in ("M01", "M1") and not settings.optional:
        return [Move(move.seq, "dwell", move.target, seconds=0.0, source=move.source)]
    here = parser.position
    rpm = parser.spindle
    tool_change = is_tool_change(move.source)
    spindle = rpm > 0 and (tool_change or settings.spindle_off)
    lift = tool_change and here[2] < clearance_z - 1e-6
    up = (here[0], here[1], clearance_z)
    before, after = [], []
    if spindle:
        before.append(Move(-1, "spindle", here, rpm=0.0, source="M05"))
        after.append(Move(-1, "spindle", here, rpm=rpm, source=f"M03 S{rpm:g}"))
    if lift:
        before.append(Move(-1, "rapid", up, source="retract"))
        after.append(Move(-1, "rapid", here, source="return"))
    wait = Move(-1, "wait", up if lift else here, source=move.source, tool=move.tool, stop_of=move.seq)
    moves = [*before, wait, *after]
    moves[-1] = replace(moves[-1], seq=move.seq)
    return moves


def after_job(mc, settings: StopSettings, offset, profile) -> None:
    """What the machine does once a job's last line has finished (``AFTERJOB``): stay,
    lift Z to the top of its travel, lift then go to work X0 Y0, or home."""
    action = AFTER_JOB[settings.after_job]
    if action == "STAY" or not mc.homed or mc.state != "IDLE" or mc.cover_open:
        return
    if action == "HOME":
        mc.home("NORMAL")
        return
    rapid = profile.motion.rapid_mm_min
    here = mc.commanded_mm
    top = profile.travel.limits()[2][1]
    if here[2] < top - 1e-3:
        mc.jog("Z", top - here[2], rapid)
    if action == "ZERO":
        for k, axis in ((0, "X"), (1, "Y")):
            if abs(offset[k] - here[k]) > 1e-3:
                mc.jog(axis, offset[k] - here[k], rapid)
