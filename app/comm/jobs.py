"""Jobs, SD uploads, pause/stop and recovery: the stream half of ``Session``.

``JobControl`` is mixed into ``Session`` (it uses its ``submit``, ``_set_state``,
``_send``, listener and clock). Its frame handlers are ``job_frames.StreamFrames``, its
link-loss and reset handling ``job_recovery.Recovery``; here the operator calls and
the answers to the commands they send. Contract of the operator calls:

- ``start_job(program, start=0)`` (a ``Program`` with ``device_lines`` or a list of
  lines): only when READY with nothing in flight; sends ``JOB n`` and streams once it
  is open. With ``start`` > 0 (start from a line) the stream is the restore preamble
  of ``modal.restart_preamble`` followed by lines ``start..``; progress stays in
  program line indices.
- ``pause()``, ``resume()`` and ``stop()`` send the real-time commands ``R HOLD``,
  ``R RESUME`` and ``R STOP`` (repeated until answered, ``realtime.py``); a stopped job
  ends once the ``STOP`` is answered and a status shows IDLE or ALARM; no D frame is
  sent after a stop.
- ``upload_to_sd(name, lines)`` sends ``SD PUT name n crc32`` and streams the lines.
- ``resume_after_reconnect()`` (RESUME_OFFERED) sends ``RESUME FROM acc+1`` and the
  missing frames; ``confirm_restart()`` (RESTART_REQUIRED, homed) restarts at done+1.
Each returns True if accepted; a refusal is reported with ``on_error`` and False.
"""

from __future__ import annotations

import math

from app.comm import frame as fr
from app.comm.events import CommandResult
from app.comm.job_frames import UNKNOWN_BOOT, StreamFrames
from app.comm.job_recovery import Recovery
from app.comm.listener import JOB_STATES, RECOVERY_STATES, SessionState
from app.comm.modal import restart_preamble
from app.comm.stream import Stream, sd_crc32
from app.i18n import msg

__all__ = ["UNKNOWN_BOOT", "JobControl", "device_lines", "plain_number"]

S = SessionState


def plain_number(value: float) -> str:
    """``value`` in the protocol's number grammar (no exponent), to 0.0001."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "-") else text


def device_lines(program) -> list[str]:
    """The lines to stream: ``program.device_lines`` or the sequence itself."""
    return list(getattr(program, "device_lines", program))


class JobControl(StreamFrames, Recovery):
    """Operator calls and command answers for streams (see the module docstring)."""

    # ------------------------------------------------------------------ operator calls

    def start_job(self, program, start: int = 0, mdi: bool = False) -> bool:
        """Stream ``program`` from device line ``start``; ``mdi``: lines the operator typed
        (``JOB <n> MDI``: the machine does no after-job action at their end)."""
        lines = device_lines(program)
        if not self._can_start(lines, "job"):
            return False
        if not 0 <= start < len(lines):
            return self._refuse("BAD_START", msg("line {start} is not in the program (0..{last})",
                                                 start=start,
                                                 last=len(lines) - 1))
        self.lines, self.mdi = lines, mdi
        self.asked_hold = False
        free = self.status.free if self.status else 1
        pre = restart_preamble(lines, start)
        self.stream = Stream.job(lines, self.rtt, free, start, pre, boot=self.boot or "",
                                 max_window=self.max_window)
        self._set_state(S.STARTING)
        self._submit_job()
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
        """Feed hold now (``R HOLD``, repeated until answered or the status shows HOLD)."""
        if not self.attached:
            return self._refuse("NOT_CONNECTED", msg("not connected"))
        self.asked_hold = True
        self.hold_jog.cancel()
        self.request_urgent("HOLD")
        return True

    def resume(self) -> bool:
        """Leave a feed hold or a program stop (``R RESUME``); a job after a reconnect uses
        resume_after_reconnect."""
        if self.state is S.RESUME_OFFERED:
            return self.resume_after_reconnect()
        if not self.attached:
            return self._refuse("NOT_CONNECTED", msg("not connected"))
        self.asked_hold = False
        self.request_urgent("RESUME")
        return True

    def stop(self) -> bool:
        """Stop and flush now (``R STOP``, repeated until answered)."""
        if self.state in RECOVERY_STATES:
            self._finish_stream(False, msg("abandoned by the operator"))
        self.hold_jog.cancel()
        if self.attached:
            self.asked_hold, self._stop_taken = True, False
            if self.state in JOB_STATES or self.state is S.UPLOADING:
                self._stop_stream()
            self.request_urgent("STOP")
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
        self.lines, self.mdi = lines, False
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
        self._submit_job()
        return True

    def _submit_job(self) -> None:
        """``JOB`` with the lines this stream sends (``MDI`` for typed lines)."""
        self.submit("JOB", self.stream.window.total, *(("MDI",) if self.mdi else ()), then=self._job_opened)

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

    def _urgent_answered(self, frame: fr.RealtimeCommand, ok: bool, info: str) -> None:
        """The machine answered ``R STOP``: the job is stopped once it stands still."""
        if frame.verb == "STOP" and ok:
            self._stop_taken = True
            if info in ("IDLE", "ALARM"):  # a later status says when a stop still under way ends
                self._stopped()

    def _urgent_unanswered(self, frame: fr.RealtimeCommand) -> None:
        if frame.verb == "STOP" and self.state is S.STOPPING:
            self._finish_stream(False, msg("the machine did not confirm the stop"))

    def _stopped(self) -> None:
        if self.state is S.STOPPING:
            self._finish_stream(False, msg("stopped by the operator"))

    def _stop_stream(self) -> None:
        if self.state is S.UPLOADING:
            self._finish_stream(False, msg("upload stopped by the operator"))
        elif self.state is not S.STOPPING:
            self._set_state(S.STOPPING)

