"""The six work coordinate systems on the CNC MCU (``SET``/``GET`` ``WCS`` and
``G54_X`` .. ``G59_Z``, docs/protocol.md "Work coordinate systems").

``mcu.systems`` maps 54..59 to each system's offset (machine mm), ``mcu.wcs`` is the
active one and ``mcu.offset`` always its row, so every work position follows it. A
change is refused ``BUSY`` while a job is open or the machine moves, written to the
flash at once, and the line parser restarts from the new offset.
"""

from __future__ import annotations

import re

from backend_sim.flash import SYSTEMS

AXES = "XYZ"
ROW_NAME = re.compile(r"G(5[4-9])_([XYZ])")
LIMIT_MM = 100000.0


def owns(name: str) -> bool:
    """Whether ``name`` is one of this module's ``SET``/``GET`` names."""
    return name == "WCS" or ROW_NAME.fullmatch(name) is not None


def get(mcu, name: str) -> float:
    if name == "WCS":
        return float(mcu.wcs)
    system, axis = _row(name)
    return mcu.systems[system][AXES.index(axis)]


def set_(mcu, name: str, value: float, refused, not_running) -> None:
    """Set ``name`` to ``value`` (``refused(code, text)`` builds the refusal)."""
    if name == "WCS":
        if value not in SYSTEMS:
            raise refused("BAD_ARGS", f"WCS {value:g}: 54 to 59")
        not_running(mcu)
        mcu.wcs = int(value)
    else:
        if abs(value) > LIMIT_MM:
            raise refused("BAD_ARGS", f"{name} {value:g}: at most {LIMIT_MM:g} mm")
        not_running(mcu)
        system, axis = _row(name)
        row = list(mcu.systems[system])
        row[AXES.index(axis)] = value
        mcu.systems[system] = tuple(row)
    store(mcu)


def write_active(mcu, offset) -> None:
    """``ZERO``: the active system's row becomes ``offset``."""
    mcu.systems[mcu.wcs] = tuple(offset)
    store(mcu)


def store(mcu) -> None:
    mcu.offset = mcu.systems[mcu.wcs]
    mcu.flash.save_systems(mcu.systems, mcu.wcs)
    mcu.reset_parser()


def _row(name: str) -> tuple[int, str]:
    match = ROW_NAME.fullmatch(name)
    return int(match.group(1)), match.group(2)
