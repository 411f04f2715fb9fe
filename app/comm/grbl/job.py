"""One job streamed to a GRBL machine: which line goes next, what was answered, what
has finished, where it waits at a program stop.

``GrblJob(lines, total, name)`` holds the ``GrblLine`` list (``dialect.grbl_lines``),
preceded by ``preamble`` texts that belong to no program line. The session asks
``next_text()`` for the next thing to send (a line, the ``G4 P0`` sync before a program
stop or at the end, or None while it must wait) and reports back with ``sent``,
``acked``, ``synced`` and ``planner_report``. Indices are program line indices;
``done`` is the last line known finished: every line answered before an idle report or
a sync, or, while running, the answered motion line before the last ``used`` ones
(``Bf:``'s blocks in use, else the planner's size: never more lines than blocks wait).

The lines a tool change adds around its stop are ``toolchange.safe_tool_changes``'.
"""

from __future__ import annotations

import re
from collections import deque
from dataclasses import dataclass

from app.comm.events import ProgressEvent
from app.comm.grbl.dialect import SYNC, GrblLine

_MOTION = re.compile(r"(?:G53\s*)?G0*[0-3](?![0-9.])")  # a line that makes a planner block


@dataclass(frozen=True)
class Outgoing:
    """A line in flight: ``kind`` "job", "preamble", "sync" (its ``index`` is the line
    it waits behind) or "command" (``index`` is the command id)."""

    kind: str
    text: str
    index: int
    exclusive: bool = False


def _is_motion(text: str) -> bool:
    """A line that makes a planner block (a G0-G3 move)."""
    return _MOTION.match(text) is not None


class GrblJob:
    """See the module docstring."""

    def __init__(self, lines: list[GrblLine], total: int, name: str = "",
                 preamble: tuple[str, ...] = (), first: int = 0) -> None:
        self.lines, self.total, self.name = lines, total, name
        self.preamble = deque(preamble)
        self.position = 0  # next entry of ``lines`` to send
        self.sent = self.acked = self.done = first - 1
        self.refused = -1
        self.stop_at: GrblLine | None = None  # a program stop the stream waits at
        self.prompted = False  # the stop's prompt has been given
        self.stopping = False
        self.cut_off = False  # the link was lost: nothing more goes out
        self.finished_sending = False
        self.modes: tuple[str, ...] = ()  # the work system and coolant it runs in (set by the session)
        self.boot = 0  # the machine's boot count when it started (set by the session)
        self._sync_out = False
        self._motion = deque()  # program indices of answered motion lines, newest last

    # ------------------------------------------------------------------ what to send

    def next_out(self) -> Outgoing | None:
        """The next line to send, or None while the stream must wait (or is over)."""
        if self.stopping or self.cut_off or self.refused >= 0 or self._sync_out or self.stop_at is not None:
            return None
        if self.preamble:
            return Outgoing("preamble", self.preamble[0], self.done)
        if self.position >= len(self.lines):
            if self.finished_sending:
                return None
            return Outgoing("sync", SYNC, self.sent)
        line = self.lines[self.position]
        if line.stop is not None:
            return Outgoing("sync", SYNC, self.sent)
        return Outgoing("job", line.text, line.index)

    def sent_out(self, out: Outgoing) -> None:
        if out.kind == "preamble":
            self.preamble.popleft()
        elif out.kind == "sync":
            self._sync_out = True
            if self.position >= len(self.lines):
                self.finished_sending = True
        else:
            self.position += 1
            self.sent = out.index

    # ------------------------------------------------------------------ answers

    def acked_line(self, out: Outgoing) -> None:
        if out.kind != "job":
            return
        self.acked = out.index
        if _is_motion(out.text):
            self._motion.append(out.index)
            while len(self._motion) > 64:
                self._motion.popleft()

    def synced(self) -> GrblLine | None:
        """A sync was answered: everything sent has finished. Returns the program stop
        now reached (None at the end of the job)."""
        self._sync_out = False
        self.all_finished()
        if self.position < len(self.lines) and self.lines[self.position].stop is not None:
            self.stop_at = self.lines[self.position]
            return self.stop_at
        return None

    def leave_stop(self) -> None:
        """The operator continues past the program stop."""
        if self.stop_at is not None:
            self.done = max(self.done, self.stop_at.index)
            self.position += 1
            self.stop_at, self.prompted = None, False

    def all_finished(self) -> None:
        self.done = max(self.done, self.acked)
        self._motion.clear()

    def planner_report(self, blocks_used: int | None) -> None:
        """A report while running: ``blocks_used`` planner blocks hold answered lines."""
        if blocks_used is None:
            return
        if blocks_used <= 0:
            self.all_finished()
            return
        if len(self._motion) > blocks_used:
            finished = self._motion[-blocks_used - 1]
            self.done = max(self.done, finished)

    @property
    def complete(self) -> bool:
        return self.finished_sending and not self._sync_out and self.refused < 0

    def progress(self) -> ProgressEvent:
        return ProgressEvent("job", self.total, self.done, self.acked, self.sent)
