"""Real-time bytes (``!`` feed hold, 0x18 stop and flush), repeated until confirmed.

docs/protocol.md: the host repeats a real-time byte every 100 ms until the status
shows the hold or stop. ``RealtimeRepeater.due(now)`` gives the bytes to write now;
``confirm(state)`` takes the state of every ``S`` frame received after the first send.
A byte not confirmed within ``give_up_s`` is reported by ``expired`` and dropped.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.comm.frame import FEED_HOLD, STOP_FLUSH

REPEAT_S = 0.1
GIVE_UP_S = 5.0
CONFIRMS = {FEED_HOLD: frozenset({"HOLD", "IDLE", "ALARM"}), STOP_FLUSH: frozenset({"IDLE", "ALARM"})}
NAMES = {FEED_HOLD: "feed hold", STOP_FLUSH: "stop"}


@dataclass
class RealtimeRepeater:
    """Pending real-time bytes with their first and last send times."""

    repeat_s: float = REPEAT_S
    give_up_s: float = GIVE_UP_S
    _pending: dict[bytes, list[float]] = field(default_factory=dict)

    def request(self, byte: bytes, now: float) -> None:
        """Send ``byte`` at the next ``due`` and repeat it until confirmed."""
        if byte not in self._pending:
            self._pending[byte] = [now, now - self.repeat_s]
        if byte == STOP_FLUSH:
            self._pending.pop(FEED_HOLD, None)

    def pending(self, byte: bytes) -> bool:
        return byte in self._pending

    def due(self, now: float) -> bytes:
        """The bytes to write at ``now`` (empty if none)."""
        out = b""
        for byte, times in self._pending.items():
            if now - times[1] >= self.repeat_s - 1e-9:
                times[1] = now
                out += byte
        return out

    def confirm(self, machine_state: str) -> list[bytes]:
        """A status with ``machine_state`` arrived: drop and return the bytes it confirms."""
        done = [b for b in self._pending if machine_state in CONFIRMS[b]]
        for byte in done:
            del self._pending[byte]
        return done

    def expired(self, now: float) -> list[bytes]:
        """Drop and return the bytes unconfirmed for ``give_up_s``."""
        gone = [b for b, (first, _) in self._pending.items() if now - first > self.give_up_s]
        for byte in gone:
            del self._pending[byte]
        return gone

    def clear(self) -> None:
        self._pending.clear()
