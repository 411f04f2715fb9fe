"""The machine in software: main MCU, CNC MCU, motors, SD card, OLED and buttons. No Qt.

``Simulator`` (``backend_sim.simulator``) is imported lazily, so ``import backend_sim``
stays light.
"""

from __future__ import annotations

__all__ = ["Simulator"]


def __getattr__(name: str):
    if name == "Simulator":
        from backend_sim.simulator import Simulator

        return Simulator
    raise AttributeError(f"module 'backend_sim' has no attribute {name!r}")
