"""Command ids, one command in flight at a time, same-id retries and timeouts.

docs/protocol.md: ``C <id> <VERB> [args]``; a repeated id (the same as the last one)
is not executed again. The machine only remembers the *last* id, so the host keeps
exactly one command outstanding and retries it with the same id until ``O``/``E``
arrives (every ``RETRY_S``: on a noisy link each try may be lost, so no back-off);
other commands wait in a FIFO. The
heartbeat ``PING`` goes out every 0.25 s besides (``PING``/``STATUS`` ids are never
remembered by the machine). ``PING`` and ``STATUS`` are answered by
an ``S`` frame. A command unanswered by its verb's deadline ends with ``TIMEOUT``.
Urgent commands (``STOP``) supersede the outstanding one.

Ids come from one sequence for the whole process (``next_command_id``): every queue,
session and reconnect takes the next, and the sequence starts at a random point below
``ID_START_MAX`` (one in a million that a new run meets the id a machine remembers; ids
stay short, so a command frame stays short on a noisy link). So a machine that still
remembers the last id of an earlier session (or of an earlier run of the program) never
takes a new command for a retry of it. A test or a benchmark may give a queue its own
sequence (``ids``) to be repeatable.
"""

from __future__ import annotations

import itertools
import random
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field

from app.comm.events import CommandResult
from app.comm.frame import Command, Error, Info, Ok

RETRY_S = 0.25
MAX_RETRY_S = RETRY_S
DEFAULT_DEADLINE = 10.0  # at 3 % bad bytes a try crosses both ways one time in four: 40 tries
DEADLINES = {
    "HOME": 240.0, "JOG": 600.0, "PAUSE": 120.0, "STOP": 60.0, "SD": 60.0,
    "RESET": 10.0, "RESUME": 10.0, "JOB": 10.0,
}
STATUS_VERBS = frozenset({"PING", "STATUS"})
ID_START_MAX = 1_000_000  # ids from 1,000,000,000 are the main MCU's own (docs/protocol.md)
_IDS = itertools.count(random.SystemRandom().randrange(1, ID_START_MAX))


def next_command_id() -> int:
    """The next command id of this process (see the module docstring)."""
    return next(_IDS)


@dataclass
class Pending:
    """One command on the wire."""

    frame: Command
    deadline: float
    first_sent: float = 0.0
    last_sent: float = 0.0
    interval: float = RETRY_S
    tries: int = 0
    rows: list[str] = field(default_factory=list)
    acknowledged: bool = False

    @property
    def id(self) -> int:
        return self.frame.id


def deadline_for(verb: str, args: tuple[str, ...]) -> float | None:
    """Seconds a verb may take; None for ``SD PUT`` (it answers when the upload ends)."""
    if verb == "SD" and args[:1] == ("PUT",):
        return None
    return DEADLINES.get(verb, DEFAULT_DEADLINE)


@dataclass
class CommandQueue:
    """Assigns ids, sends one command at a time, matches answers, retries, times out."""

    outstanding: Pending | None = None
    waiting: deque[Command] = field(default_factory=deque)
    ids: Callable[[], int] = next_command_id  # where ids come from (the process's sequence)
    _next: int | None = None

    @property
    def next_id(self) -> int:
        """The id the next command of this queue will get (taken from the sequence now)."""
        if self._next is None:
            self._next = self.ids()
        return self._next

    def take_id(self) -> int:
        """The next id of this queue's sequence, for a frame sent outside it (an ``R``)."""
        cid, self._next = self.next_id, None
        return cid

    _take_id = take_id

    def submit(self, verb: str, args: tuple[str, ...] = (), urgent: bool = False) -> Command:
        """Queue a command and return its frame (with its id)."""
        command = Command(self._take_id(), verb, tuple(str(a) for a in args))
        if urgent:
            self.waiting.appendleft(command)
        else:
            self.waiting.append(command)
        return command

    def supersede(self) -> Pending | None:
        """Drop the outstanding command (an urgent one goes next); return it."""
        dropped, self.outstanding = self.outstanding, None
        return dropped

    def is_waiting(self, command_id: int) -> bool:
        """True while command ``command_id`` is queued and not yet sent."""
        return any(command.id == command_id for command in self.waiting)

    def idle(self) -> bool:
        return self.outstanding is None and not self.waiting

    def due(self, now: float) -> tuple[list[Command], list[CommandResult]]:
        """Frames to send at ``now`` and the commands that timed out."""
        timed_out = []
        pending = self.outstanding
        if pending is not None and pending.deadline and now - pending.first_sent > pending.deadline:
            timed_out.append(_result(pending, ok=False, code="TIMEOUT", info="no answer"))
            self.outstanding = pending = None
        if pending is None and self.waiting:
            command = self.waiting.popleft()
            self.outstanding = Pending(command, deadline_for(command.verb, command.args) or 0.0, now, now)
            return [command], timed_out
        if pending is not None and not pending.acknowledged and now - pending.last_sent >= pending.interval:
            pending.last_sent, pending.tries = now, pending.tries + 1
            pending.interval = min(MAX_RETRY_S, pending.interval * 2)
            return [pending.frame], timed_out
        return [], timed_out

    def on_answer(self, frame: Ok | Error | Info) -> CommandResult | None:
        """An ``O``/``E``/``I`` frame; the result if it ended the outstanding command."""
        pending = self.outstanding
        if pending is None or frame.id != pending.id:
            return None
        if isinstance(frame, Info):
            pending.rows.append(frame.text)
            return None
        self.outstanding = None
        if isinstance(frame, Ok):
            return _result(pending, ok=True, info=frame.info)
        return _result(pending, ok=False, code=frame.code, info=frame.text)

    def on_status(self) -> CommandResult | None:
        """An ``S`` frame: it answers an outstanding PING or STATUS."""
        pending = self.outstanding
        if pending is not None and pending.frame.verb in STATUS_VERBS:
            self.outstanding = None
            return _result(pending, ok=True)
        return None

    def acknowledge(self) -> None:
        """The machine showed it has the outstanding command (e.g. the first ``A`` of SD PUT)."""
        if self.outstanding is not None:
            self.outstanding.acknowledged = True

    def heartbeat(self, sending: list[Command]) -> list[Command]:
        """The second's ``PING`` with a fresh id, sent even while a command is outstanding
        (the machine never remembers a PING's id, so the retry stays a retry); none when
        ``sending`` already holds a PING or STATUS."""
        if any(c.verb in STATUS_VERBS for c in sending):
            return []
        return [Command(self._take_id(), "PING")]

    def fail_all(self, code: str, info: str) -> list[CommandResult]:
        """End every command (link lost, disconnect): results for each."""
        pendings = ([self.outstanding] if self.outstanding else []) + [Pending(c, 0) for c in self.waiting]
        self.outstanding = None
        self.waiting.clear()
        return [_result(p, ok=False, code=code, info=info) for p in pendings]


def _result(pending: Pending, ok: bool, code: str = "", info: str = "") -> CommandResult:
    frame = pending.frame
    return CommandResult(frame.id, frame.verb, frame.args, ok, info, code, tuple(pending.rows))
