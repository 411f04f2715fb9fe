"""Link health as Klipper shows its retransmit counter: the share of ``D`` frames sent
in the last minute that were resends (docs/protocol.md, "Errors and resends").

``ResendMeter.add(now, sent, resent)`` counts frames in one-second buckets;
``rate(now)``, ``sent(now)`` and ``resent(now)`` cover the last ``WINDOW_S``;
``warning(now)`` is on while the rate is over ``LIMIT`` with at least ``MIN_FRAMES``
frames sent. No clock of its own: the session passes its time.
"""

from __future__ import annotations

from collections import deque

WINDOW_S = 60
LIMIT = 0.10
MIN_FRAMES = 20


class ResendMeter:
    """Frames sent and resent per second over the last minute."""

    def __init__(self) -> None:
        self._buckets: deque[list[int]] = deque()  # [second, sent, resent]

    def add(self, now: float, sent: int, resent: int) -> None:
        if not sent and not resent:
            return
        second = int(now)
        if self._buckets and self._buckets[-1][0] == second:
            self._buckets[-1][1] += sent
            self._buckets[-1][2] += resent
        else:
            self._buckets.append([second, sent, resent])
        self._expire(now)

    def _expire(self, now: float) -> None:
        while self._buckets and self._buckets[0][0] <= int(now) - WINDOW_S:
            self._buckets.popleft()

    def sent(self, now: float) -> int:
        self._expire(now)
        return sum(b[1] for b in self._buckets)

    def resent(self, now: float) -> int:
        self._expire(now)
        return sum(b[2] for b in self._buckets)

    def rate(self, now: float) -> float:
        sent = self.sent(now)
        return self.resent(now) / sent if sent else 0.0

    def warning(self, now: float) -> bool:
        return self.sent(now) >= MIN_FRAMES and self.rate(now) > LIMIT

    def clear(self) -> None:
        self._buckets.clear()
