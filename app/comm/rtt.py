"""Adaptive retransmission timeout (Jacobson/Karels, RFC 6298) as docs/protocol.md fixes it.

``timeout`` is ``max(30 ms, srtt + 4 rttvar)``, doubled after each expiry up to
2 s, and back to the computed value once a fresh sample arrives; ``probe_timeout``
(2 x the fastest round trip, within 15 ms..``timeout``) paces single-frame resends. Only frames sent
once give samples (Karn's rule), which the caller enforces.
"""

from __future__ import annotations

from dataclasses import dataclass

MIN_TIMEOUT = 0.03
MIN_PROBE_TIMEOUT = 0.015
MAX_TIMEOUT = 2.0
INITIAL_TIMEOUT = 0.5
ALPHA = 1 / 8
BETA = 1 / 4


@dataclass
class RttEstimator:
    """Smoothed round-trip time and the resend timeout derived from it."""

    srtt: float | None = None
    rttvar: float = 0.0
    backoffs: int = 0
    min_rtt: float | None = None

    def sample(self, rtt: float) -> None:
        """Fold one measured round trip (seconds) in and clear the backoff."""
        rtt = max(0.0, rtt)
        self.min_rtt = rtt if self.min_rtt is None else min(self.min_rtt, rtt)
        if self.srtt is None:
            self.srtt, self.rttvar = rtt, rtt / 2
        else:
            self.rttvar = (1 - BETA) * self.rttvar + BETA * abs(self.srtt - rtt)
            self.srtt = (1 - ALPHA) * self.srtt + ALPHA * rtt
        self.backoffs = 0

    def base_timeout(self) -> float:
        """``max(100 ms, srtt + 4 rttvar)``, or 0.5 s before the first sample."""
        if self.srtt is None:
            return INITIAL_TIMEOUT
        return max(MIN_TIMEOUT, self.srtt + 4 * self.rttvar)

    @property
    def timeout(self) -> float:
        """The current timeout: the base doubled once per expiry, at most 2 s."""
        return min(MAX_TIMEOUT, self.base_timeout() * (2**self.backoffs))

    @property
    def probe_timeout(self) -> float:
        """The wait before resending one frame alone: 2 x the fastest round trip seen
        (at least ``MIN_PROBE_TIMEOUT``), never more than ``timeout``. Cheap to get wrong (one
        frame), costly to get long (the stream waits): noisy links inflate ``srtt``."""
        if self.min_rtt is None:
            return self.timeout
        return min(self.timeout, max(MIN_PROBE_TIMEOUT, 2 * self.min_rtt))

    def expired(self) -> None:
        """A timeout fired: double the next one (capped at 2 s)."""
        if self.timeout < MAX_TIMEOUT:
            self.backoffs += 1

    def progressed(self) -> None:
        """New data was acknowledged: the backoff ends even without a clean sample."""
        self.backoffs = 0
