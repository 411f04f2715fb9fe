"""``SD RUN``: the main MCU streams a file from the card to the CNC MCU itself.

Contract: ``SdJob`` plays the host's part of docs/protocol.md on the UART hop: it
opens the stream with its own ``C <id> JOB <n>``, keeps at most ``min(free, 8)``
``D`` frames unacknowledged, resends from ``n`` on ``N n`` or from the first
unacknowledged line after ``RESEND_S`` without progress, and is done when ``F``
reaches the last line. It needs no host: the job carries on if the host is lost.
"""

from __future__ import annotations

import enum
from collections.abc import Callable

from app.comm.frame import Command, Data, Frame

WINDOW = 8
RESEND_S = 0.5


class SdJobState(enum.Enum):
    OPENING = "opening"
    STREAMING = "streaming"
    DONE = "done"
    FAILED = "failed"


class SdJob:
    def __init__(self, name: str, lines: list[str], cmd_id: int, send: Callable[[Frame], None],
                 now: float) -> None:
        self.name, self.lines, self.cmd_id, self._send = name, lines, cmd_id, send
        self.state = SdJobState.OPENING
        self.acked = -1
        self.sent = -1
        self.done = -1
        self.free = WINDOW
        self.error = ""
        self.last_progress = now
        send(Command(cmd_id, "JOB", (str(len(lines)),)))

    @property
    def active(self) -> bool:
        return self.state in (SdJobState.OPENING, SdJobState.STREAMING)

    @property
    def progress(self) -> float:
        return (self.done + 1) / len(self.lines)

    def opened(self, now: float) -> None:
        self.state = SdJobState.STREAMING
        self.last_progress = now
        self.pump()

    def fail(self, text: str) -> None:
        self.state = SdJobState.FAILED
        self.error = text

    def on_ack(self, seq: int, free: int, now: float) -> None:
        if seq > self.acked:
            self.acked = seq
            self.last_progress = now
        self.free = free
        self.pump()

    def on_nak(self, seq: int, now: float) -> None:
        self.sent = min(self.sent, seq - 1)
        self.pump()

    def on_finished(self, seq: int, now: float) -> None:
        if seq > self.done:
            self.free += seq - self.done
            self.done = seq
            self.last_progress = now
        if self.done >= len(self.lines) - 1:
            self.state = SdJobState.DONE
        self.pump()

    def on_status(self, free: int) -> None:
        self.free = free
        self.pump()

    def pump(self) -> None:
        if self.state is not SdJobState.STREAMING:
            return
        window = min(self.free, WINDOW)
        while self.sent < len(self.lines) - 1 and self.sent - self.acked < window:
            self.sent += 1
            self._send(Data(self.sent, self.lines[self.sent]))

    def next_due(self) -> float | None:
        if self.state is SdJobState.STREAMING and self.sent > self.acked:
            return self.last_progress + RESEND_S
        return None

    def poll(self, now: float) -> None:
        due = self.next_due()
        if due is not None and now >= due:
            self.sent = self.acked
            self.last_progress = now
            self.pump()
