"""The seam between "a machine" and the protocol that drives it.

The window, the console and the job logic hold a session through the ``Machine``
protocol below: both ``app.comm.session.Session`` (the student mill's frame protocol)
and ``app.comm.grbl.session.GrblSession`` (GRBL 1.1 / grblHAL) are sans-IO objects with
these names (bytes in with ``feed``, time with ``tick``, the operator's calls), report
through a ``SessionListener`` with the events of ``app.comm.events``, and say what
they can do with ``Capabilities``. ``make_session(kind, ...)`` builds one;
``kind_for_url`` and ``detect`` choose the kind ("frame" or "grbl") for ``auto``.
"""

from __future__ import annotations

import re
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from app.capabilities import Capabilities as BaseCapabilities
from app.comm.frame import OVERRIDE_RANGES

DRIVERS = ("frame", "grbl")
_GRBL_SIGNS = re.compile(rb"(?im)^(grbl|grblhal) \d|^<[A-Za-z]+[|:]|^\[(MSG|GC|VER|OPT):"
                         rb"|^(ok|error:\d+|ALARM:\d+)\r?$")
_FRAME_SIGNS = re.compile(rb"(?m)^[SAFONEILX] [^\r\n]*\*[0-9A-Fa-f]+\r?$")


@dataclass(frozen=True)
class Capabilities(BaseCapabilities):
    """``app.capabilities.Capabilities`` (what the window's state table reads: ``sd_card``,
    ``exact_resume``, ``crc_link``, ``oled_panel``, ``cover``, ``overrides``) plus what a
    driver adds; the defaults are the frame protocol's student mill."""

    check_mode: bool = True
    settings_table: bool = False  # GRBL's $$ table (name, unit, meaning; backup/restore)
    unlock: bool = False  # an alarm lock the operator lifts ($X)
    hold_to_jog: bool = False  # a jog that is cancelled on key release
    home_recover: bool = True  # HOME RECOVER after a fault
    driver: str = "frame"
    # the percentages each override takes (docs/protocol.md, "Overrides"; GRBL's are wider)
    feed_override: range = OVERRIDE_RANGES["FEED"]
    spindle_override: range = OVERRIDE_RANGES["SPINDLE"]
    rapid_override: tuple[int, ...] = tuple(OVERRIDE_RANGES["RAPID"])

    def override_range(self, verb: str):
        """The percentages override ``verb`` (``FEED``, ``SPINDLE``, ``RAPID``) takes, in
        order (a ``range`` for the sliders, the rapid rate's few values)."""
        return getattr(self, f"{verb.lower()}_override")


FRAME_CAPABILITIES = Capabilities()
GRBL_CAPABILITIES = Capabilities(sd_card=False, exact_resume=False, crc_link=False, oled_panel=False,
                                 cover=True, overrides=True, settings_table=True, unlock=True,
                                 hold_to_jog=True, home_recover=False, driver="grbl",
                                 feed_override=range(10, 201), spindle_override=range(10, 201),
                                 rapid_override=(25, 50, 100))


class Machine(Protocol):
    """What the layers above use of either session (see the module docstring)."""

    state: object
    status: object
    capabilities: Capabilities

    def attach(self, write: Callable[[bytes], object]) -> None: ...

    def detach(self, reason: str = "disconnected") -> None: ...

    def feed(self, data: bytes) -> None: ...

    def tick(self) -> None: ...

    def start_job(self, lines, start: int = 0, mdi: bool = False) -> bool: ...

    def pause(self) -> bool | None: ...

    def resume(self) -> bool: ...

    def stop(self) -> bool | None: ...

    def confirm_restart(self) -> bool: ...

    def jog(self, axis: str, distance_mm: float, feed_mm_min: float) -> int: ...

    def send_command(self, text: str) -> int | None: ...


def make_session(kind: str, listener=None, clock: Callable[[], float] = time.monotonic):
    """A detached session of ``kind`` ("frame" or "grbl") with its ``capabilities``."""
    if kind == "grbl":
        from app.comm.grbl.session import GrblSession

        session = GrblSession(None, listener, clock)
        session.capabilities = GRBL_CAPABILITIES
    elif kind == "frame":
        from app.comm.session import Session

        session = Session(None, listener, clock)
        session.capabilities = FRAME_CAPABILITIES
    else:
        raise ValueError(f"driver must be one of {', '.join(DRIVERS)}, not {kind!r}")
    return session


def kind_for_url(url: str | None) -> str | None:
    """The driver a URL names by itself (``sim://grbl``: grbl; ``sim://``: frame), else None."""
    if not url or url.startswith("sim://"):
        return "grbl" if (url or "").lower().startswith("sim://grbl") else "frame"
    return None


def detect(data: bytes) -> str | None:
    """"grbl" or "frame" from the first bytes a machine sent (None: cannot tell yet)."""
    if _GRBL_SIGNS.search(data):
        return "grbl"
    if _FRAME_SIGNS.search(data):
        return "frame"
    return None


def probe(transport, wait: Callable[[float], None] = time.sleep, timeout: float = 2.0) -> str | None:
    """Listen to a freshly opened ``transport`` (a GRBL prints its welcome at reset; the
    frame machine sends status), then ask GRBL for a report (``?``, which the frame
    protocol drops as noise). The bytes read stay in ``transport.probe_bytes``."""
    seen = bytearray()
    step, waited, asked = 0.05, 0.0, False
    while waited < timeout:
        waiting = transport.in_waiting
        if waiting:
            seen += transport.read(waiting)
            kind = detect(bytes(seen))
            if kind:
                transport.probe_bytes = bytes(seen)
                return kind
        if not asked and waited >= timeout / 2:
            transport.write(b"?")
            asked = True
        wait(step)
        waited += step
    transport.probe_bytes = bytes(seen)
    return None
