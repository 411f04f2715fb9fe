"""The kit's side of the wire: bytes out, checked replies in, on the wall clock.

``Link(port)`` wraps anything with pyserial's ``read``/``write``/``in_waiting``.
Every line the machine sends becomes a ``Reply`` (kept in ``replies`` with its
arrival time, bad ones too: the checks judge them). While ``heartbeat`` is on, the
link sends ``C <id> PING`` after every 0.25 s without writing, every 0.02 s once
nothing valid has come for 0.5 s (docs/protocol.md, "Heartbeat"), so the machine never
sees a host loss the kit did not mean. Command ids start at a random value below 1,000,000 and count up
("Host conventions").
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable

from app.comm.conformance.wire import Reply, seal

PING_EVERY_S = 0.25
QUIET_PING_S = 0.02  # once nothing valid has come for QUIET_S ("Heartbeat")
QUIET_S = 0.5
RETRY_S = 0.25  # a command's retry, same id, no back-off ("Host conventions")
READ_SLICE_S = 0.01


class LinkDead(Exception):
    """The port failed (unplugged, closed): no further check can run."""


class Link:
    def __init__(self, port, clock: Callable[[], float] = time.monotonic) -> None:
        self.port, self.clock = port, clock
        self.port.timeout = READ_SLICE_S
        self.replies: list[Reply] = []
        self.rx = bytearray()
        self.next_id = random.randrange(1, 1_000_000)
        self.last_write = -1e9
        self.last_valid = clock()
        self.heartbeat = True
        self.corrupt: Callable[[bytes], bytes] | None = None  # the noisy-wire section's filter

    # -- out ---------------------------------------------------------------------------
    def write(self, data: bytes) -> None:
        if self.corrupt is not None:
            data = self.corrupt(data)
        try:
            self.port.write(data)
        except OSError as exc:
            raise LinkDead(f"write failed: {exc}") from None
        self.last_write = self.clock()

    def send(self, body: str) -> None:
        self.write(seal(body))

    def new_id(self) -> int:
        cid, self.next_id = self.next_id, self.next_id + 1
        return cid

    def send_command(self, text: str, cid: int | None = None) -> int:
        cid = self.new_id() if cid is None else cid
        self.send(f"C {cid} {text}")
        return cid

    # -- in ----------------------------------------------------------------------------
    def pump(self) -> None:
        """Read what has come (waiting at most one read slice); ping when due."""
        now = self.clock()
        every = QUIET_PING_S if now - self.last_valid >= QUIET_S else PING_EVERY_S
        if self.heartbeat and now - self.last_write >= every:
            self.send_command("PING")
        try:
            data = self.port.read(max(1, self.port.in_waiting))
        except OSError as exc:
            raise LinkDead(f"read failed: {exc}") from None
        if not data:
            return
        self.rx += data
        now = self.clock()
        while (end := self.rx.find(b"\n")) >= 0:
            line, self.rx = bytes(self.rx[: end + 1]), self.rx[end + 1 :]
            reply = Reply.parse(line, now)
            self.replies.append(reply)
            if reply.problem is None:
                self.last_valid = now

    def wait(self, match: Callable[[Reply], bool], timeout: float, start: int | None = None) -> Reply | None:
        """The first valid reply from index ``start`` (default: from now on) that matches."""
        index = len(self.replies) if start is None else start
        deadline = self.clock() + timeout
        while True:
            while index < len(self.replies):
                reply = self.replies[index]
                index += 1
                if reply.problem is None and match(reply):
                    return reply
            if self.clock() >= deadline:
                return None
            self.pump()

    def idle(self, seconds: float) -> None:
        """Let ``seconds`` pass, reading (and pinging, if the heartbeat is on)."""
        self.wait(lambda r: False, seconds)

    def since(self, start: int) -> list[Reply]:
        return [r for r in self.replies[start:] if r.problem is None]

    # -- commands ------------------------------------------------------------------------
    def command(self, text: str, timeout: float = 5.0, cid: int | None = None) -> tuple[int, Reply | None]:
        """Send ``C <id> text`` and wait for its ``O``/``E``, repeating the same id every
        0.25 s, as a host does ("Host conventions")."""
        start = len(self.replies)
        cid = self.send_command(text, cid)
        deadline = self.clock() + timeout
        while True:
            answer = self.wait(lambda r: r.kind in "OE" and r.id == cid, min(RETRY_S, timeout), start)
            if answer is not None or self.clock() >= deadline:
                return cid, answer
            self.send_command(text, cid)

    def realtime(self, verb: str, timeout: float = 5.0, cid: int | None = None) -> tuple[int, Reply | None]:
        """Send ``R <id> verb`` as a host does ("Real-time commands": two copies back to
        back, then one every 10 ms) until its ``O``/``E`` arrives or ``timeout``."""
        start = len(self.replies)
        cid = self.new_id() if cid is None else cid
        frame = f"R {cid} {verb}"
        self.send(frame)
        self.send(frame)
        deadline = self.clock() + timeout
        while True:
            answer = self.wait(lambda r: r.kind in "OE" and r.id == cid, 0.01, start)
            if answer is not None or self.clock() >= deadline:
                return cid, answer
            self.send(frame)

    def status(self, timeout: float = 2.0):
        """A fresh status (the answer to ``STATUS``), or None."""
        start = len(self.replies)
        self.send_command("STATUS")
        reply = self.wait(lambda r: r.kind == "S", timeout, start)
        return None if reply is None else reply.status()
