"""Real-time commands (``R`` frames) on the machine's side (docs/protocol.md, "Real-time
commands"), and the legacy bytes that are no longer commands.

- ``RecentIds``: what one MCU remembers of the last ``REMEMBERED`` ``R`` frames it took
  (their ids and the answers sent), so a repeat is answered again, never carried out
  again; kept apart from the remembered ``C`` id.
- ``UrgentRelay``: the main MCU's ``R`` frames on their way down the UART (the host's,
  and its own): each is sent again every ``REPEAT_S`` until the CNC MCU answers it, for
  at most ``GIVE_UP_S``; ``due(now)`` gives the copies to send now.
- ``LegacyCounter``: ``!``/0x18 taken off the start of a line, counted and reported in
  one ``L`` frame per ``LOG_EVERY_S`` at most; never acted on.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass

from app.comm.frame import Log, RealtimeCommand

REMEMBERED = 16
REPEAT_S = 0.005
GIVE_UP_S = 1.0
LOG_EVERY_S = 1.0


class RecentIds:
    """The ids of the last ``REMEMBERED`` R frames taken, each with its answers (encoded)."""

    def __init__(self) -> None:
        self._answers: OrderedDict[int, list[bytes]] = OrderedDict()

    def remembers(self, rid: int) -> bool:
        return rid in self._answers

    def start(self, rid: int) -> None:
        """``rid`` is taken now: remember it (forgetting the oldest beyond ``REMEMBERED``)."""
        self._answers[rid] = []
        while len(self._answers) > REMEMBERED:
            self._answers.popitem(last=False)

    def record(self, rid: int | None, raw: bytes) -> bool:
        """Keep the answer ``raw`` of a remembered id; False if ``rid`` is none of them."""
        if rid is None or rid not in self._answers:
            return False
        self._answers[rid].append(raw)
        return True

    def answers(self, rid: int) -> list[bytes]:
        return list(self._answers.get(rid, ()))


@dataclass
class _Forwarding:
    raw: bytes
    first: float
    last: float


class UrgentRelay:
    """R frames the main MCU forwards down the UART until the CNC MCU answers them."""

    def __init__(self) -> None:
        self.recent = RecentIds()
        self._waiting: dict[int, _Forwarding] = {}

    def forwarding(self, rid: int) -> bool:
        """True while ``rid`` is sent again and again, unanswered."""
        return rid in self._waiting

    def forward(self, frame: RealtimeCommand, raw: bytes, now: float) -> None:
        """``frame`` goes down now (the caller writes ``raw``) and again until answered."""
        self.recent.start(frame.id)
        self._waiting[frame.id] = _Forwarding(raw, now, now)

    def answered(self, rid: int | None, raw: bytes) -> bool:
        """An ``O``/``E`` from the CNC MCU: True if it answers an R frame (kept for repeats)."""
        if not self.recent.record(rid, raw):
            return False
        self._waiting.pop(rid, None)
        return True

    def due(self, now: float) -> list[bytes]:
        """The copies to send again at ``now``; frames unanswered for ``GIVE_UP_S`` are dropped."""
        out = []
        for rid, item in list(self._waiting.items()):
            if now - item.first > GIVE_UP_S:
                del self._waiting[rid]
            elif now - item.last >= REPEAT_S - 1e-9:
                item.last = now
                out.append(item.raw)
        return out

    def next_due(self) -> float | None:
        """When the next copy is due (None: nothing waits for an answer)."""
        return min((item.last + REPEAT_S for item in self._waiting.values()), default=None)

    def clear(self) -> None:
        self._waiting.clear()


class LegacyCounter:
    """Counts ignored ``!``/0x18 and says so at most once per ``LOG_EVERY_S``."""

    def __init__(self) -> None:
        self.total = 0
        self._unsaid = 0
        self._said_at = float("-inf")

    def seen(self, count: int = 1) -> None:
        self.total += count
        self._unsaid += count

    def report(self, now: float) -> Log | None:
        """The ``L`` frame to send now, if any came since the last one and it is time."""
        if not self._unsaid or now - self._said_at < LOG_EVERY_S:
            return None
        count, self._unsaid, self._said_at = self._unsaid, 0, now
        return Log(f"ignored {count} real-time byte(s) (use R frames)")

    def next_due(self) -> float | None:
        """When the next ``L`` may go (0.0: at once), None while nothing is unsaid."""
        if not self._unsaid:
            return None
        return max(0.0, self._said_at + LOG_EVERY_S)
