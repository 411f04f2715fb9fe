"""Serve the simulator's host port on a pseudo-terminal or a TCP socket.

Contract: ``PtyServer(sim)`` opens a pty pair in raw mode (``path`` is the slave,
e.g. ``/dev/pts/5``, what pyserial opens); ``TcpServer(sim, port)`` listens on
127.0.0.1 (for ``socket://127.0.0.1:PORT``), one client at a time, a new client
replacing the old. ``start()`` runs two daemon threads: bytes from the far end go to
``sim.host_port.write``; bytes the host port receives go to the far end as soon as
they land. ``close()`` stops both. A slow reader gets every byte (the sender waits for
room, as a USB device's endpoint waits for the host to poll it: a frame is never cut
short); bytes nobody reads for ``DROP_AFTER_S`` are dropped, as USB CDC would.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import select
import socket
import threading
import time
import tty

import serial

_POLL_S = 0.1
DROP_AFTER_S = 2.0  # a far end that reads nothing for this long is gone: its bytes are dropped


class _Bridge:
    def __init__(self, sim) -> None:
        self.sim = sim
        self.port = sim.host_port
        self._stop = threading.Event()
        self._threads: list[threading.Thread] = []

    def start(self) -> None:
        for target in (self._inbound, self._outbound):
            thread = threading.Thread(target=target, daemon=True, name=f"cnc-sim-{target.__name__}")
            thread.start()
            self._threads.append(thread)

    def close(self) -> None:
        self._stop.set()
        for thread in self._threads:
            thread.join(timeout=2)

    def _outbound(self) -> None:
        """Bytes that land at the host port go out at once; the wait is in wall time,
        whatever the speed factor and however far the simulation lags."""
        self.port.timeout = 0
        while not self._stop.is_set():
            try:
                with self.sim.lock:
                    self.sim.condition.wait_for(self._landed, _POLL_S)
                    data = self.port.read(self.port.in_waiting)
            except serial.SerialException:
                self._stop.wait(_POLL_S)
                continue
            if data:
                self._send(data)

    def _landed(self) -> bool:
        return self.port.landed() > 0 or self._stop.is_set() or self.port.unplugged

    def _inbound(self) -> None:
        raise NotImplementedError

    def _send(self, data: bytes) -> None:
        """``data`` whole to the far end, waiting for room while it reads (see above)."""
        view, deadline = memoryview(data), time.monotonic() + DROP_AFTER_S
        while view and not self._stop.is_set():
            try:
                view = view[self._write_some(view):]
            except (BlockingIOError, InterruptedError, TimeoutError):
                if time.monotonic() > deadline:
                    return
                self._wait_for_room()
            except OSError:
                return

    def _write_some(self, data: memoryview) -> int:
        raise NotImplementedError

    def _wait_for_room(self) -> None:
        """Until the far end may take more bytes (or ``_POLL_S``)."""

    def _to_host_port(self, data: bytes) -> None:
        with contextlib.suppress(serial.SerialException):
            self.port.write(data)


class PtyServer(_Bridge):
    def __init__(self, sim) -> None:
        super().__init__(sim)
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        flags = fcntl.fcntl(self.master, fcntl.F_GETFL)
        fcntl.fcntl(self.master, fcntl.F_SETFL, flags | os.O_NONBLOCK)

    def _inbound(self) -> None:
        while not self._stop.is_set():
            ready, _, _ = select.select([self.master], [], [], _POLL_S)
            if not ready:
                continue
            try:
                data = os.read(self.master, 4096)
            except (BlockingIOError, InterruptedError):
                continue
            except OSError:
                self._stop.wait(_POLL_S)
                continue
            if data:
                self._to_host_port(data)

    def _write_some(self, data: memoryview) -> int:
        return os.write(self.master, data)

    def _wait_for_room(self) -> None:
        select.select([], [self.master], [], _POLL_S)

    def close(self) -> None:
        super().close()
        for fd in (self.master, self.slave):
            with contextlib.suppress(OSError):
                os.close(fd)


class TcpServer(_Bridge):
    def __init__(self, sim, port: int) -> None:
        super().__init__(sim)
        self.listener = socket.create_server(("127.0.0.1", port))
        self.address = self.listener.getsockname()
        self.client: socket.socket | None = None

    def _inbound(self) -> None:
        self.listener.settimeout(_POLL_S)
        while not self._stop.is_set():
            try:
                client, _ = self.listener.accept()
            except (TimeoutError, OSError):
                continue
            self._serve(client)

    def _serve(self, client: socket.socket) -> None:
        if self.client is not None:
            with contextlib.suppress(OSError):
                self.client.close()
        self.client = client
        client.settimeout(_POLL_S)
        while not self._stop.is_set():
            try:
                data = client.recv(4096)
            except TimeoutError:
                continue
            except OSError:
                break
            if not data:
                break
            self._to_host_port(data)
        with contextlib.suppress(OSError):
            client.close()
        if self.client is client:
            self.client = None

    def _write_some(self, data: memoryview) -> int:
        client = self.client
        return client.send(data) if client is not None else len(data)  # (no client: nobody reads)

    def close(self) -> None:
        super().close()
        with contextlib.suppress(OSError):
            self.listener.close()
