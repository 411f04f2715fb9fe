"""The GUI's end of the link: the serial worker on its thread, and the built-in
simulator kept alive across disconnects.

A real machine does not vanish when its USB cable is pulled; so the simulator behind
``sim://`` is created once (per speed and SD folder) and a disconnect only closes its
host port. Reconnecting reaches the same machine, which is what resume needs; the
machine panel dock keeps showing it meanwhile. ``MachineLink.shutdown()`` stops both.
"""

from __future__ import annotations

import threading

from PySide6.QtCore import QObject, QTimer

from app.capabilities import FRAME_PROTOCOL, Capabilities
from app.comm.transport import is_sim, open_transport
from app.comm.worker import SerialController, SerialWorker


class SimOpener:
    """``open_transport`` for the worker, reusing one running simulator for ``sim://``
    (keyed by the URL; the port's ``simulator`` is set before it opens)."""

    def __init__(self, profile=None):
        self.profile = profile
        self.sim = None
        self._key = None
        self._lock = threading.Lock()

    def __call__(self, url: str):
        if not is_sim(url or "sim://"):
            return open_transport(url)
        with self._lock:
            port = open_transport(url, do_not_open=True)
            port.profile = self.profile
            if self.sim is not None and url == self._key:
                port.simulator = self.sim
            port.open()
            if port.simulator is not self.sim:
                self.stop()
                self.sim, self._key = port.simulator, url
            port.owns_simulator = False  # the opener keeps it across connections
            return port

    def stop(self) -> None:
        sim, self.sim = self.sim, None
        if sim is not None:
            sim.stop()


def _apply_link_timing(worker, link) -> None:
    monitor = worker.session.link
    monitor.heartbeat_s, monitor.degraded_s, monitor.lost_s = link.heartbeat_s, link.degraded_s, link.lost_s


class MachineLink(QObject):
    """Owns the ``SerialController`` (worker thread) and the simulator opener."""

    def __init__(self, parent=None, profile=None):
        super().__init__(parent)
        self.opener = SimOpener(profile)
        self.controller = SerialController(self, SerialWorker(opener=self.opener))
        self.worker = self.controller.worker
        self.url = ""
        self.driver = ""
        if profile is not None:
            _apply_link_timing(self.worker, profile.link)  # before the thread starts
        self.controller.start()

    def set_link_timing(self, link) -> None:
        """New heartbeat / degraded / lost periods, applied in the worker's thread."""
        QTimer.singleShot(0, self.worker, lambda: _apply_link_timing(self.worker, link))

    @property
    def capabilities(self) -> Capabilities:
        """What the connected machine can do, as its driver says (the frame protocol's
        mill until a driver provides its own ``capabilities``)."""
        return getattr(self.worker.session, "capabilities", FRAME_PROTOCOL)

    @property
    def sim(self):
        """The built-in simulator, once ``sim://`` has been opened (else None)."""
        return self.opener.sim

    def clock(self) -> float:
        """The session's clock (machine time: the simulator's clock for ``sim://``)."""
        return self.worker.session.clock()

    def call(self, name: str, *args) -> None:
        self.controller.call(name, *args)

    def connect_to(self, url: str, driver: str | None = None) -> None:
        """Open ``url``; ``driver`` "auto", "frame" or "grbl" (None: the last one chosen)."""
        self.url = url
        if driver is not None:
            self.driver = driver
        self.controller.call("connect_to", url, self.driver)

    def shutdown(self) -> None:
        self.controller.shutdown()
        self.opener.stop()
