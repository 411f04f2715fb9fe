"""The receiving end of a ``D`` stream: expected seq, acks, gaps (docs/protocol.md).

``JobStream.offer(seq)`` decides what to do with an arriving ``D`` frame, without
side effects on the caller's queue: ``QUEUE`` (seq == expected), ``REACK``
(a duplicate), ``NAK`` (a gap, first of its bad stretch), ``QUIET`` (a gap inside a
stretch already answered). ``bad_frame()`` is the same for a frame that failed its
CRC. Used by the CNC MCU for jobs and by the main MCU for SD uploads.

Selective repeat (docs/protocol.md): a frame above a gap is not thrown away but kept
(``keep``, within ``room`` seqs of ``expected``); once the gap is filled the caller
takes the kept frames in order (``take``) and, if another gap remains
(``gap_remains``), answers ``N`` for it at once.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field


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

    def start(self, total: int) -> None:
        self.total, self.expected, self.acc, self.done = total, 0, -1, -1
        self.open, self.bad_stretch = True, False
        self.ahead.clear()

    def close(self) -> None:
        self.open = False
        self.bad_stretch = False
        self.ahead.clear()

    def keep(self, seq: int, line: str, room: int) -> None:
        """Keep a frame above the gap (``expected < seq < expected + room``) for later."""
        if self.expected < seq < min(self.expected + max(room, 1), self.total):
            self.ahead.setdefault(seq, line)

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
        if seq > self.expected:
            return self._nak()
        return Verdict.QUEUE

    def bad_frame(self) -> Verdict:
        return self._nak()

    def accepted(self, seq: int) -> None:
        self.expected = seq + 1
        self.acc = seq
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
