"""The main MCU's own care of the UART hop: a host stream's ``D`` frames (``DataRelay``)
and forwarded commands (``Reforward``).

docs/protocol.md, machine conventions: the main MCU keeps the ``D`` frames it relayed
until the CNC MCU acknowledges them (``A``), so the noisier hop is repaired on its
own round trip instead of the host's:

- ``resend(seq, now)``: a ``N seq`` of the CNC MCU for a kept frame: that frame again
  (at most every ``RESEND_GAP_S``: a queue-full ``N`` must not become a flood);
- ``probe(now)``: nothing acknowledged for ``PROBE_S`` while frames are kept: the first
  kept frame again (its answer, ``A`` or ``N``, says what else is missing);
- ``answer_for(seq)``: a host's resend of a frame the CNC MCU has already acknowledged
  is answered at once, as the CNC MCU would answer it, and the UART is spared: its
  last ``A``, and ``N`` for the first missing frame while frames are kept above a gap
  the host must fill (a probe's answer says what is missing).
"""

from __future__ import annotations

from app.comm.frame import Ack, Frame, Nak

RESEND_GAP_S = 0.02
PROBE_S = 0.02


class DataRelay:
    """Relayed, unacknowledged ``D`` frames of the current host stream."""

    def __init__(self) -> None:
        self.reset()

    def reset(self) -> None:
        """A new stream (``JOB``, ``RESUME FROM``): nothing kept, nothing acknowledged."""
        self.kept: dict[int, list] = {}  # seq -> [raw, last resent by the main MCU]
        self.acked = -1
        self.last_ack: Ack | None = None
        self.progress_at = 0.0
        self.gap_named_at = float("-inf")

    def relayed(self, seq: int, raw: bytes, now: float) -> None:
        if not self.kept:
            self.progress_at = now
        self.kept[seq] = [raw, float("-inf")]

    def on_ack(self, ack: Ack, now: float) -> None:
        self.last_ack = ack
        if ack.seq > self.acked:
            self.acked = ack.seq
            self.progress_at = now
            for seq in [s for s in self.kept if s <= ack.seq]:
                del self.kept[seq]

    def resend(self, seq: int, now: float) -> bytes | None:
        kept = self.kept.get(seq)
        if kept is None or now - kept[1] < RESEND_GAP_S:
            return None
        kept[1] = now
        return kept[0]

    def probe(self, now: float) -> bytes | None:
        if not self.kept or now - self.progress_at < PROBE_S:
            return None
        self.progress_at = now
        kept = self.kept[min(self.kept)]
        kept[1] = now
        return kept[0]

    def next_due(self) -> float | None:
        return self.progress_at + PROBE_S if self.kept else None

    def answer_for(self, seq: int, now: float) -> list[Frame]:
        """The frames that answer a host's copy of ``seq`` the CNC MCU already has (none:
        relay it); the gap is named once per burst of copies (``PROBE_S``)."""
        if seq > self.acked or seq in self.kept or self.last_ack is None:
            return []
        gap = self.kept and self.acked + 1 not in self.kept and now - self.gap_named_at >= PROBE_S
        if gap:
            self.gap_named_at = now
        return [self.last_ack] + ([Nak(self.acked + 1)] if gap else [])


REFORWARD_S = 0.05
REFORWARD_FOR_S = 0.5


class Reforward:
    """A forwarded host command sent down again every ``REFORWARD_S`` while the CNC MCU
    has not answered it, for ``REFORWARD_FOR_S`` (the CNC MCU deduplicates by id; the
    host's own retries go on after that)."""

    def __init__(self) -> None:
        self.command = None
        self._until = self._last = 0.0

    def start(self, command, now: float) -> None:
        self.command, self._until, self._last = command, now + REFORWARD_FOR_S, now

    def next_due(self, answered) -> float | None:
        """When it goes again (None: it does not); ``answered(command)`` ends it."""
        if self.command is None or answered(self.command) or self._last + REFORWARD_S > self._until:
            self.command = None
            return None
        return self._last + REFORWARD_S

    def take(self, now: float, answered):
        """The command to send again at ``now``, if due."""
        due = self.next_due(answered)
        if due is None or now < due - 1e-9:
            return None
        self._last = now
        return self.command
