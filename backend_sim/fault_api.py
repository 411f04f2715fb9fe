"""``sim.faults``: every fault a test or the GUI's machine panel can inject.

Links: ``hop`` is ``"usb"`` (host <-> main MCU) or ``"uart"`` (main <-> CNC MCU),
``direction`` is ``"down"`` (towards the CNC MCU) or ``"up"``. One-shot frame faults
act on the next ``frames`` complete frames written in that direction:
``drop``, ``corrupt``, ``duplicate``, ``delay(seconds=)``, ``reorder``,
``noise(nbytes=)``, ``truncate(keep=)``. ``set_rates(drop=, corrupt=, duplicate=,
noise=, seed=)`` sets seeded per-byte error rates (on one hop/direction, or on all
four when they are None). ``unplug()``/``replug()`` the USB cable, ``cut_uart()``/
``restore_uart()`` the wire between the MCUs. Machine faults: ``trip_limit(axis)``,
``lose_encoder(axis)``, ``open_cover()``/``close_cover()``, ``reset_main()``,
``reset_cnc()``. ``counts()`` says what was injected, per channel.
"""

from __future__ import annotations

HOPS = ("usb", "uart")
DIRECTIONS = ("down", "up")


class Faults:
    def __init__(self, sim) -> None:
        self._sim = sim

    def channel(self, hop: str, direction: str):
        if hop not in HOPS or direction not in DIRECTIONS:
            raise ValueError(f"hop {hop!r} / direction {direction!r}: one of {HOPS} / {DIRECTIONS}")
        return self._sim.wires[f"{hop}_{direction}"].faults

    def _arm(self, kind: str, hop: str, direction: str, frames: int = 1, **params) -> None:
        with self._sim.lock:
            self.channel(hop, direction).arm(kind, frames, **params)

    def drop(self, hop: str = "usb", direction: str = "down", frames: int = 1) -> None:
        self._arm("drop", hop, direction, frames)

    def corrupt(self, hop: str = "usb", direction: str = "down", frames: int = 1) -> None:
        self._arm("corrupt", hop, direction, frames)

    def duplicate(self, hop: str = "usb", direction: str = "down", frames: int = 1) -> None:
        self._arm("duplicate", hop, direction, frames)

    def delay(self, hop: str = "usb", direction: str = "down", seconds: float = 0.2, frames: int = 1) -> None:
        self._arm("delay", hop, direction, frames, seconds=seconds)

    def reorder(self, hop: str = "usb", direction: str = "down") -> None:
        self._arm("reorder", hop, direction, 1)

    def noise(self, hop: str = "usb", direction: str = "down", nbytes: int = 8) -> None:
        self._arm("noise", hop, direction, 1, nbytes=nbytes)

    def truncate(self, hop: str = "usb", direction: str = "down", keep: int | None = None) -> None:
        self._arm("truncate", hop, direction, 1, keep=keep)

    def set_rates(self, hop: str | None = None, direction: str | None = None, *, seed: int = 0,
                  **rates: float) -> None:
        with self._sim.lock:
            for h in HOPS if hop is None else (hop,):
                for d in DIRECTIONS if direction is None else (direction,):
                    self.channel(h, d).set_rates(seed=seed, **rates)

    def clear(self) -> None:
        with self._sim.lock:
            for wire in self._sim.wires.values():
                wire.faults.clear()

    def counts(self) -> dict[str, dict[str, int]]:
        return {name: dict(w.faults.counts) for name, w in self._sim.wires.items()}

    # ------------------------------------------------------------------ cables

    def unplug(self) -> None:
        with self._sim.lock:
            for name in ("usb_down", "usb_up"):
                self._sim.wires[name].set_cut(True)
            self._sim.host_port.set_unplugged(True)
            self._sim.wake()

    def replug(self) -> None:
        with self._sim.lock:
            for name in ("usb_down", "usb_up"):
                self._sim.wires[name].set_cut(False)
            self._sim.host_port.set_unplugged(False)
            self._sim.wake()

    def cut_uart(self) -> None:
        with self._sim.lock:
            for name in ("uart_down", "uart_up"):
                self._sim.wires[name].set_cut(True)

    def restore_uart(self) -> None:
        with self._sim.lock:
            for name in ("uart_down", "uart_up"):
                self._sim.wires[name].set_cut(False)

    # ------------------------------------------------------------------ machine

    def trip_limit(self, axis: str) -> None:
        with self._sim.lock:
            self._sim.cnc.catch_up()
            self._sim.cnc.mc.trip_limit(axis)
            self._sim.wake()

    def lose_encoder(self, axis: str) -> None:
        with self._sim.lock:
            self._sim.cnc.catch_up()
            self._sim.cnc.mc.lose_encoder(axis)
            self._sim.wake()

    def open_cover(self) -> None:
        self._sim.panel.set_cover(True)

    def close_cover(self) -> None:
        self._sim.panel.set_cover(False)

    def reset_main(self) -> None:
        self._sim.panel.reset_main()

    def reset_cnc(self) -> None:
        self._sim.panel.reset_cnc()
