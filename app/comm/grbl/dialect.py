"""The machine dialect's device lines as GRBL 1.1 takes them, and the travel GRBL reports.

``grbl_lines(device_lines, optional_stop=True)`` -> ``list[GrblLine]``: every device
line keeps its program index. GRBL refuses ``M6`` (error:20) and its ``M0``/``M1``
hold the machine in a way the host cannot tell apart from a feed hold, so all three
are program stops the host handles: the stream waits until everything before has
finished (a ``G4 P0`` sync: GRBL answers a dwell only once the planner is empty), then
the prompt (``GrblLine.stop``). ``M01`` is dropped when ``optional_stop`` is off. The
rest (``G00``-``G03`` with absolute XYZ, IJ relative to the start as GRBL's default
``G91.1``, ``G04 P`` seconds, ``M03 S``, ``M05``, ``M02``, ``M30``) is GRBL's own.
``line_problems(lines)`` names lines GRBL's buffers cannot take (longer than
``MAX_LINE`` bytes).

``grbl_travel(settings, wco)`` turns ``$130``-``$132`` and the live ``WCO`` into a
``Travel`` and the work offset the preflight (``app.gcode.checks.preflight``) expects:
GRBL's machine space is ``[-max, 0]`` per axis (GRBL's documentation: the machine
coordinates are negative; builds that force the origin at home differ).
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import NamedTuple

from app.comm.events import ProgramStopEvent
from app.i18n import msg
from app.profile import MachineProfile, Travel

MAX_LINE = 80  # bytes of a line GRBL can hold, its line end included
PREAMBLE = ("G21 G90 G94 G17",)  # millimetres, absolute, feed per minute, XY plane
SYNC = "G4 P0"
_STOP = re.compile(r"^M0*([016])(?:\s+T(\d+))?\s*$")


class GrblLine(NamedTuple):
    """One line of a job: ``text`` to send (None at a program stop), its program index
    (a named tuple: a million of them are made at Start, three times faster than a
    frozen dataclass)."""

    index: int
    text: str | None
    stop: ProgramStopEvent | None = None


def grbl_lines(device_lines, optional_stop: bool = True, first_index: int = 0) -> list[GrblLine]:
    """The device lines from ``first_index`` on as GRBL job lines (see the module)."""
    out = []
    for index, line in enumerate(device_lines[first_index:], first_index):
        text = line.strip().upper()
        stop = _STOP.match(text) if "M" in text else None  # (most lines name no M code)
        if stop is None:
            out.append(GrblLine(index, text))
            continue
        code = int(stop[1])
        if code == 1 and not optional_stop:
            continue
        tool = int(stop[2]) if stop[2] else None
        out.append(GrblLine(index, None, ProgramStopEvent(index, line.strip(), code, tool)))
    return out


def line_problems(lines) -> list[str]:
    """Messages for lines GRBL cannot take whole (index and length named)."""
    return [msg("device line {index} is {length} bytes; GRBL takes at most {limit}",
                index=index, length=len(text) + 1, limit=MAX_LINE)
            for index, text in enumerate(lines) if len(text) + 1 > MAX_LINE]


def axis_range(settings: dict[int, str], k: int) -> tuple[float, float]:
    """(min, max) machine position of axis ``k`` (0 X, 1 Y, 2 Z) from ``$13k``: GRBL's
    machine space is negative, ``[-max travel, 0]``, whichever end each axis homes to."""
    travel = abs(float(settings.get(130 + k, "0") or 0))
    return (-travel, 0.0)


def tool_change_height(settings: dict[int, str], options: str = "") -> float | None:
    """The machine Z (``G53``) a tool change lifts to: the top of the Z travel less the
    homing pull-off (``$27``, at least 1 mm: where homing leaves Z, off its switch), as
    gSender's ``G53 G0 Z[safe height]``; None without ``$132``. The top is machine Z 0,
    but on a build that sets the origin where it homes (``Z`` among ``$I``'s ``[OPT:]``
    letters, ``options``) with Z homing down (``$23`` bit 2), where it is ``+$132``."""
    if 132 not in settings:
        return None
    try:
        pull_off = float(settings.get(27, "1") or 1)
        homes_down = int(float(settings.get(23, "0") or 0)) & 4
    except ValueError:
        return None
    top = axis_range(settings, 2)[1]
    if homes_down and "Z" in options.split(",")[0]:
        top = top - axis_range(settings, 2)[0]  # the space is [0, max]
    return top - max(pull_off, 1.0)


def grbl_travel(settings: dict[int, str], wco, profile: MachineProfile | None = None):
    """(profile with GRBL's travel, work offset) for ``checks.preflight``; ValueError if a
    ``$13x`` setting is missing or not a positive number."""
    profile = profile or MachineProfile()
    ranges = []
    for k, axis in enumerate("XYZ"):
        if 130 + k not in settings:
            raise ValueError(msg("the machine has not reported ${number} ({axis} travel)",
                                 number=130 + k, axis=axis))
        lo, hi = axis_range(settings, k)
        if hi - lo <= 0:
            raise ValueError(msg("${number} ({axis} travel) is {value}: not a travel",
                                 number=130 + k, axis=axis, value=settings[130 + k]))
        ranges.append((lo, hi))
    travel = Travel(x_max=ranges[0][1] - ranges[0][0], y_max=ranges[1][1] - ranges[1][0],
                    z_max=ranges[2][1] - ranges[2][0], home_backoff_mm=profile.travel.home_backoff_mm)
    offset = tuple(float(wco[k]) - ranges[k][0] for k in range(3))
    return replace(profile, travel=travel), offset
