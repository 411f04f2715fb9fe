"""Sender of one stream of ``D`` frames with the credit window of docs/protocol.md.

``SendWindow`` knows the lines of one stream and the machine's acknowledgements; it
never writes. ``due(now)`` returns the frames to send now; ``on_ack``/``on_nak``/
``on_status_ack`` take the machine's answers. Contract:

- at most ``min(free, 16)`` frames are unacknowledged, where ``free`` comes from the
  newest ``A`` (or ``S``) snapshot: frame ``s`` is sent only if ``s <= acked + 16`` and
  ``s <= acc + free`` of some snapshot (that sum never decreases within a stream);
- ``N n``: frame ``n`` alone is resent (selective repeat: the machine keeps the
  frames above a gap), except a repeat ``N n`` within one timeout of the last resend
  of ``n``; it acknowledges nothing (with two hops, the main MCU's ``N`` for a USB
  error can come before the CNC MCU has what lies below);
- no acknowledgement within ``rtt.probe_timeout`` of the last progress resends the
  first unacknowledged frame alone and doubles the timeout;
- after ``MAX_RETRIES`` resends of one seq spread over at least ``MIN_FAIL_S``,
  ``failed`` names the error.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.comm.frame import Data
from app.comm.rtt import RttEstimator
from app.i18n import msg

MAX_WINDOW = 16
MAX_RETRIES = 10
MIN_FAIL_S = 5.0


@dataclass
class SendWindow:
    """Sender state of one stream; seqs run from ``start`` to ``len(lines) - 1``."""

    lines: list[str]
    start: int = 0
    free: int = 1
    rtt: RttEstimator = field(default_factory=RttEstimator)
    max_window: int = MAX_WINDOW
    max_retries: int = MAX_RETRIES
    acked: int = -1
    next_seq: int = 0
    room_end: int = 0
    sent: int = 0
    resent: int = 0
    high_sent: int = -1
    failed: str = ""
    timeouts: int = 0
    hold_at: int | None = None  # no frame after this seq is sent (a program stop line)
    _first_sent: dict[int, float] = field(default_factory=dict)
    _resent_seqs: set[int] = field(default_factory=set)
    _retries: dict[int, int] = field(default_factory=dict)
    _first_retry: dict[int, float] = field(default_factory=dict)
    _timer: float | None = None
    _repeat: set[int] = field(default_factory=set)
    _last_sent: dict[int, float] = field(default_factory=dict)
    _repeated_at: dict[int, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.acked = self.high_sent = self.start - 1
        self.next_seq = self.start
        self.room_end = self.acked + self.free

    @property
    def total(self) -> int:
        return len(self.lines)

    @property
    def in_flight(self) -> int:
        """Frames sent and not yet acknowledged."""
        return self.next_seq - self.acked - 1

    @property
    def all_acked(self) -> bool:
        return self.acked >= self.total - 1

    @property
    def resend_rate(self) -> float:
        return self.resent / self.sent if self.sent else 0.0

    def due(self, now: float) -> list[Data]:
        """Frames to send at ``now`` (resends first after a timeout); empty once failed."""
        if self.failed:
            return []
        if self.in_flight > 0 and self._timer is not None and now - self._timer > self.rtt.probe_timeout:
            self.rtt.expired()
            self.timeouts += 1
            self._probe(self.acked + 1, now)
        out = [self._send(seq, now) for seq in sorted(self._repeat) if self.acked < seq < self.next_seq]
        self._repeat.clear()
        limit = min(self.room_end, self.acked + self.max_window, self.total - 1)
        if self.hold_at is not None:
            limit = min(limit, self.hold_at)
        while not self.failed and self.next_seq <= limit:
            out.append(self._send(self.next_seq, now))
            self.next_seq += 1
        return out

    def on_ack(self, seq: int, free: int, now: float, timed: bool = True) -> bool:
        """``A seq free``; True if it acknowledged something new. Only an ``A`` is
        ``timed`` (a round-trip sample); an ``S`` or ``F`` may come long after."""
        self.room_end = max(self.room_end, seq + free)
        return self._advance(seq, now, timed)

    def on_status_ack(self, acc: int, free: int, now: float) -> bool:
        """The ``acc``/``free`` of an ``S`` frame: the same snapshot as an ``A``."""
        return self.on_ack(acc, free, now, timed=False)

    def on_nak(self, seq: int, now: float) -> None:
        """``N seq``: resend frame ``seq`` unless stale or a repeat. Not an acknowledgement:
        the main MCU answers for the USB hop before the CNC MCU has the frames below."""
        if seq <= self.acked or seq > self.high_sent:
            return
        last = self._repeated_at.get(seq)
        if last is not None and now - last < self.rtt.probe_timeout:
            return
        if self._count_retry(seq, now):
            self._repeat.add(seq)
            self._repeated_at[seq] = now
            self._timer = now

    def restart_at(self, seq: int, free: int) -> None:
        """Forget what was in flight: the machine has everything below ``seq`` (RESUME FROM)."""
        self.acked = self.high_sent = seq - 1
        self.next_seq = seq
        self._first_sent.clear()
        self._last_sent.clear()
        self._resent_seqs.clear()
        self.room_end = self.acked + free
        self._timer = None
        self._retries.clear()
        self._first_retry.clear()
        self._repeat.clear()
        self._repeated_at.clear()

    # ------------------------------------------------------------------ internals

    def _send(self, seq: int, now: float) -> Data:
        self._last_sent[seq] = now
        if seq in self._first_sent:
            self.resent += 1
            self._resent_seqs.add(seq)
        else:
            self._first_sent[seq] = now
        self.sent += 1
        self.high_sent = max(self.high_sent, seq)
        if self._timer is None:
            self._timer = now
        return Data(seq, self.lines[seq])

    def _advance(self, seq: int, now: float, timed: bool = True) -> bool:
        seq = min(seq, self.high_sent)
        if seq <= self.acked:
            return False
        latest = max((self._last_sent[s] for s in range(self.acked + 1, seq + 1) if s in self._last_sent),
                     default=None)
        if timed and latest is not None:  # from the last copy of what it covers: the one that completed it
            self.rtt.sample(now - latest)
        else:
            self.rtt.progressed()
        for old in range(self.acked + 1, seq + 1):
            self._last_sent.pop(old, None)
            self._first_sent.pop(old, None)
            self._resent_seqs.discard(old)
            self._retries.pop(old, None)
            self._first_retry.pop(old, None)
            self._repeated_at.pop(old, None)
        self.acked = seq
        self.next_seq = max(self.next_seq, seq + 1)
        self._timer = now if self.in_flight > 0 else None
        return True

    def _probe(self, seq: int, now: float) -> None:
        """A timeout: resend the first unacknowledged frame alone (the machine keeps the
        frames above a gap; its answer, ``A`` or ``N``, says what is still missing)."""
        if self._count_retry(seq, now):
            self._repeat.add(seq)
            self._repeated_at[seq] = now
            self._timer = now

    def _count_retry(self, seq: int, now: float = 0.0) -> bool:
        """One more resend of ``seq``; False (and ``failed`` set) past ``max_retries``
        resends that took at least ``MIN_FAIL_S`` since its first resend."""
        tries = self._retries.get(seq, 0) + 1
        self._retries[seq] = tries
        first = self._first_retry.setdefault(seq, now)  # not the first send: a frame deep in
        if tries > self.max_retries and now - first >= MIN_FAIL_S:  # the window waits its turn
            self.failed = msg("line {seq} was resent {count} times without an acknowledgement", seq=seq,
                              count=self.max_retries)
            return False
        return True
