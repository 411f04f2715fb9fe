"""Real-time commands (``R <id> <VERB>``), repeated until the machine answers them.

docs/protocol.md, "Real-time commands": the host writes each ``R`` frame twice back to
back, then once every ``REPEAT_S`` until its ``O``/``E`` arrives (or, for ``HOLD``, a
status in HOLD or ALARM: a stale IDLE or RUN status could predate it), and gives up
after ``GIVE_UP_S``. ``UrgentCommands.request(verb, now)`` queues one (a new id from the
session's command sequence; a request of a verb already waiting is that one); ``due(now)``
gives the frames to write now; ``on_answer(frame)`` and ``on_status(state)`` end them;
``expired(now)`` gives those that never got an answer. A ``STOP`` drops a waiting
``HOLD``/``RESUME`` and a ``HOLD`` a waiting ``RESUME`` (and the other way round): an
operator's later click is the one that counts.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from app.comm.frame import Error, Ok, RealtimeCommand

REPEAT_S = 0.01
FIRST_COPIES = 2
GIVE_UP_S = 5.0
CONFIRMS = {"HOLD": frozenset({"HOLD", "ALARM"})}
NAMES = {"HOLD": "feed hold", "RESUME": "resume", "STOP": "stop", "RESET": "reset"}
SUPERSEDES = {"STOP": ("HOLD", "RESUME"), "HOLD": ("RESUME",), "RESUME": ("HOLD",),
              "RESET": ("HOLD", "RESUME", "STOP")}


@dataclass
class Urgent:
    """One ``R`` frame waiting for its answer."""

    frame: RealtimeCommand
    first: float
    last: float | None = None


class UrgentCommands:
    """Pending ``R`` frames and their repeats (see the module docstring)."""

    def __init__(self, ids: Callable[[], int]) -> None:
        self.ids = ids
        self._pending: dict[str, Urgent] = {}

    def request(self, verb: str, now: float) -> RealtimeCommand:
        """Send ``R <id> verb`` at the next ``due`` and repeat it until answered."""
        for older in SUPERSEDES.get(verb, ()):
            self._pending.pop(older, None)
        if verb not in self._pending:
            self._pending[verb] = Urgent(RealtimeCommand(self.ids(), verb), now)
        return self._pending[verb].frame

    def pending(self, verb: str) -> bool:
        return verb in self._pending

    def due(self, now: float) -> list[RealtimeCommand]:
        """The frames to write at ``now`` (two copies the first time)."""
        out = []
        for urgent in self._pending.values():
            if urgent.last is None:
                urgent.last = now
                out += [urgent.frame] * FIRST_COPIES
            elif now - urgent.last >= REPEAT_S - 1e-9:
                urgent.last = now
                out.append(urgent.frame)
        return out

    def on_answer(self, frame: Ok | Error) -> RealtimeCommand | None:
        """An ``O``/``E``: the ``R`` frame it answers (no longer repeated), else None."""
        for verb, urgent in self._pending.items():
            if urgent.frame.id == frame.id:
                del self._pending[verb]
                return urgent.frame
        return None

    def on_status(self, machine_state: str) -> list[RealtimeCommand]:
        """A status in ``machine_state``: the ``R`` frames it shows took effect (dropped)."""
        done = [u.frame for verb, u in self._pending.items() if machine_state in CONFIRMS.get(verb, ())]
        for frame in done:
            del self._pending[frame.verb]
        return done

    def expired(self, now: float) -> list[RealtimeCommand]:
        """Drop and return the frames unanswered for ``GIVE_UP_S``."""
        gone = [u.frame for u in self._pending.values() if now - u.first > GIVE_UP_S]
        for frame in gone:
            del self._pending[frame.verb]
        return gone

    def clear(self) -> None:
        self._pending.clear()
