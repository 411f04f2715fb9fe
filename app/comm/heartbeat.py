"""Link health from the time since the last valid frame (docs/protocol.md, heartbeat).

``LinkMonitor`` is told when a valid frame arrived (``heard``) and asked, as time
passes, for the link state: CONNECTED, DEGRADED after 2 s of silence, LOST after
3 s. It also says when the next ``PING`` is due (every 0.25 s; every 0.02 s once
nothing valid has come for half a second). Garbled lines are
never a sign of life: only the session's valid frames reach ``heard``.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass


class LinkState(enum.Enum):
    DISCONNECTED = "DISCONNECTED"
    CONNECTED = "CONNECTED"
    DEGRADED = "DEGRADED"
    LOST = "LOST"


@dataclass
class LinkMonitor:
    """Silence timer and heartbeat schedule of one connection."""

    heartbeat_s: float = 1.0
    degraded_s: float = 2.0
    lost_s: float = 3.0
    state: LinkState = LinkState.DISCONNECTED
    last_heard: float = 0.0
    last_ping: float | None = None

    def attach(self, now: float) -> None:
        """A transport was opened: the silence timer starts now."""
        self.last_heard = now
        self.last_ping = None
        self.state = LinkState.CONNECTED

    def detach(self) -> None:
        self.state = LinkState.DISCONNECTED

    def heard(self, now: float) -> None:
        self.last_heard = now

    def excuse(self, seconds: float) -> None:
        """The host read nothing for ``seconds`` (busy preparing a job): that time is not
        the machine's silence. A link already lost stays lost."""
        if self.state is not LinkState.LOST:
            self.last_heard += max(0.0, seconds)

    def silent_for(self, now: float) -> float:
        return max(0.0, now - self.last_heard)

    def update(self, now: float) -> bool:
        """Recompute the state at ``now``; True if it changed."""
        if self.state is LinkState.DISCONNECTED:
            return False
        silent = self.silent_for(now)
        if silent >= self.lost_s:
            new = LinkState.LOST
        elif silent >= self.degraded_s:
            new = LinkState.DEGRADED
        else:
            new = LinkState.CONNECTED
        changed, self.state = new is not self.state, new
        return changed

    def ping_due(self, now: float) -> bool:
        """Every ``heartbeat_s / 4`` (0.25 s): on a noisy link a ping and its answer are
        often lost, and the machine must not miss three seconds of them (host lost);
        every ``heartbeat_s / 50`` once nothing valid has come for ``heartbeat_s / 2``
        (ask again and again before calling the link degraded or lost: at 3 % bad bytes
        one ping in ten comes back, and the main MCU answers it itself)."""
        if self.state is LinkState.DISCONNECTED:
            return False
        silent = self.silent_for(now) >= self.heartbeat_s / 2
        period = self.heartbeat_s / (50 if silent else 4)
        return self.last_ping is None or now - self.last_ping >= period - 1e-9

    def pinged(self, now: float) -> None:
        """Any command frame sent counts as the heartbeat of its second."""
        self.last_ping = now
