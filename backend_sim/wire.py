"""One direction of one hop: when each written byte lands at the far end.

Bytes leave back to back: a write at time ``t`` on an idle wire lands its first byte
at ``t + latency + byte_time`` and each further byte ``byte_time`` later; a write on a
busy wire queues behind the bytes already waiting (a UART TX buffer). Delivery is
event driven: ``next_time()`` is when the next byte that matters (a newline, or the
last byte waiting) lands, and ``take(now)`` returns every byte landed by ``now``.
Nothing is ticked per bit or per byte.

A TX queue with two fast lanes, never cutting a frame in two: ``write_urgent`` puts
whole frames (``R`` real-time commands) behind the frame being shifted out and earlier
urgent frames, ahead of everything else; ``write_priority`` puts whole frames (resent
``D`` frames) behind those and earlier priority frames, ahead of the frames queued by
``write``. ``cut`` models an unplugged cable: bytes written are lost.

The UART between the MCUs runs at 115200 8N1 (10 bits per byte); the USB CDC hop to
the host is fast but not instant (``USB_LATENCY``, about 1 MB/s).
"""

from __future__ import annotations

import heapq
import math
import re

from backend_sim.faults import ChannelFaults

UART_BITS_PER_BYTE = 10
USB_LATENCY = 0.0005
USB_BYTE_TIME = 1e-6
_EVENT = re.compile(rb"\n")


def uart_byte_time(baud: int) -> float:
    """Seconds one byte takes on an 8N1 UART: 10 bits."""
    return UART_BITS_PER_BYTE / baud


def to_ms(t: float) -> int:
    """The first whole simulated ms at or after ``t`` seconds."""
    return math.ceil(t * 1000 - 1e-6)


class Wire:
    """Bytes in flight in one direction, with their landing times and faults."""

    def __init__(self, name: str, byte_time: float, latency: float = 0.0, seed: int = 0) -> None:
        self.name = name
        self.byte_time = byte_time
        self.latency = latency
        self.faults = ChannelFaults(name, seed)
        self.cut = False
        self.sent = 0
        self._pending = bytearray()
        self._t_first = 0.0
        self._delayed: list[tuple[float, int, bytes]] = []
        self._order = 0
        self._taken = 0  # bytes landed and taken so far (positions below are counted from it)
        self._urgent_end = 0  # where the urgent lane ends, in bytes since the wire started
        self._lane_end = 0  # where the priority lane ends (never before the urgent lane's end)

    def write(self, data: bytes, now: float) -> None:
        for piece in self._through_faults(data, now):
            self._queue(piece, now)

    def _through_faults(self, data: bytes, now: float):
        """The pieces of ``data`` to send now, after the wire's faults; a delayed piece is
        kept for later. Nothing while the wire is cut."""
        if self.cut or not data:
            return
        self.sent += len(data)
        for delay, piece in self.faults.process(bytes(data)):
            if delay > 0:
                self._order += 1
                heapq.heappush(self._delayed, (now + delay, self._order, piece))
            else:
                yield piece

    def write_priority(self, data: bytes, now: float) -> None:
        """Send whole frames ahead of the frames queued by ``write`` (behind the frame
        being shifted out, the urgent frames and earlier priority frames)."""
        for piece in self._through_faults(data, now):
            index = self._lane_index(self._lane_end, now)
            self._insert(index, piece, now)
            self._lane_end = self._taken + index + len(piece)

    def write_urgent(self, data: bytes, now: float) -> None:
        """Send whole frames ahead of every queued frame (behind the frame being shifted
        out and earlier urgent frames)."""
        for piece in self._through_faults(data, now):
            index = self._lane_index(self._urgent_end, now)
            self._insert(index, piece, now)
            self._urgent_end = self._taken + index + len(piece)
            self._lane_end = max(self._lane_end + len(piece), self._urgent_end)

    def _lane_index(self, lane_end: int, now: float) -> int:
        """Where a frame joins a lane ending at ``lane_end``: there, or behind the frame
        being shifted out if that ends later."""
        if not self._pending:
            return 0
        index = max(0, lane_end - self._taken)
        shifted = self._count(now)
        if index <= shifted:
            index = self._pending.find(b"\n", shifted) + 1 or len(self._pending)
        return min(index, len(self._pending))

    def _insert(self, index: int, piece: bytes, now: float) -> None:
        if not self._pending:
            self._queue(piece, now)
        else:
            self._pending[index:index] = piece

    def take(self, now: float) -> bytes:
        """Every byte landed by ``now`` (seconds), in order."""
        if not (self._pending and now >= self._t_first - 1e-12) and not (
                self._delayed and self._delayed[0][0] <= now):
            return b""
        out = self._landed(now)
        while self._delayed and self._delayed[0][0] <= now:
            t, _, piece = heapq.heappop(self._delayed)
            self._queue(piece, t)
            out += self._landed(now)
        return bytes(out)

    def next_time(self) -> float | None:
        """When the next newline, real-time byte or last waiting byte lands."""
        if not self._pending and not self._delayed:
            return None
        times = []
        if self._pending:
            match = _EVENT.search(self._pending)
            index = match.start() if match else len(self._pending) - 1
            times.append(self._t_first + index * self.byte_time)
        if self._delayed:
            times.append(self._delayed[0][0])
        return min(times) if times else None

    def clear(self) -> None:
        self._pending.clear()
        self._delayed.clear()
        self._lane_end = self._urgent_end = self._taken  # no lane frame waits any more

    def set_cut(self, cut: bool) -> None:
        self.cut = cut
        if cut:
            self.clear()

    @property
    def in_flight(self) -> int:
        return len(self._pending) + sum(len(p) for _, _, p in self._delayed)

    def _queue(self, data: bytes, now: float) -> None:
        if not self._pending:
            self._t_first = now + self.latency + self.byte_time
        self._pending += data

    def _count(self, now: float) -> int:
        if not self._pending or now < self._t_first - 1e-12:
            return 0
        return min(len(self._pending), int((now - self._t_first) / self.byte_time + 1e-6) + 1)

    def _landed(self, now: float) -> bytearray:
        count = self._count(now)
        if not count:
            return bytearray()
        out = self._pending[:count]
        del self._pending[:count]
        self._taken += count
        self._t_first += count * self.byte_time
        return out
