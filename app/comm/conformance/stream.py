"""The kit's own job streamer: the host's side of "Errors and resends", from the doc.

``Streamer(link, lines, free)`` sends ``D <seq> <line>`` frames after the caller's
``JOB``: at most ``min(free, 16)`` unacknowledged (``free`` from the last ``A``, plus
the lines an ``F`` reports finished), frame ``n`` alone on ``N n`` (a repeat ``N n``
within a probe time of its last resend ignored), the first unacknowledged frame alone
after a probe time without progress. ``hold_after`` keeps the stream at a program
stop until that line's ``F``. ``run(timeout)`` returns when ``F`` of the last line
comes, a line is refused (``E -``), or the time is up (``run(timeout, to_stop=True)``
also once the stream waits at a program stop with every frame sent acknowledged);
``Outcome`` says which, with
the counts the checks judge (``naks``, ``resends``, the highest window used).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.comm.conformance.link import Link
from app.comm.conformance.wire import Reply

WINDOW_CAP = 16
PROBE_S = 0.25


@dataclass
class Outcome:
    done: int = -1
    acked: int = -1
    refused: Reply | None = None
    naks: list[int] = field(default_factory=list)
    resends: int = 0
    most_in_flight: int = 0
    complete: bool = False
    overrun: list[str] = field(default_factory=list)  # frames the machine could not take (N at the window)


class Streamer:
    def __init__(self, link: Link, lines: list[str], free: int, hold_after: set[int] | None = None) -> None:
        self.link, self.lines = link, lines
        self.free = free
        self.hold_after = hold_after or set()
        self.next = 0
        self.out = Outcome()
        self.resent_at: dict[int, float] = {}
        self.progress_at = link.clock()
        self.index = len(link.replies)  # replies are read from here on, across runs

    def window(self) -> int:
        return min(self.free, WINDOW_CAP)

    def _may_send(self) -> bool:
        if self.next >= len(self.lines):
            return False
        if any(self.out.done < stop < self.next for stop in self.hold_after):
            return False
        return self.next - (self.out.acked + 1) < self.window()

    def _waiting_at_stop(self) -> bool:
        """Every frame sent is acknowledged and a program stop holds the rest back."""
        held = any(self.out.done < stop < self.next for stop in self.hold_after)
        return held and self.out.acked >= self.next - 1

    def _send(self, seq: int) -> None:
        self.link.send(f"D {seq} {self.lines[seq]}")

    def run(self, timeout: float, to_stop: bool = False) -> Outcome:
        deadline = self.link.clock() + timeout
        last = len(self.lines) - 1
        self._take_new()
        while self.out.done < last and self.out.refused is None and self.link.clock() < deadline:
            if to_stop and self._waiting_at_stop():
                break
            while self._may_send():
                self._send(self.next)
                self.next += 1
                self.out.most_in_flight = max(self.out.most_in_flight, self.next - self.out.acked - 1)
            self.link.pump()
            self._take_new()
            self._probe()
        self.out.complete = self.out.done >= last
        return self.out

    def _take_new(self) -> None:
        """What came since the last look (also while the caller waited between runs)."""
        for reply in self.link.since(self.index):
            self._take(reply)
        self.index = len(self.link.replies)

    def _take(self, reply: Reply) -> None:
        now = self.link.clock()
        if reply.kind == "A":
            seq, free = reply.int(0), reply.int(1)
            if seq > self.out.acked:
                self.out.acked, self.progress_at = seq, now
            self.free = free
        elif reply.kind == "F" and reply.int(0) > self.out.done:
            self.free += reply.int(0) - self.out.done
            self.out.done, self.progress_at = reply.int(0), now
        elif reply.kind == "N":
            self._nak(reply.int(0), now)
        elif reply.kind == "E" and reply.id is None:
            self.out.refused = reply

    def _nak(self, seq: int, now: float) -> None:
        self.out.naks.append(seq)
        if seq >= self.next or now - self.resent_at.get(seq, -1e9) < PROBE_S or seq <= self.out.acked:
            return
        self.resent_at[seq] = now
        self.out.resends += 1
        self._send(seq)

    def _probe(self) -> None:
        now = self.link.clock()
        first = self.out.acked + 1
        if (
            first < self.next
            and now - self.progress_at >= PROBE_S
            and now - self.resent_at.get(first, -1e9) >= PROBE_S
        ):
            self.resent_at[first] = now
            self.out.resends += 1
            self._send(first)
            self.progress_at = now
