"""The host end of the USB link, shaped like pyserial's ``Serial`` (the transport seam).

Contract: ``read(size=1)`` returns up to ``size`` bytes, waiting at most ``timeout``
seconds of *simulated* time (``None``: until ``size`` bytes; ``0``: never waits). If
the simulator runs on its own thread, the caller waits on a condition; if not, the
read itself advances the simulation as fast as possible until the bytes are there or
the timeout has passed, so a test needs no thread and no sleep. ``write(data)``
returns ``len(data)``; ``in_waiting``, ``reset_input_buffer()``,
``reset_output_buffer()``, ``flush()``, ``close()``/``open()``, ``is_open``.
When unplugged, reads and writes raise ``serial.SerialException``; after ``close()``,
``serial.PortNotOpenError``. After a replug the same object works again.
Bytes that the host does not read pile up to ``RX_LIMIT``; older ones are lost.
"""

from __future__ import annotations

import math

import serial

RX_LIMIT = 1 << 16
_WAIT_SLICE_S = 0.05


class HostPort:
    port = "sim://"
    name = "sim://"
    baudrate = 115200

    def __init__(self, sim) -> None:
        self._sim = sim
        self._rx = bytearray()
        self._timeout: float | None = None
        self.write_timeout: float | None = None
        self.is_open = True
        self.unplugged = False
        self.lost_bytes = 0

    # ------------------------------------------------------------------ pyserial API

    @property
    def timeout(self) -> float | None:
        return self._timeout

    @timeout.setter
    def timeout(self, value: float | None) -> None:
        if value is not None and value < 0:
            raise ValueError(f"timeout must be >= 0 or None, not {value}")
        self._timeout = value

    @property
    def in_waiting(self) -> int:
        self._check()
        with self._sim.lock:
            return len(self._rx)

    def read(self, size: int = 1) -> bytes:
        self._check()
        with self._sim.lock:
            if len(self._rx) < size and self._timeout != 0:
                self._wait_for(size)
            self._check()
            out = bytes(self._rx[:size])
            del self._rx[:size]
            return out

    def read_until(self, expected: bytes = b"\n", size: int | None = None) -> bytes:
        """Bytes up to and including ``expected``, ``size`` bytes, or what came in ``timeout``."""
        out = bytearray()
        timeout, clock = self._timeout, self._sim.clock
        deadline = None if timeout is None else clock.now + timeout
        try:
            while not out.endswith(expected) and (size is None or len(out) < size):
                if deadline is not None:
                    self._timeout = max(0.0, deadline - clock.now)
                byte = self.read(1)
                if not byte:
                    break
                out += byte
        finally:
            self._timeout = timeout
        return bytes(out)

    readline = read_until

    def write(self, data: bytes) -> int:
        self._check()
        data = bytes(data)
        with self._sim.lock:
            self._sim.wires["usb_down"].write(data, self._sim.clock.now)
            self._sim.wake()
        return len(data)

    def reset_input_buffer(self) -> None:
        self._check()
        with self._sim.lock:
            self._rx.clear()

    def reset_output_buffer(self) -> None:
        self._check()

    def flush(self) -> None:
        self._check()

    def close(self) -> None:
        self.is_open = False
        with self._sim.lock:
            self._sim.wake()

    def open(self) -> None:
        if self.unplugged:
            raise serial.SerialException("could not open port sim://: device unplugged")
        self.is_open = True

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # ------------------------------------------------------------------ simulator side

    def deliver(self, data: bytes) -> None:
        """Bytes that have landed at the host (called by the simulator, under its lock)."""
        if not self.is_open or self.unplugged:
            return
        self._rx += data
        if len(self._rx) > RX_LIMIT:
            self.lost_bytes += len(self._rx) - RX_LIMIT
            del self._rx[: len(self._rx) - RX_LIMIT]

    def landed(self) -> int:
        """Bytes waiting for the host, without the port checks (the servers' wait)."""
        return len(self._rx)

    def set_unplugged(self, unplugged: bool) -> None:
        self.unplugged = unplugged
        if unplugged:
            self._rx.clear()

    def _check(self) -> None:
        if self.unplugged:
            raise serial.SerialException("device reports readiness to read but returned no data "
                                         "(device disconnected or multiple access on port?)")
        if not self.is_open:
            raise serial.PortNotOpenError()

    def _wait_for(self, size: int) -> None:
        sim = self._sim
        deadline = None if self._timeout is None else sim.clock.now_ms + math.ceil(self._timeout * 1000)
        ready = lambda: len(self._rx) >= size or self.unplugged or not self.is_open  # noqa: E731
        if not sim.running:
            sim.run_until_locked(ready, deadline)
            return
        while not ready() and (deadline is None or sim.clock.now_ms < deadline):
            wall = _WAIT_SLICE_S if deadline is None else sim.clock.wall_until(deadline)
            sim.condition.wait(min(max(wall, 0.001), _WAIT_SLICE_S))
            if not sim.running:
                sim.run_until_locked(ready, deadline)
                return
