"""A minimal host for the simulator tests: send frames, collect and check what comes back."""

from __future__ import annotations

from collections.abc import Callable

from app.comm.deframer import Deframer, Dropped
from app.comm.frame import Ack, Data, Error, Finished, Frame, Ok, seal

HOMED_TIMEOUT = 120.0


class Host:
    """Talks to ``sim.host_port`` as the GUI would, one frame at a time, no threads."""

    def __init__(self, sim) -> None:
        self.sim = sim
        self.port = sim.host_port
        self.port.timeout = 0
        self.deframer = Deframer()
        self.frames: list[Frame] = []
        self.times: list[float] = []
        self.dropped: list[Dropped] = []
        self.next_id = 1
        self.acked, self.free, self.done = -1, 8, -1
        self.heartbeat = True
        self.last_sent = sim.clock.now

    def send(self, body: str) -> None:
        self.port.write(seal(body))
        self.last_sent = self.sim.clock.now

    def tick(self) -> None:
        """Send a PING when a second has passed without a frame (the host's heartbeat)."""
        if self.heartbeat and self.sim.clock.now - self.last_sent >= 1.0:
            self.command("PING")

    def command(self, text: str) -> int:
        cid = self.next_id
        self.next_id += 1
        self.send(f"C {cid} {text}")
        return cid

    def pump(self) -> None:
        data = self.port.read(self.port.in_waiting)
        for item in self.deframer.feed(data, self.sim.clock.now):
            if isinstance(item, Dropped):
                self.dropped.append(item)
            else:
                self.frames.append(item)
                self.times.append(self.sim.clock.now)
                self._credit(item)

    def _credit(self, frame: Frame) -> None:
        if isinstance(frame, Ack):
            self.acked, self.free = max(self.acked, frame.seq), frame.free
        elif isinstance(frame, Finished) and frame.seq > self.done:
            self.free += frame.seq - max(self.done, -1)
            self.done = frame.seq

    def realtime(self, verb: str, why: str = "") -> int:
        """Send the real-time command ``R <id> verb`` once; its id."""
        cid = self.next_id
        self.next_id += 1
        self.send(f"R {cid} {verb} {why}".rstrip())
        return cid

    def wait(self, match: Callable[[Frame], bool], timeout: float = 10.0, start: int | None = None) -> Frame:
        """The first frame matching, among those not yet pumped when called (or from ``start``)."""
        found: list[Frame] = []
        start = len(self.frames) if start is None else start

        def done() -> bool:
            self.tick()
            self.pump()
            found[:] = [f for f in self.frames[start:] if match(f)]
            return bool(found)

        assert self.sim.run_until(done, timeout), f"no matching frame in {timeout} s: {self.frames[-8:]}"
        return found[0]

    def answer(self, cid: int, timeout: float = 10.0) -> Frame:
        """The O or E of command ``cid``."""
        return self.wait(lambda f: isinstance(f, Ok | Error) and f.id == cid, timeout)

    def ok(self, text: str, timeout: float = 10.0) -> Ok:
        frame = self.answer(self.command(text), timeout)
        assert isinstance(frame, Ok), frame
        return frame

    def refused(self, text: str, timeout: float = 10.0) -> Error:
        frame = self.answer(self.command(text), timeout)
        assert isinstance(frame, Error), frame
        return frame

    def home(self) -> None:
        self.ok("HOME", HOMED_TIMEOUT)

    def of(self, kind: type) -> list:
        self.pump()
        return [f for f in self.frames if isinstance(f, kind)]

    def stream(self, lines: list[str], count: int | None = None) -> None:
        """Open a job and send its first ``count`` lines within the credit window (no faults)."""
        self.acked, self.free, self.done = -1, 8, -1
        self.ok(f"JOB {len(lines)}")
        for seq, line in enumerate(lines[:count]):
            room = lambda seq=seq: self.tick() or self.pump() or seq - 1 - self.acked < min(self.free, 8)  # noqa: E731
            assert self.sim.run_until(room, 120), "no room in the queue"
            self.send(Data(seq, line).body())
