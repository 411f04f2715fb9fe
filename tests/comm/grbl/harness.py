"""A GRBL session driven by hand: a fake clock, the bytes it wrote, every event."""

from __future__ import annotations

from app.comm.grbl.events import GrblListener
from app.comm.grbl.session import GrblSession

WELCOME = b"\r\nGrbl 1.1h ['$' for help]\r\n"


class Recorder(GrblListener):
    def __init__(self) -> None:
        self.events: list = []

    def __getattribute__(self, name):
        if name.startswith("on_"):
            return lambda event: self.events.append((name, event))
        return super().__getattribute__(name)

    def of(self, name: str) -> list:
        return [e for n, e in self.events if n == name]


class Harness:
    def __init__(self, rx_size: int | None = None, greet: bool = True) -> None:
        self.now = 0.0
        self.wire = bytearray()
        self.rec = Recorder()
        self.session = GrblSession(None, self.rec, lambda: self.now, rx_size=rx_size)
        self.session.attach(self.wire.extend)
        if greet:
            self.session.feed(WELCOME)

    def take(self) -> bytes:
        out = bytes(self.wire)
        self.wire.clear()
        return out

    def lines(self) -> list[str]:
        """Lines written since the last take (real-time bytes dropped)."""
        data = self.take()
        return [ln for ln in data.translate(None, b"?!~\x18\x85").decode("latin-1").split("\n") if ln]

    def feed(self, *lines: str) -> None:
        self.session.feed(b"".join(line.encode() + b"\r\n" for line in lines))

    def advance(self, seconds: float, step: float = 0.05) -> None:
        end = self.now + seconds
        while self.now < end - 1e-9:
            self.now = min(end, self.now + step)
            self.session.tick()

    def answer_refresh(self, state: str = "Idle") -> None:
        """Answer the connect-time reads ($I $$ $# $G) and send one report."""
        self.take()
        self.feed("[VER:1.1h.20190825:]", "[OPT:V,15,128]", "ok", "$10=1", "$13=0", "$130=150.000",
                  "$131=150.000", "$132=30.000", "$23=3", "ok", "[G54:-150.000,-150.000,-10.000]", "ok",
                  "[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok",
                  f"<{state}|MPos:-100.000,-100.000,-5.000|FS:0,0|WCO:-150.000,-150.000,-10.000>")
        self.take()
