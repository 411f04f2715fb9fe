"""Transports: the pyserial-shaped seam between the session and the machine.

``open_transport(url)`` returns an object with pyserial's ``read(n)``,
``write(data) -> int``, ``in_waiting``, ``reset_input_buffer()`` and ``close()``,
raising pyserial's exceptions (``SerialException`` is an ``OSError``):

- ``sim://[?speed=X&sd=DIR]`` (also ``""``/None): an in-process ``backend_sim``
  Simulator started on its own thread at ``speed`` times real time (default 1);
- anything else: ``serial.serial_for_url(url, baudrate=115200, timeout=0)``: a
  real port (``/dev/ttyUSB0``, ``COM3``), ``socket://host:port``, ``loop://``,
  ``spy://...``.

``list_ports()`` lists the simulator first, then the serial ports found by
``serial.tools.list_ports``.
"""

from __future__ import annotations

from dataclasses import dataclass
from urllib.parse import parse_qs, urlsplit

import serial
import serial.tools.list_ports

from app.i18n import msg

SIM_URL = "sim://"
BAUDRATE = 115200


@dataclass(frozen=True)
class PortInfo:
    """One entry of the port list: what to pass to ``open_transport`` and what to show."""

    url: str
    description: str


def is_sim(url: str | None) -> bool:
    return not url or url.startswith(SIM_URL)


def sim_options(url: str | None) -> dict[str, str]:
    """The query options of a ``sim://`` URL as a flat dict (last value wins)."""
    query = urlsplit(url or SIM_URL).query
    return {key: values[-1] for key, values in parse_qs(query).items()}


def open_transport(url: str | None):
    """Open ``url`` (see the module docstring); raises ``serial.SerialException``/``OSError``."""
    if is_sim(url):
        return SimTransport.start(sim_options(url))
    return serial.serial_for_url(url, baudrate=BAUDRATE, timeout=0)


def list_ports() -> list[PortInfo]:
    """The simulator first, then every serial port the OS reports."""
    ports = [PortInfo(SIM_URL, msg("Simulated machine (in-process)"))]
    for port in sorted(serial.tools.list_ports.comports(), key=lambda p: p.device):
        ports.append(PortInfo(port.device, port.description or port.device))
    return ports


def start_simulator(options: dict[str, str], profile=None):
    """A ``backend_sim`` Simulator for ``sim://`` options, started on its own thread."""
    from backend_sim import Simulator

    try:
        speed = float(options.get("speed", "1"))
    except ValueError:
        raise serial.SerialException(f"sim:// speed {options['speed']!r} is not a number") from None
    sim = Simulator(profile=profile, sd_dir=options.get("sd"))
    sim.start(speed=speed)
    return sim


class SimTransport:
    """The host port of an in-process simulator running on its own thread.

    ``close()`` closes the port, and stops the simulator too if this transport owns it
    (a GUI keeps its simulator running across disconnects, as a real machine would).
    """

    def __init__(self, sim, owns_sim: bool = True) -> None:
        self.sim = sim
        self.port = sim.host_port
        self.owns_sim = owns_sim

    def clock(self) -> float:
        """The simulator's clock in seconds: the host's timers run on machine time."""
        return self.sim.clock.now

    @classmethod
    def start(cls, options: dict[str, str]) -> SimTransport:
        return cls(start_simulator(options))

    @property
    def in_waiting(self) -> int:
        return self.port.in_waiting

    @property
    def timeout(self):
        return self.port.timeout

    def read(self, size: int = 1) -> bytes:
        return self.port.read(size)

    def write(self, data: bytes) -> int:
        return self.port.write(data)

    def reset_input_buffer(self) -> None:
        self.port.reset_input_buffer()

    def close(self) -> None:
        try:
            if self.owns_sim:
                self.sim.stop()
        finally:
            self.port.close()
