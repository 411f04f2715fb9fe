"""The receiving end of a ``D`` stream: expected seq, acks, gaps (docs/protocol.md).

``JobStream.offer(seq)`` decides what to do with an arriving ``D`` frame, without
side effects on the caller's queue: ``QUEUE`` (seq == expected), ``REACK``
(a duplicate), ``NAK`` (a gap, first of its bad stretch), ``QUIET`` (a gap inside a
stretch already answered). ``bad_frame()`` is the same for a frame that failed its
CRC. Used by the CNC MCU for jobs and by the main MCU for SD uploads.

Selective repeat (docs/protocol.md): a frame above a gap is not thrown away but kept
(``keep``, within ``room`` seqs of ``expected``); once the gap is filled the caller
takes the kept frames in order (``take``) and, if another gap remains
(``gap_remains``), answers ``N`` for it at once. Every seq seen missing is named as
soon as it is seen: ``keep`` returns the seqs of a new hole below the kept frame
(answer ``N`` for each), and a duplicate that arrives while frames are kept above a
gap is answered ``N expected`` as well as ``A`` (``after_duplicate``: once per burst of
duplicates, so a go-back-N host's rewind gets one ``N``, not one per frame).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

MAX_HOLE_NAKS = 4  # N frames for one newly seen hole (the rest follow as it is filled)


class Verdict(enum.Enum):
    QUEUE = "queue"
    REACK = "reack"
    NAK = "nak"
    QUIET = "quiet"


@dataclass
class JobStream:
    """Counters of one stream: ``total`` lines, ``expected`` next seq, last ``acc``/``done``."""

    total: int = 0
    expected: int = 0
    acc: int = -1
    done: int = -1
    open: bool = False
    bad_stretch: bool = False
    ahead: dict[int, str] = field(default_factory=dict)
    high: int = -1  # the highest seq seen: queued or kept
    probe_answered: bool = False  # a duplicate of this burst was answered N expected

    def start(self, total: int) -> None:
        self.total, self.expected, self.acc, self.done = total, 0, -1, -1
        self.open, self.bad_stretch = True, False
        self.high, self.probe_answered = -1, False
        self.ahead.clear()

    def close(self) -> None:
        self.open = False
        self.bad_stretch = False
        self.ahead.clear()

    def keep(self, seq: int, line: str, room: int) -> list[int]:
        """Keep a frame above the gap (``expected < seq < expected + room``) for later;
        return the seqs seen missing for the first time (between the highest frame seen
        and this one, ``expected`` excepted: ``offer`` names it), at most ``MAX_HOLE_NAKS``."""
        if not self.expected < seq < min(self.expected + max(room, 1), self.total):
            return []
        self.ahead.setdefault(seq, line)
        new = range(max(self.high + 1, self.expected + 1), seq)
        self.high = max(self.high, seq)
        return list(new[:MAX_HOLE_NAKS])

    def after_duplicate(self) -> int | None:
        """A duplicate was re-acknowledged: the seq to answer ``N`` for too (the first
        of a burst while frames are kept above a gap: a host's probe), else None."""
        if self.probe_answered or not any(s > self.expected for s in self.ahead):
            return None
        self.probe_answered = True
        return self.expected

    def take(self) -> tuple[int, str] | None:
        """The kept frame that is next (seq ``expected``), if there is one."""
        line = self.ahead.pop(self.expected, None)
        return None if line is None else (self.expected, line)

    def gap_remains(self) -> bool:
        """After taking what fits: frames are kept above a new gap (answer ``N expected``)."""
        for seq in [s for s in self.ahead if s < self.expected]:
            del self.ahead[seq]
        if self.ahead:
            self.bad_stretch = True
            return True
        return False

    def offer(self, seq: int) -> Verdict:
        if seq < self.expected:
            return Verdict.REACK
        self.probe_answered = False
        if seq > self.expected:
            return self._nak()
        return Verdict.QUEUE

    def bad_frame(self) -> Verdict:
        return self._nak()

    def accepted(self, seq: int) -> None:
        self.expected = seq + 1
        self.acc = seq
        self.high = max(self.high, seq)
        self.bad_stretch = False

    def finished(self, seq: int) -> bool:
        """Record lines up to ``seq`` done; True when that was the last line."""
        self.done = max(self.done, seq)
        return self.total > 0 and self.done >= self.total - 1

    @property
    def complete(self) -> bool:
        return self.acc >= self.total - 1

    def _nak(self) -> Verdict:
        if self.bad_stretch:
            return Verdict.QUIET
        self.bad_stretch = True
        return Verdict.NAK
