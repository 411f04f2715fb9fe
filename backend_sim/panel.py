"""``sim.panel``: the machine's front panel as seen by tests and the GUI's machine panel.

Contract: ``oled_framebuffer()`` -> numpy (64, 128) bool (True = lit pixel),
``oled_text()`` -> the 8 text rows read back from it; ``led``, ``buzzer`` (bool, now);
``press(button)`` with UP, DOWN, OK, EXIT (the menu), MRESET (main MCU), RESET (CNC
MCU); ``set_cover(open)``; ``reset_main()``, ``reset_cnc()``. Thread safe (takes the
simulator's lock).
"""

from __future__ import annotations

import numpy as np

from backend_sim import oled
from backend_sim.menu import BUTTONS, Menu


class Panel:
    def __init__(self, sim) -> None:
        self._sim = sim
        self.menu = Menu(sim.main, sim.cnc)
        sim.main.menu = self.menu
        self.cover_open = False

    def oled_framebuffer(self) -> np.ndarray:
        with self._sim.lock:
            return oled.render(self.menu.lines())

    def oled_text(self) -> list[str]:
        return oled.read_text(self.oled_framebuffer())

    @property
    def led(self) -> bool:
        with self._sim.lock:
            return self._sim.main.led

    @property
    def buzzer(self) -> bool:
        with self._sim.lock:
            return self._sim.main.buzzer

    def press(self, button: str) -> None:
        button = button.upper()
        if button == "MRESET":
            return self.reset_main()
        if button == "RESET":
            return self.reset_cnc()
        if button not in BUTTONS:
            raise ValueError(f"unknown button {button!r}; known: {', '.join(BUTTONS)}, MRESET, RESET")
        with self._sim.lock:
            self.menu.press(button)
            self._sim.wake()
        return None

    def set_cover(self, is_open: bool) -> None:
        with self._sim.lock:
            self.cover_open = is_open
            self._sim.cnc.set_cover(is_open)
            self._sim.wake()

    def reset_main(self) -> None:
        with self._sim.lock:
            self._sim.main.boot()
            self.menu.reset()
            self._sim.wires["uart_down"].clear()
            self._sim.wake()

    def reset_cnc(self) -> None:
        with self._sim.lock:
            self._sim.wires["uart_up"].clear()
            self._sim.cnc.reset()
            self._sim.wake()
