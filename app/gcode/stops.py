"""Program stops as device lines: ``M00``, ``M01`` and ``M06 T<n>`` (docs/protocol.md).

A PAUSE row of ``Ops`` keeps in its ``value`` which stop it is: ``stop_value(code,
tool)`` encodes it, ``device_line(value)`` writes the line the machine holds at. M60
(pallet change and stop) is an ``M00`` on a machine with no pallets.
"""

from __future__ import annotations

TOOL_BASE = 1000.0


def stop_value(code: int, tool: float | None = None) -> float:
    """The PAUSE row value of ``M<code>`` (``tool``: the tool an M6 names, if any)."""
    if code == 6 and tool is not None and tool >= 0:
        return TOOL_BASE + int(tool)
    return float(6 if code == 6 else 1 if code == 1 else 0)


def device_line(value: float) -> str:
    """The device line of a PAUSE row value (see ``stop_value``)."""
    if value >= TOOL_BASE:
        return f"M06 T{int(value - TOOL_BASE)}"
    return {6: "M06", 1: "M01"}.get(int(value), "M00")
