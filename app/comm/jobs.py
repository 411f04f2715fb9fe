"""Jobs, SD uploads, pause/stop and recovery: the stream half of ``Session``.

``JobControl`` is mixed into ``Session`` (it uses its ``submit``, ``_set_state``,
``_send``, listener and clock). Contract of the operator calls:

- ``start_job(program, start=0)`` (a ``Program`` with ``device_lines`` or a list of
  lines): only when READY with nothing in flight; sends ``JOB n`` and streams once it
  is open. With ``start`` > 0 (start from a line) the stream is the restore preamble
  of ``modal.restart_preamble`` followed by lines ``start..``; progress stays in
  program line indices.
- ``pause()`` sends ``!`` (repeated until the status shows HOLD); ``resume()`` sends
  ``RESUME``; ``stop()`` sends 0x18 (repeated until IDLE) and an urgent ``STOP``; no
  D frame is sent after a stop.
- ``upload_to_sd(name, lines)`` sends ``SD PUT name n crc32`` and streams the lines.
- ``resume_after_reconnect()`` (RESUME_OFFERED) sends ``RESUME FROM acc+1`` and the
  missing frames; ``confirm_restart()`` (RESTART_REQUIRED, homed) restarts at done+1.
Each returns True if accepted; a refusal is reported with ``on_error`` and False.
"""

from __future__ import annotations

import math

from app.comm import frame as fr
from app.comm.events import CommandResult, ResumeOffer, StatusEvent
from app.comm.listener import JOB_STATES, RECOVERY_STATES, SENDING_STATES, SessionState
from app.comm.modal import restart_preamble
from app.comm.stops import stop_event
from app.comm.stream import Stream, sd_crc32
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


def plain_number(value: float) -> str:
    """``value`` in the protocol's number grammar (no exponent), to 0.0001."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "-") else text


def device_lines(program) -> list[str]:
    """The lines to stream: ``program.device_lines`` or the sequence itself."""
    return list(getattr(program, "device_lines", program))


class JobControl:
    """Operator calls and frame handlers for streams (see the module docstring)."""

    # ------------------------------------------------------------------ operator calls

    def start_job(self, program, start: int = 0) -> bool:
        lines = device_lines(program)
        if not self._can_start(lines, "job"):
            return False
        if not 0 <= start < len(lines):
            return self._refuse("BAD_START", msg("line {start} is not in the program (0..{last})",
                                                 start=start,
                                                 last=len(lines) - 1))
        self.lines = lines
        free = self.status.free if self.status else 1
        pre = restart_preamble(lines, start)
        self.stream = Stream.job(lines, self.rtt, free, start, pre, boot=self.boot or "",
                                 max_window=self.max_window)
        self._set_state(S.STARTING)
        self.submit("JOB", len(lines), then=self._job_opened)
        return True

    def upload_to_sd(self, name: str, lines) -> bool:
        lines = device_lines(lines)
        if not self._can_start(lines, "upload"):
            return False
        self.stream = Stream.upload(name, lines, self.rtt)
        self._set_state(S.UPLOADING)
        self.stream.opener = self.commands.next_id  # the id SD PUT gets: its D frames wait for it
        self.submit("SD", "PUT", name, len(lines), f"{sd_crc32(lines):08X}", then=self._upload_answered)
        return True

    def run_from_sd(self, name: str) -> int:
        return self.submit("SD", "RUN", name)

    def list_sd(self) -> int:
        return self.submit("SD", "LIST")

    def delete_sd(self, name: str) -> int:
        return self.submit("SD", "DEL", name)

    def home(self, mode: str = "NORMAL") -> int:
        return self.submit("HOME", mode)

    def jog(self, axis: str, distance_mm: float, feed_mm_min: float) -> int:
        """``JOG``; ValueError for a non-finite distance or feed (never sent as ``inf``)."""
        for what, value in (("distance", distance_mm), ("feed", feed_mm_min)):
            if not math.isfinite(value):
                raise ValueError(f"jog {what} {value} is not a finite number")
        return self.submit("JOG", axis.upper(), plain_number(distance_mm), plain_number(feed_mm_min))

    def pause(self) -> bool:
        """Feed hold now (real-time ``!``, repeated until the status shows HOLD)."""
        if not self.attached:
            return self._refuse("NOT_CONNECTED", msg("not connected"))
        self.realtime.request(fr.FEED_HOLD, self.clock())
        self.tick()
        return True

    def resume(self) -> bool:
        """Leave a feed hold (``RESUME``); a job after a reconnect uses resume_after_reconnect."""
        if self.state is S.RESUME_OFFERED:
            return self.resume_after_reconnect()
        self.submit("RESUME")
        return True

    def stop(self) -> bool:
        """Stop and flush now (0x18 repeated until IDLE, and an urgent ``STOP``)."""
        if self.state in RECOVERY_STATES:
            self._finish_stream(False, msg("abandoned by the operator"))
        if self.attached:
            self.realtime.request(fr.STOP_FLUSH, self.clock())
            if self.state in JOB_STATES or self.state is S.UPLOADING:
                self._stop_stream()
            self.submit("STOP", urgent=True, then=self._stop_answered)
        return True

    def resume_after_reconnect(self) -> bool:
        if self.state is not S.RESUME_OFFERED or self.status is None:
            return self._refuse("NO_RESUME", msg("there is no interrupted job to resume"))
        seq = self.status.acc + 1
        self._set_state(S.RESUMING)
        self.submit("RESUME", "FROM", seq, then=lambda r: self._resumed(r, seq))
        return True

    def take_over_job(self, program) -> bool:
        """Resume a job of ``program`` another client left open on this machine (same
        boot, per the last status): ``RESUME FROM acc+1``, then the rest of its lines."""
        lines = device_lines(program)
        if not self._can_start(lines, "job"):
            return False
        status = self.status
        if status is None or status.acc < 0 or status.acc >= len(lines) - 1:
            return self._refuse("NO_RESUME", "the machine has no open job of these lines to resume")
        self.lines = lines
        self.stream = Stream.job(lines, self.rtt, status.free, boot=self.boot or "",
                                 max_window=self.max_window)
        self.stream.done = status.done
        seq = status.acc + 1
        self._set_state(S.RESUMING)
        self.submit("RESUME", "FROM", seq, then=lambda r: self._resumed(r, seq))
        return True

    def confirm_restart(self) -> bool:
        """After a machine reset and re-homing: restart the job at done+1 (modal state restored)."""
        if self.state is not S.RESTART_REQUIRED or self.stream is None:
            return self._refuse("NO_RESTART", msg("there is no job waiting for a restart"))
        homed = self.status is not None and self.status.homed or self.homed_boot == self.boot
        if self.status is None or not homed:
            return self._refuse("HOME_REQUIRED", msg("home the machine before restarting the job"))
        start = self.stream.program_index(self.stream.done) + 1
        pre = restart_preamble(self.lines, start)
        self.stream = Stream.job(self.lines, self.rtt, self.status.free, start, pre, self.boot or "",
                                 self.max_window)
        self._set_state(S.STARTING)
        self.submit("JOB", self.stream.window.total, then=self._job_opened)
        return True

    # ------------------------------------------------------------------ checks

    def _can_start(self, lines: list[str], what: str) -> bool:
        if self.state is not S.READY or self.stream is not None:
            return self._refuse("BUSY", msg("cannot start a {what} while {state}", what=what,
                                                state=self.state.name.lower()))
        if not lines:
            return self._refuse("EMPTY", msg("the {what} has no lines", what=what))
        for seq, line in enumerate(lines):
            try:
                fr.seal(f"D {seq} {line}")
            except fr.FrameError as exc:
                return self._refuse("BAD_LINE", msg("line {seq} cannot be sent: {error}", seq=seq,
                                                                 error=str(exc)))
        return True

    def _refuse(self, code: str, text: str) -> bool:
        self._error(code, text)
        return False

    # ------------------------------------------------------------------ command answers

    def _job_opened(self, result: CommandResult) -> None:
        if self.state is not S.STARTING:
            return
        if result.ok:
            if self.status is not None:
                self.stream.window.on_ack(-1, self.status.free, self.clock())
            self._set_state(S.STREAMING)
        else:
            self._finish_stream(False, msg("JOB refused: {code} {info}", code=result.code, info=result.info))

    def _upload_answered(self, result: CommandResult) -> None:
        if self.state is not S.UPLOADING:
            return
        stored = result.ok and self.stream.window.all_acked
        reason = msg("stored") if stored else f"{result.code} {result.info}".strip() or msg("upload failed")
        self._finish_stream(stored, reason)

    def _resumed(self, result: CommandResult, seq: int) -> None:
        if self.state is not S.RESUMING:
            return
        if not result.ok:
            self._finish_stream(False, msg("RESUME FROM refused: {code} {info}", code=result.code,
                                               info=result.info))
            return
        free = self.status.free if self.status else 1
        self.stream.window.restart_at(seq, free)
        self._set_state(S.STREAMING)
        if self.status is not None and self.status.state == "HOLD" and "W" not in self.status.flags:
            self.submit("RESUME")  # a feed hold of the link loss (a program stop waits for the operator)

    def _stop_answered(self, result: CommandResult) -> None:
        if result.ok and self.state is S.STOPPING:
            self._finish_stream(False, msg("stopped by the operator"))

    def _stop_stream(self) -> None:
        if self.state is S.UPLOADING:
            self._finish_stream(False, msg("upload stopped by the operator"))
        elif self.state is not S.STOPPING:
            self._set_state(S.STOPPING)

    def _realtime_confirmed(self, byte: bytes) -> None:
        if byte == fr.STOP_FLUSH and self.state is S.STOPPING:
            self._finish_stream(False, msg("stopped by the operator"))

    # ------------------------------------------------------------------ frames of a stream

    def _tick_stream(self, now: float) -> None:
        stream = self.stream
        if stream is None or self.state not in SENDING_STATES or not self.attached:
            return
        if self.commands.is_waiting(stream.opener):  # SD PUT still behind another command:
            return  # a D frame before it would reach a machine with no upload open (BAD_SEQ)
        for frame in stream.window.due(now):
            self._send(frame)
        if stream.window.failed:
            self._error("RETRIES_EXHAUSTED", stream.window.failed)
            if stream.kind == "job":
                self.realtime.request(fr.STOP_FLUSH, now)
            self._finish_stream(False, stream.window.failed)
            return
        self._check_quality()
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

    # ------------------------------------------------------------------ recovery

    def _interrupt(self, reason: str) -> None:
        if self.state is not S.INTERRUPTED:
            self._log("warning", f"job interrupted: {reason}")
            self._set_state(S.INTERRUPTED)

    def _job_link_lost(self, reason: str) -> None:
        if self.stream is None:
            return
        if self.state is S.UPLOADING:
            self._finish_stream(False, msg("upload failed: {reason}", reason=reason))
        elif self.state is S.STOPPING:
            self._finish_stream(False, msg("stopped (link lost before the machine confirmed: {reason})",
                                                  reason=reason))
        elif self.state in JOB_STATES or self.state in RECOVERY_STATES:
            self._interrupt(reason)

    def _offer_recovery(self, event: StatusEvent) -> None:
        stream = self.stream
        if event.boot == stream.boot and stream.kind == "job":
            self._lines_finished(event.done, self.clock())
            if self.stream is None:
                return
        if "U" in event.flags:
            return
        if event.boot == stream.boot:
            start = stream.program_index(event.acc) + 1
            offer = ResumeOffer(True, start, stream.program_index(stream.done), stream.program_total, False,
                                "the machine kept its position")
            self._offer(offer, S.RESUME_OFFERED)
        else:
            self._offer_restart("the machine was reset")

    def _offer_restart(self, reason: str) -> None:
        stream = self.stream
        done = stream.program_index(stream.done)
        offer = ResumeOffer(False, done + 1, done, stream.program_total, True, reason)
        self._offer(offer, S.RESTART_REQUIRED)

    def _machine_reset(self, event: StatusEvent) -> None:
        self._error("MACHINE_RESET", msg("the machine was reset (new boot id {boot}); position unknown",
                                                 boot=event.boot))
        if self.stream is not None and self.stream.kind == "job" and self.state is not S.STOPPING:
            if self.state in JOB_STATES or self.state in RECOVERY_STATES:
                self._offer_restart("the machine was reset: home it, then confirm the restart")
        elif self.stream is not None:
            self._finish_stream(False, msg("the machine was reset"))
