"""Transports: the pyserial-shaped seam between the session and the machine.

``open_transport(url)`` is ``serial.serial_for_url(url, baudrate=115200, timeout=0)``:
an object with pyserial's ``read(n)``, ``write(data) -> int``, ``in_waiting``,
``reset_input_buffer()`` and ``close()``, raising pyserial's exceptions
(``SerialException`` is an ``OSError``): a real port (``/dev/ttyUSB0``, ``COM3``),
``socket://host:port``, ``loop://``, ``spy://...``, and every scheme a package in
``URL_HANDLER_PACKAGES`` serves through pyserial's own URL handler mechanism
(``<package>.protocol_<scheme>``; ``sim://`` is the simulator's). This module names
those packages; it imports none of them.

A transport may offer ``clock()`` (seconds): the host's timers then run on it (an
in-process simulated machine); otherwise they run on the wall clock.

``list_ports()`` lists the serial ports found by ``serial.tools.list_ports``.
"""

from __future__ import annotations

from dataclasses import dataclass

import serial
import serial.tools.list_ports

SIM_URL = "sim://"
BAUDRATE = 115200
URL_HANDLER_PACKAGES = ("backend_sim",)


@dataclass(frozen=True)
class PortInfo:
    """One entry of the port list: what to pass to ``open_transport`` and what to show."""

    url: str
    description: str


def register_url_handlers(packages=URL_HANDLER_PACKAGES) -> None:
    """Let ``serial.serial_for_url`` find the handlers of ``packages`` (idempotent)."""
    for package in packages:
        if package not in serial.protocol_handler_packages:
            serial.protocol_handler_packages.append(package)


def is_sim(url: str | None) -> bool:
    return bool(url) and url.startswith(SIM_URL)


def open_transport(url: str | None, do_not_open: bool = False):
    """Open ``url`` (None or "": ``sim://``); raises ``serial.SerialException``/``OSError``
    (a URL with an unknown scheme is a ``SerialException`` too)."""
    register_url_handlers()
    try:
        return serial.serial_for_url(url or SIM_URL, baudrate=BAUDRATE, timeout=0,
                                     do_not_open=do_not_open)
    except ValueError as exc:
        raise serial.SerialException(f"cannot open {url}: {exc}") from None


def list_ports() -> list[PortInfo]:
    """Every serial port the OS reports."""
    return [PortInfo(port.device, port.description or port.device)
            for port in sorted(serial.tools.list_ports.comports(), key=lambda p: p.device)]
