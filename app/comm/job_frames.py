"""The machine's frames for a stream: the half of ``JobControl`` that follows a job or
an upload as ``A``/``N``/``F``/``S``/``E -``/``X`` frames come in, and sends its ``D``
frames as time passes.

``StreamFrames`` is mixed into ``Session`` through ``JobControl`` (it uses the
session's ``stream``, ``state``, ``commands``, ``urgent``, ``health``, listener and clock).
Contract: ``_tick_stream`` sends what the window allows (nothing before an upload's
``SD PUT`` has gone out) and ends the stream when a line ran out of retries; ``A``/``N``
/``F`` and the ``acc``/``done``/``free`` of ``S`` move the window and the progress (in
program lines, at most every 0.1 s unless a line finished); the last ``F`` completes a
job; a refused line (``E -``) ends it naming the program line; ``LIMIT``,
``SOFT_LIMIT``, ``FOLLOWING_ERROR`` and a status in ``ALARM`` end it; ``UART_LOST``
or flag ``U`` interrupts it; a program stop the machine holds at (flag ``W``) is
reported once. Frames that belong to no stream of this session are ignored (an ``E -``
is logged).
"""

from __future__ import annotations

from app.comm import frame as fr
from app.comm.events import StatusEvent
from app.comm.listener import JOB_STATES, SENDING_STATES, SessionState
from app.comm.stops import stop_event
from app.i18n import N_, msg

S = SessionState
PROGRESS_EVERY_S = 0.1
UNKNOWN_BOOT = "0"
STOP_ALARMS = frozenset({"LIMIT", "SOFT_LIMIT", "FOLLOWING_ERROR"})  # COVER_OPEN holds: RESUME goes on

_REFUSED, _REFUSED_BARE = N_("line refused: {code} {text}"), N_("line refused: {code}")
_LINE_REFUSED = N_("line {line} refused: {code} {text}")
_LINE_REFUSED_BARE = N_("line {line} refused: {code}")


def _refused_seq(text: str, default: int) -> int:
    """The seq an ``E -`` names as the first word of its text (the machine's), else ``default``."""
    first = text.split(" ", 1)[0]
    return int(first) if first.isdigit() else default


class StreamFrames:
    """Frame handlers and the sending tick of a stream (see the module docstring)."""

    def _tick_stream(self, now: float) -> None:
        stream = self.stream
        if stream is None or self.state not in SENDING_STATES or not self.attached:
            return
        if self.commands.is_waiting(stream.opener):  # SD PUT still behind another command:
            return  # a D frame before it would reach a machine with no upload open (BAD_SEQ)
        window = stream.window
        sent, resent = window.sent, window.resent
        for frame in window.due(now):
            self._send(frame)
        self.health.add(now, window.sent - sent, window.resent - resent)
        if window.failed:
            self._error("RETRIES_EXHAUSTED", window.failed)
            if stream.kind == "job":
                self.urgent.request("STOP", now)
            self._finish_stream(False, window.failed)
            return
        self._report_progress(now)

    def _on_ack(self, frame: fr.Ack, now: float) -> None:
        if self.stream is None or self.state not in SENDING_STATES:
            return
        if self.stream.window.on_ack(frame.seq, frame.free, now) and self.state is S.UPLOADING:
            self.commands.acknowledge()

    def _on_nak(self, frame: fr.Nak, now: float) -> None:
        if self.stream is not None and self.state in SENDING_STATES:
            self.stream.window.on_nak(frame.seq, now)

    def _on_finished(self, frame: fr.Finished, now: float) -> None:
        if self.stream is None or self.stream.kind != "job" or self.state not in SENDING_STATES:
            return
        self.stream.window.on_ack(frame.seq, 0, now, timed=False)
        self._lines_finished(frame.seq, now)

    def _lines_finished(self, seq: int, now: float) -> None:
        if self.stream.finish_line(seq):
            self._report_progress(now, force=True)
            if self.stream.complete:
                self._finish_stream(True, msg("completed"))

    def _line_refused(self, frame: fr.Error) -> None:
        said = {"code": frame.code, "text": frame.text}
        reason = msg(_REFUSED if frame.text else _REFUSED_BARE, **said)
        if self.stream is None or self.state is S.STOPPING:  # a frame still in flight
            self._log("warning", msg("{reason} (no job running)", reason=reason))
            return
        self._error("LINE_REFUSED", reason)
        if self.state in JOB_STATES | SENDING_STATES:
            seq = _refused_seq(frame.text, self.status.done + 1 if self.status else 0)
            line = self.stream.program_index(seq)
            self.stream.refused = line
            reason = msg(_LINE_REFUSED if frame.text else _LINE_REFUSED_BARE, line=line, **said)
            self._finish_stream(False, reason)

    def _job_alarm(self, code: str, text: str) -> None:
        if self.stream is None:
            return
        if code == "UART_LOST" and self.state in JOB_STATES - {S.STOPPING}:
            self._interrupt(msg("the UART hop to the CNC MCU is down"))
        elif code in STOP_ALARMS and self.state in JOB_STATES | SENDING_STATES:
            self._finish_stream(False, msg("alarm {code} {text}", code=code, text=text))

    def _job_status(self, event: StatusEvent, now: float) -> None:
        stream = self.stream
        if stream is None or event.boot == UNKNOWN_BOOT:
            return
        if self.state is S.INTERRUPTED:
            if self.link.state.value == "CONNECTED":
                self._offer_recovery(event)
            return
        if self.state is S.STOPPING:
            if self._stop_taken and event.state in ("IDLE", "ALARM"):
                self._stopped()
            return
        if stream.kind != "job" or self.state not in SENDING_STATES:
            return
        if "U" in event.flags:
            self._interrupt(msg("the UART hop to the CNC MCU is down"))
            return
        stream.window.on_status_ack(event.acc, event.free, now)
        if event.state == "HOLD" and self.state is S.STREAMING:
            self._set_state(S.PAUSED)
        elif event.state == "RUN" and self.state is S.PAUSED:
            self._set_state(S.STREAMING)
        self._lines_finished(event.done, now)
        self._program_stop(event)
        if self.stream is not None and event.state == "ALARM":
            self._finish_stream(False, msg("the machine is in ALARM"))

    def _program_stop(self, event: StatusEvent) -> None:
        """Report a program stop the machine now holds at (flag ``W``), once."""
        if self.stream is None or self.stream.kind != "job":
            return
        seq = self.program_stops.update(event.flags, event.done)
        if seq is None or seq >= self.stream.window.total:
            return
        index = self.stream.program_index(seq)
        line = self.lines[index] if 0 <= index < len(self.lines) else ""
        self._log("info", f"program stop at line {index}: {line}")
        self.listener.on_program_stop(stop_event(index, line))

    def _report_progress(self, now: float, force: bool = False) -> None:
        last, when = self._last_progress
        if not force and now - when < PROGRESS_EVERY_S:
            return
        progress = self.stream.progress()
        if progress != last:
            self._last_progress = (progress, now)
            self.listener.on_progress(progress)
