"""Incremental deframing of the byte stream into frames (docs/protocol.md, "Frames").

``Deframer.feed(chunk, now)`` accepts chunks split anywhere and returns, in order, the
decoded ``Frame`` objects, ``Dropped`` lines (with the reason, for the log and for
``N``) and, on the machine's side, ``Legacy`` items: a ``!`` or 0x18 that began a line,
taken off it and counted, never a command (docs/protocol.md, "Real-time commands").
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from app.comm.frame import LEGACY_BYTES, MAX_FRAME, PARTIAL_TIMEOUT, Frame, FrameError, decode

_FRAME_START = re.compile(rb"[A-Z] ")


@dataclass
class DeframerStats:
    """Counts of what a Deframer dropped, by reason."""

    frames: int = 0
    bad: int = 0
    overlength: int = 0
    timeouts: int = 0
    legacy: int = 0
    resynced: int = 0  # frames found at the end of a line that began with noise


@dataclass(frozen=True)
class Dropped:
    """A line that was not a valid frame; ``reason`` says why (for the log and for ``N``)."""

    reason: str
    raw: bytes


@dataclass(frozen=True)
class Legacy:
    """A ``!`` or 0x18 that began a line: taken off it, counted, never acted on."""

    byte: bytes


@dataclass
class Deframer:
    """Incremental deframer: ``feed(chunk, now)`` -> list of Frame | Dropped | Legacy.

    Chunks may split frames anywhere. ``\\r`` is ignored. A line over 96 bytes is
    dropped (once, when its newline arrives); a partial line with no newline for
    ``PARTIAL_TIMEOUT`` seconds is dropped. With ``legacy=True`` (the machine's
    side) a ``!`` or 0x18 that begins a line (nothing of it buffered) is taken off and
    reported as ``Legacy``; anywhere else it is a byte of the line like any other.
    A line that is no frame is searched for one at its end (``resync``): the longest
    tail that starts with a kind letter and a space and checks out (CRC and grammar)
    is taken, so noise glued in front of a frame costs nothing but its own bytes;
    an over-length line keeps its last 96 bytes for that search.
    """

    legacy: bool = False
    stats: DeframerStats = field(default_factory=DeframerStats)
    _buf: bytearray = field(default_factory=bytearray)
    _started: float | None = None
    _overlong: bool = False

    def feed(self, chunk: bytes, now: float) -> list[Frame | Dropped | Legacy]:
        out: list[Frame | Dropped | Legacy] = self.poll(now)
        parts = chunk.split(b"\n")
        for line in parts[:-1]:
            if self._buf or self._overlong:
                self._append(line, now)
                out.append(self._finish())
            else:
                self._whole(self._take_legacy(line, out), out)
        line = parts[-1]
        if not (self._buf or self._overlong):
            line = self._take_legacy(line, out)
        self._append(line, now)
        return out

    def _whole(self, line: bytes, out: list) -> None:
        """A complete line with nothing buffered before it (the common case, no copy)."""
        if b"\r" in line:
            line = line.replace(b"\r", b"")
        if line:
            out.append(self._classify(line[-MAX_FRAME:], len(line) >= MAX_FRAME))

    def poll(self, now: float) -> list[Frame | Dropped | Legacy]:
        """Drop a partial frame that has waited too long for its newline."""
        if self._started is not None and now - self._started > PARTIAL_TIMEOUT:
            raw = bytes(self._buf)
            self._reset()
            self.stats.timeouts += 1
            return [Dropped("partial frame timed out", raw)]
        return []

    def pending(self) -> int:
        """Bytes of a partial frame waiting for its newline."""
        return len(self._buf)

    def _take_legacy(self, line: bytes, out: list) -> bytes:
        """Take the legacy bytes off the start of a line (machine side only)."""
        if not self.legacy:
            return line
        start = 0
        while start < len(line) and line[start] in LEGACY_BYTES:
            out.append(Legacy(line[start:start + 1]))
            start += 1
        self.stats.legacy += start
        return line[start:] if start else line

    def _append(self, data: bytes, now: float) -> None:
        data = data.replace(b"\r", b"")
        if not data:
            return
        if self._started is None:
            self._started = now
        self._buf += data
        if len(self._buf) >= MAX_FRAME:  # keep the tail: a frame may still end it
            self._overlong = True
            del self._buf[:-MAX_FRAME]

    def _finish(self) -> Frame | Dropped:
        raw, overlong = bytes(self._buf), self._overlong
        self._reset()
        return self._classify(raw, overlong)

    def _classify(self, raw: bytes, overlong: bool) -> Frame | Dropped:
        """Decode one complete line (or a frame at its end), counting what is dropped and why."""
        reason = "over-length frame"
        if not overlong:
            try:
                frame = decode(raw)
            except FrameError as exc:
                reason = str(exc)
            else:
                self.stats.frames += 1
                return frame
        frame = self._resync(raw)
        if frame is not None:
            self.stats.frames += 1
            self.stats.resynced += 1
            return frame
        if overlong:
            self.stats.overlength += 1
        else:
            self.stats.bad += 1
        return Dropped(reason, raw)

    @staticmethod
    def _resync(raw: bytes) -> Frame | None:
        """The frame that ends ``raw`` after bytes of noise, if one checks out."""
        if b"*" not in raw[-6:]:  # no CRC field at the end: nothing to find
            return None
        for match in _FRAME_START.finditer(raw, 1):
            try:
                return decode(raw[match.start():])
            except FrameError:
                continue
        return None

    def _reset(self) -> None:
        self._buf = bytearray()
        self._started = None
        self._overlong = False
