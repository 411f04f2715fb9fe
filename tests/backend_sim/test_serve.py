"""The pty bridge never cuts a frame short for a slow reader, and gives up on one that
reads nothing (``backend_sim/serve.py``): the pty's buffer is filled first, as a host
busy elsewhere leaves it."""

from __future__ import annotations

import os
import select
import threading
import time
from types import SimpleNamespace

import pytest

from backend_sim import serve


@pytest.fixture
def server():
    bridge = serve.PtyServer(SimpleNamespace(host_port=None))
    yield bridge
    bridge.close()


def _fill(fd: int) -> int:
    """Write until the pty takes no more; the byte count."""
    written = 0
    try:
        while True:
            written += os.write(fd, b"f" * 512)
    except BlockingIOError:
        return written


def _read(fd: int, count: int, seconds: float = 30.0) -> bytes:
    data, deadline = bytearray(), time.monotonic() + seconds
    while len(data) < count and time.monotonic() < deadline:
        if select.select([fd], [], [], 0.1)[0]:
            data += os.read(fd, 65536)
    return bytes(data)


def test_a_slow_reader_gets_every_byte_of_what_is_sent_while_it_is_full(server):
    filler = _fill(server.master)
    frames = b"".join(b"S 1234ABCD IDLE %07d*0000\n" % k for k in range(400))  # 10 kB
    full, wait_for_room = threading.Event(), server._wait_for_room

    def waits() -> None:  # the sender met the full pty (the reader is busy elsewhere)
        full.set()
        wait_for_room()

    server._wait_for_room = waits
    sender = threading.Thread(target=server._send, args=(frames,))
    sender.start()
    assert full.wait(5), "the sender never found the pty full"
    got = _read(server.slave, filler + len(frames))
    sender.join(5)
    assert not sender.is_alive()
    assert got == b"f" * filler + frames


def test_bytes_nobody_reads_are_dropped_after_a_while(server, monkeypatch):
    monkeypatch.setattr(serve, "DROP_AFTER_S", 0.2)
    _fill(server.master)
    started = time.monotonic()
    server._send(b"S lost*0000\n")  # returns: nobody reads
    assert time.monotonic() - started < 5
