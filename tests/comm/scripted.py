"""Helpers to drive a Session by hand: a fake clock, a recording listener, scripted replies."""

from __future__ import annotations

from app.comm import deframer as dfr
from app.comm import frame as fr
from app.comm.listener import SessionListener
from app.comm.session import Session

BOOT = "B00710AD"


class FakeClock:
    """A clock the test moves: ``clock()`` -> now; ``advance(dt)``."""

    def __init__(self, now: float = 100.0) -> None:
        self.now = now

    def __call__(self) -> float:
        return self.now


class Recorder(SessionListener):
    """Keeps every event by method name: ``rec.events["on_status"]``."""

    def __init__(self) -> None:
        self.events: dict[str, list] = {}

    def __getattribute__(self, name):
        if name.startswith("on_"):
            return lambda event: self.events.setdefault(name, []).append(event)
        return super().__getattribute__(name)

    def of(self, name: str) -> list:
        return self.events.get(name, [])

    def last(self, name: str):
        return self.of(name)[-1] if self.of(name) else None


class Harness:
    """A session whose writes are captured and decoded; replies are fed as frames."""

    def __init__(self, connect: bool = True, status: fr.Status | None = None) -> None:
        self.clock = FakeClock()
        self.rec = Recorder()
        self.wire = bytearray()
        self.session = Session(self.wire.extend, self.rec, self.clock)
        if connect:
            self.session.attach(self.wire.extend)
            self.reply(status or self.status())
            self.take()

    @staticmethod
    def status(state="IDLE", acc=-1, done=-1, free=16, flags="H", boot=BOOT) -> fr.Status:
        return fr.Status(boot, state, 0.0, 0.0, 10.0, acc, done, free, 0, flags)

    def reply(self, *frames: fr.Frame | bytes) -> None:
        data = b"".join(f if isinstance(f, bytes) else fr.encode(f) for f in frames)
        self.session.feed(data)

    def advance(self, seconds: float, step: float = 0.005) -> None:
        """Move the clock in steps, ticking the session each step."""
        end = self.clock.now + seconds
        while self.clock.now < end - 1e-9:
            self.clock.now = min(end, self.clock.now + step)
            self.session.tick()

    def take(self) -> list:
        """Frames written since the last take, decoded (a legacy byte as its bytes)."""
        data, self.wire[:] = bytes(self.wire), b""
        out = []
        for item in dfr.Deframer(legacy=True).feed(data, 0.0):
            out.append(item.byte if isinstance(item, dfr.Legacy) else item)
        return out

    def take_data(self) -> list[int]:
        return [f.seq for f in self.take() if isinstance(f, fr.Data)]

    def command(self, verb: str) -> fr.Command:
        found = [f for f in self.take() if isinstance(f, fr.Command) and f.verb == verb]
        assert found, f"no {verb} command was sent"
        return found[-1]

    def open_job(self, lines: list[str], free: int = 16) -> None:
        assert self.session.start_job(lines)
        job = self.command("JOB")
        self.reply(fr.Ok(job.id, "JOB", str(len(lines))))
