"""One stream of D frames (a job, a restarted job, or an SD upload) and its seq mapping.

A job streams the program's device lines with seq = program line index, and sends
nothing past a program stop line (``M00``, ``M01``, ``M06``) until the machine has
finished that line, so the lines after a stop wait on the computer, not in the
machine's queue (docs/protocol.md, "Program stops"). A job
restarted after a machine reset streams ``preamble + lines[start:]`` as a new JOB,
so stream seq ``s`` is program line ``s - len(preamble) + start`` (preamble lines map
to ``start - 1``). Progress is always reported in program line indices.
"""

from __future__ import annotations

import zlib
from bisect import bisect_right
from dataclasses import dataclass, field

from app.comm.events import ProgressEvent
from app.comm.rtt import RttEstimator
from app.comm.stops import is_stop_line
from app.comm.window import MAX_WINDOW, SendWindow


def sd_crc32(lines: list[str]) -> int:
    """CRC32 of the lines joined with ``\\n`` plus a final ``\\n`` (SD PUT)."""
    return zlib.crc32(("\n".join(lines) + "\n").encode("ascii"))


@dataclass
class Stream:
    """A stream in progress: its window, where it maps in the program, what is done."""

    kind: str
    window: SendWindow
    program_total: int
    start: int = 0
    preamble: int = 0
    name: str = ""
    boot: str = ""
    done: int = -1
    refused: int = -1  # program line of a D line the machine refused
    opener: int = 0  # id of the command that opens the stream on the machine (SD PUT)
    stops: list[int] = field(default_factory=list)  # stream seqs of the program stop lines

    @classmethod
    def job(cls, lines: list[str], rtt: RttEstimator, free: int, start: int = 0,
            preamble: list[str] | None = None, boot: str = "", max_window: int = MAX_WINDOW) -> Stream:
        """A job over ``lines[start:]`` preceded by ``preamble``."""
        pre = list(preamble or [])
        window = SendWindow(pre + list(lines[start:]), free=max(1, free), rtt=rtt, max_window=max_window)
        stream = cls("job", window, len(lines), start, len(pre), boot=boot,
                     stops=[seq for seq, line in enumerate(window.lines) if is_stop_line(line)])
        stream.hold_at_next_stop()
        return stream

    @classmethod
    def upload(cls, name: str, lines: list[str], rtt: RttEstimator) -> Stream:
        return cls("upload", SendWindow(list(lines), free=1, rtt=rtt), len(lines), name=name)

    def program_index(self, seq: int) -> int:
        """The program line of stream seq ``seq`` (``start - 1`` for preamble lines)."""
        return self.start - 1 if seq < self.preamble else seq - self.preamble + self.start

    def finish_line(self, seq: int) -> bool:
        """Lines up to ``seq`` finished; True if that is new."""
        seq = min(seq, self.window.total - 1)
        if seq <= self.done:
            return False
        self.done = seq
        self.hold_at_next_stop()
        return True

    def hold_at_next_stop(self) -> None:
        """Send up to the first stop line not yet finished, and nothing after it."""
        i = bisect_right(self.stops, self.done)
        self.window.hold_at = self.stops[i] if i < len(self.stops) else None

    @property
    def complete(self) -> bool:
        return self.done >= self.window.total - 1

    def progress(self) -> ProgressEvent:
        w = self.window
        done = self.done if self.kind == "job" else w.acked
        return ProgressEvent(
            self.kind, self.program_total, self.program_index(done), self.program_index(w.acked),
            self.program_index(w.high_sent), w.resent, w.resend_rate,
        )
