"""pyserial's URL handler for ``sim://``: the simulator behind ``serial.serial_for_url``.

With ``"backend_sim"`` in ``serial.protocol_handler_packages``, any pyserial program
opens the simulated machine with ``serial.serial_for_url("sim://?speed=5")``:

- ``speed=X`` (default 1): the machine runs X times faster than real time; the link's
  host-facing timers stay in wall-clock time, so the host needs no knowledge of X;
- ``sd=DIR``: the folder standing for the SD card; ``seed=N``: boot ids and faults.

``sim://grbl[?speed=X]`` is the simulated GRBL 1.1 machine (``backend_sim.grbl``) instead.

The port starts its own ``Simulator`` on a thread and stops it on ``close()``; a
caller that keeps one machine across connections (the GUI) sets ``port.simulator``
to a running one before ``open()`` and that simulator is left running. ``clock()``
gives the link's clock (``SimClock.link_now``) for a host living in the same process.
"""

from __future__ import annotations

from urllib.parse import parse_qs, urlsplit

from serial import PortNotOpenError, SerialBase, SerialException


def url_options(url: str | None) -> dict[str, str]:
    """The query options of a ``sim://`` URL as a flat dict (last value wins)."""
    query = urlsplit(url or "sim://").query
    return {key: values[-1] for key, values in parse_qs(query).items()}


def is_grbl_url(url: str | None) -> bool:
    """``sim://grbl[?...]``: the simulated GRBL machine (``backend_sim.grbl``)."""
    return urlsplit(url or "sim://").netloc.lower() == "grbl"


def build_simulator(options: dict[str, str], profile=None, grbl: bool = False):
    """A started ``Simulator`` (``GrblSimulator`` with ``grbl``) for ``sim://`` options;
    ``SerialException`` on a bad option."""
    from backend_sim.grbl.simulator import GrblSimulator
    from backend_sim.simulator import Simulator

    speed = _number(options, "speed", "1", float)
    seed = _number(options, "seed", None, int)
    if not speed > 0:
        raise SerialException(f"sim:// speed must be > 0, not {speed:g}")
    if grbl:
        sim = GrblSimulator(profile=profile, seed=seed)
        sim.start(speed=speed)
        return sim
    sim = Simulator(profile=profile, sd_dir=options.get("sd"), seed=seed)
    sim.start(speed=speed)
    return sim


def _number(options: dict[str, str], name: str, default, kind):
    text = options.get(name, default)
    if text is None:
        return None
    try:
        return kind(text)
    except ValueError:
        raise SerialException(f"sim:// {name} {text!r} is not a number") from None


class Serial(SerialBase):
    """The host end of a simulated machine, as a pyserial ``Serial`` (see the module)."""

    simulator = None
    profile = None
    owns_simulator = False

    def open(self) -> None:
        if self._port is None:
            raise SerialException("Port must be configured before it can be used.")
        if self.is_open:
            raise SerialException("Port is already open.")
        self.owns_simulator = self.simulator is None
        if self.owns_simulator:
            self.simulator = build_simulator(url_options(self._port), self.profile, is_grbl_url(self._port))
        self._host = self.simulator.host_port
        if not self._host.is_open:
            self._host.open()
        self._host.timeout = 0
        self.is_open = True

    @property
    def sim(self):
        return self.simulator

    def clock(self) -> float:
        """The link's clock in seconds (wall-clock paced at any speed factor)."""
        return self.simulator.clock.link_now

    def _reconfigure_port(self) -> None:
        """Nothing to configure: the simulated USB CDC ignores the line settings."""

    def close(self) -> None:
        if not self.is_open:
            return
        self.is_open = False
        try:
            if self.owns_simulator:
                self.simulator.stop()
        finally:
            self._host.close()

    @property
    def in_waiting(self) -> int:
        self._check()
        return self._host.in_waiting

    def read(self, size: int = 1) -> bytes:
        """Up to ``size`` bytes within ``timeout`` wall seconds (None: until ``size``)."""
        self._check()
        timeout = self._timeout
        speed = self.simulator.clock.speed or 1.0
        self._host.timeout = None if timeout is None else timeout * speed
        try:
            return self._host.read(size)
        finally:
            self._host.timeout = 0

    def write(self, data) -> int:
        self._check()
        return self._host.write(bytes(data))

    def reset_input_buffer(self) -> None:
        self._check()
        self._host.reset_input_buffer()

    def reset_output_buffer(self) -> None:
        self._check()

    def flush(self) -> None:
        self._check()

    def _check(self) -> None:
        if not self.is_open:
            raise PortNotOpenError()
