"""Jobs on a GRBL machine: start, program stops, hold, resume, stop, errors, cut-offs.

A mixin of ``GrblSession`` (it relies on the session's ``job``, ``counter``, ``status``,
``_realtime``, ``_set_state``, ``_end_job``...). ``start_job(device_lines, start,
line_map=...)`` streams ``dialect.grbl_lines`` behind ``dialect.PREAMBLE`` (and, from a
later line, ``modal.restart_preamble``). On ``error:N`` the stream stops at once: the
job ends naming the source line and GRBL's meaning, and says that lines already in the
machine's buffer may still run (GRBL documents this); the machine is held, then reset
once the hold is complete (a reset while moving would lose the position). In check mode
(``$C``) an error does not stop the check: every refused line is listed and the job
ends failed. ``stop()`` is the same hold-then-reset. A reset the host did not ask for,
or a link loss, cuts the job off: once the machine answers again, ``ResumeOffer`` at
the line after the last one known finished (GRBL cannot resume exactly);
``confirm_restart()`` runs from there with the modal state restored: units, distance
mode, feed mode and plane (``PREAMBLE``), the work system and coolant the job ran in
(``$G``, read as the job's first line: a reset puts GRBL back in G54 with coolant off),
the G92 and tool length offsets (``$#``, read next: a reset clears both), then the
spindle, feed and position the lines before it left (``modal.restart_preamble``).
"""

from __future__ import annotations

from app.comm.events import ProgramStopEvent, ResumeOffer
from app.comm.grbl import protocol as p
from app.comm.grbl.dialect import PREAMBLE, grbl_lines, line_problems, tool_change_height
from app.comm.grbl.job import GrblJob, Outgoing
from app.comm.grbl.toolchange import safe_tool_changes, state_after
from app.comm.listener import SessionState
from app.comm.modal import ModalState, preamble_of
from app.i18n import joined, msg

S = SessionState
PARSER_STATE = "$G"  # the job's first line: the work system and coolant it runs in
PARAMETERS = "$#"  # then its G92 and tool length offsets (a reset clears both)
WORK_SYSTEMS = frozenset(f"G{n}" for n in range(54, 60))
COOLANT = ("M7", "M8")
PROGRESS_S = 0.1
STILL_REPORTS = 2  # reports at rest after the hold before the reset: the first may predate the hold
_SETTLED = ("Idle", "Check", "Alarm")


class GrblJobControl:
    """Job calls and the job side of incoming lines (see the module docstring)."""

    # ------------------------------------------------------------------ calls

    def start_job(self, device_lines, start: int = 0, name: str = "", line_map=None,
                  modes: tuple[str, ...] | None = None, offsets=None, mdi: bool = False) -> bool:
        """Stream ``device_lines`` (or a ``Program``: its device lines and line map) from
        index ``start``; False (with an error event) if the machine cannot take a job now.
        ``line_map`` (device index -> source line) lets messages name the source line.
        ``modes`` (a restart: ``held_modes`` of the job cut off) are set before the lines,
        and ``offsets`` (its ``held_offsets``: G92 and the tool length offset) after them;
        None reads both from the machine (``$G``, ``$#``) for a later restart. ``mdi``
        (typed lines) changes nothing: GRBL has no after-job action."""
        if hasattr(device_lines, "device_lines"):
            program = device_lines
            device_lines = list(program.device_lines)
            line_map = line_map if line_map is not None else program.line_map.tolist()
            name = name or getattr(program, "name", "")
        began = self.clock()
        why = self._job_refusal(device_lines, start)
        if why:
            self._error("REFUSED", why)
            return False
        if modes is None:
            reads = (PARSER_STATE,) if self.check_mode else (PARSER_STATE, PARAMETERS)  # $C refuses $#
            first = reads + PREAMBLE
        else:
            first = PREAMBLE + modes + self._offset_lines(offsets, modes)
        before = state_after(ModalState(), device_lines[:start])  # modal_state's, read from the end
        preamble = first + (tuple(preamble_of(before)) if start else ())  # modal.restart_preamble
        lines = safe_tool_changes(grbl_lines(device_lines, self.optional_stop, start), before,
                                  self._tool_change_lift())
        job = GrblJob(lines, len(device_lines), name, preamble, first=start)
        job.device_lines, job.line_map, job.errors = device_lines, line_map, []
        job.modes = held_modes(self.parser_state) if modes is None else modes
        job.offsets = offsets
        job.boot = self.boots
        job.end_reason, job.reset_sent, job.cut_off = "", False, False
        self.job, self.last_job, self._last_progress = job, None, float("-inf")
        self._set_state(S.STARTING)
        self._set_state(S.STREAMING)
        self.link.excuse(self.clock() - began)  # (a million lines take a second or two to prepare)
        self.tick()
        return True

    def _job_refusal(self, device_lines, start: int):
        if self.job is not None:
            return msg("a job is already running")
        if not self.attached or self.status is None:
            return msg("the machine is not connected")
        restarting = self.state is S.STARTING and self._restart_on_welcome is not None
        if self.state not in (S.READY, S.RESTART_REQUIRED) and not restarting:
            return msg("the machine is not ready ({state})", state=self.state.name)
        if self.alarm is not None and not self.check_mode:
            if not self.homing_enabled:
                return msg("the machine is in alarm: unlock ($X) first")
            return msg("the machine is in alarm: home ($H) or unlock ($X) first")
        if not 0 <= start < len(device_lines):
            return msg("no line {start} to start from", start=start)
        problems = line_problems(device_lines[start:])
        return joined(problems[:3]) if problems else ""

    def pause(self) -> None:
        """Feed hold (``!``)."""
        self._realtime(p.FEED_HOLD)

    def resume(self) -> bool:
        """Go on past a program stop, or leave a feed hold / door (``~``)."""
        job = self.job
        if job is not None and job.stop_at is not None and job.prompted:
            job.leave_stop()
            self.tick()
            return True
        self._realtime(p.CYCLE_START)
        return True

    def stop(self) -> None:
        """End the job now: hold, then a reset once the machine is at rest. A job cut off
        by a link loss or a reset (no Start here taken) is abandoned."""
        job = self.job
        if self.state in (S.INTERRUPTED, S.RESTART_REQUIRED) or self._restart_on_welcome is not None:
            self._abandon()
            job = None
        if job is None:
            self._realtime(p.FEED_HOLD)
            self._reset_when_still = True
            return
        self._stop_job(msg("stopped by the operator"))

    def reset(self) -> None:
        """Soft reset (0x18) at once: a reset while moving loses the position (alarm 3)."""
        self._realtime(p.SOFT_RESET)

    def confirm_restart(self) -> bool:
        """After a cut-off: run the job again from the line after the last one finished.
        After a link loss (no reset since), GRBL may hold the start of a line cut off
        mid-way, which the next line would complete: it is reset first, once at rest (a
        reset at rest keeps the position), and the job restarts on its welcome (STARTING
        meanwhile; a link loss before it cuts the job off again, ``stop()`` abandons it)."""
        job = self.last_job
        if self.state is not S.RESTART_REQUIRED or job is None:
            self._error("REFUSED", msg("there is no interrupted job to restart"))
            return False
        if job.boot == self.boots:
            self._restart_on_welcome, self._reset_when_still = job, True
            self._set_state(S.STARTING)
            self._log("info", msg("the machine is reset once at rest (its buffer cleared), then the job "
                                  "starts again at line {line}", line=self._source_line(job.done + 1)))
            return True
        return self._restart(job)

    def _restart(self, job) -> bool:
        return self.start_job(job.device_lines, job.done + 1, job.name, job.line_map, job.modes, job.offsets)

    def abandon_restart(self) -> None:
        if self.state is S.RESTART_REQUIRED:
            self.last_job = self._restart_on_welcome = None
            self._settle()

    def _abandon(self) -> None:
        """The job cut off (INTERRUPTED, or waiting for Start here) ends, as any job ends."""
        self.job, self._restart_on_welcome = self.job or self.last_job, None
        self._end_job(False, msg("abandoned by the operator"))
        self.last_job = None

    # ------------------------------------------------------------------ answers

    def _job_ok(self, out: Outgoing) -> None:
        job = self.job
        job.acked_line(out)
        if out.kind == "preamble" and out.text == PARSER_STATE:
            job.modes = held_modes(self.parser_state)  # its [GC:..] came just before the ok
        elif out.kind == "preamble" and out.text == PARAMETERS:
            job.offsets = self.held_offsets()
        elif out.kind == "sync":
            stop = job.synced()
            if stop is not None and not job.stopping:
                job.prompted = True
                self.listener.on_program_stop(stop.stop)
                line = self._source_line(stop.index)
                self._log("info", msg("program stop at line {line}: {text}", line=line, text=stop.stop.line))
            elif job.complete and not job.stopping:
                self._job_complete()
                return
        self._progress()

    def _job_complete(self) -> None:
        job = self.job
        if job.errors:
            first = job.errors[0]
            if len(job.errors) == 1:
                self._end_job(False, msg("the check found 1 refused line: {first}", first=first))
            else:
                self._end_job(False, msg("the check found {count} refused lines; the first: {first}",
                                         count=len(job.errors), first=first))
        else:
            self._end_job(True, msg("completed"))

    def _job_error(self, out: Outgoing, code: int, text: str) -> None:
        job = self.job
        where = self._source_line(out.index)
        what = msg("line {line} ({text}): error {code}: {what}", line=where, text=out.text, code=code,
                   what=text)
        if job.refused < 0 and out.kind == "job":
            job.refused = out.index
        if self.check_mode and out.kind == "job":
            job.errors.append(what)
            job.refused = -1
            self._log("error", what, "machine")
            return
        self._error("LINE_REFUSED", what)
        self._stop_job(msg("{what}; the lines already in the machine's buffer may still have run",
                           what=what))

    def _stop_job(self, reason: str) -> None:
        job = self.job
        if job.stopping:
            return
        job.stopping, job.end_reason = True, reason
        self._set_state(S.STOPPING)
        if job.stop_at is not None or self.check_mode:
            self._send_reset(job)  # known at rest (after a sync), or nothing moves
        else:
            job.still_reports = 0
            self._realtime(p.FEED_HOLD)

    def _send_reset(self, job: GrblJob) -> None:
        if not job.reset_sent:
            job.reset_sent = True
            self._realtime(p.SOFT_RESET)

    def _job_report(self, status) -> None:
        job = self.job
        if job.stopping:
            still = status.state in _SETTLED or (status.state in ("Hold", "Door") and status.substate == 0)
            job.still_reports = job.still_reports + 1 if still else 0
            if job.still_reports >= STILL_REPORTS:
                self._send_reset(job)
            return
        if self.state is S.INTERRUPTED:
            self._job_reconnected(same_boot=True)
            return
        in_flight = any(o.kind == "job" for o in self.counter.items())
        if status.state in ("Idle", "Check") and not in_flight:
            job.all_finished()
        else:
            job.planner_report(self._blocks_used(status))
        if status.state in ("Hold", "Door") and self.state is S.STREAMING:
            self._set_state(S.PAUSED)
        elif status.state in ("Run", "Idle", "Check") and self.state is S.PAUSED:
            self._set_state(S.STREAMING)
        self._progress()

    def _blocks_used(self, status) -> int | None:
        """Planner blocks that may still hold answered lines: ``Bf:``'s count when the
        report has it, else the whole planner (``[OPT:]``: GRBL answers a motion line
        only once it is in the planner, so older answered lines have finished)."""
        size = self.info.planner_blocks if self.info and self.info.planner_blocks else None
        if status.planner_free is None:
            return size
        self._planner_max = max(getattr(self, "_planner_max", 0), status.planner_free)
        return (size or self._planner_max) - status.planner_free

    def _job_reset(self) -> None:
        """The welcome line arrived during a job: stopped as asked, or cut off."""
        job = self.job
        if job.stopping:
            self._end_job(False, job.end_reason)
            return
        self._job_reconnected(same_boot=False)

    def _job_link_lost(self, reason: str) -> None:
        pending, self._restart_on_welcome = self._restart_on_welcome, None
        if pending is not None:  # Start here confirmed, the reset not yet seen: cut off again
            self.job, self._reset_when_still = pending, False
        job = self.job
        if job is None:
            return
        if job.stopping:
            self._end_job(False, msg("{first}; then the link was lost: {reason}", first=job.end_reason,
                                     reason=reason))
            return
        job.cut_off = True
        job.refused = max(job.refused, -1)
        self._set_state(S.INTERRUPTED)

    def _job_reconnected(self, same_boot: bool) -> None:
        """The machine answers again after a cut-off: offer Start here."""
        job, self.job = self.job, None
        if same_boot and self.grbl_status is not None and self.grbl_status.state in ("Idle", "Check"):
            job.done = max(job.done, job.acked)
        self.last_job = job
        self._set_state(S.RESTART_REQUIRED)
        self._offer_restart(job, same_boot)

    def _offer_restart(self, job: GrblJob, same_boot: bool) -> None:
        if same_boot:
            reason = msg("the link was lost during the job; GRBL cannot resume exactly: start again at "
                         "line {line}, the line after the last one known finished (lines after it may "
                         "have run)", line=self._source_line(job.done + 1))
        elif self.homing_enabled:
            reason = msg("the machine was reset during the job; home it, then start again at line {line}, "
                         "the line after the last one known finished", line=self._source_line(job.done + 1))
        else:
            reason = msg("the machine was reset during the job; start again at line {line}, the line after "
                         "the last one known finished (it has no homing: check its position and work zero "
                         "first)", line=self._source_line(job.done + 1))
        self._log("warning", reason)
        self.listener.on_progress(job.progress())
        needs_home = not same_boot and self.homing_enabled
        self.listener.on_resume_offer(ResumeOffer(False, job.done + 1, job.done, job.total, needs_home,
                                                  reason))

    def _follow_cut_off_job(self, status) -> None:
        """After a link loss (no reset since) the machine runs what its buffer holds: until
        the operator answers Start here, and until the reset that a confirmed restart waits
        for, the restart line follows what the reports show finished (the offer is made
        again with it), so no line the machine finished runs twice."""
        pending = self._restart_on_welcome
        job = pending or (self.last_job if self.state is S.RESTART_REQUIRED else None)
        if job is None or job.boot != self.boots:
            return
        before = job.done
        if status.state in ("Idle", "Check"):
            job.all_finished()
        else:
            job.planner_report(self._blocks_used(status))
        if job.done == before:
            return
        if pending is None:
            self._offer_restart(job, same_boot=True)
        else:
            self.listener.on_progress(job.progress())
            self._log("info", msg("the machine finished more lines meanwhile: the job starts again at line "
                                  "{line}", line=self._source_line(job.done + 1)))

    def _tool_change_lift(self) -> tuple[str, float] | None:
        """``G53 G00 Z..`` near the top of the Z travel (``dialect.tool_change_height``) and
        the work Z it reaches (the live WCO) once homed; None (the program's own highest Z)
        on a machine not homed, whose machine coordinates say nothing of the travel."""
        options = self.info.options if self.info is not None else ""
        height = tool_change_height(self.settings, options) if self.homed else None
        if height is None or self.grbl_status is None:
            return None
        return f"G53 G00 Z{height:.3f}", height - self.grbl_status.wco[2]

    # ------------------------------------------------------------------ offsets a reset clears

    def held_offsets(self):
        """``(g92, tlo)`` in millimetres from the last ``$#`` (None before one): what a reset
        clears (GRBL 1.1 keeps neither G92 nor G43.1 across one) and a restart sets again."""
        g92, tlo = self.parameter_mm("G92"), self.parameter_mm("TLO")
        if g92 is None or len(g92) < 3:
            return None
        return tuple(g92[:3]), (tlo[2] if tlo and len(tlo) >= 3 else tlo[0] if tlo else 0.0)  # Z's

    def _offset_lines(self, offsets, modes: tuple[str, ...]) -> tuple[str, ...]:
        """``G43.1 Z..`` and ``G92 X.. Y.. Z..`` that put back ``offsets`` (``held_offsets``)
        in the work system of ``modes``: G92 sets the offset from where the machine stands,
        ``value = MPos - G5x - G92 (- TLO in Z)``, so the last report's MPos is used (a
        restart starts at rest)."""
        if offsets is None:
            return ()
        g92, tlo = offsets
        lines = [f"G43.1 Z{tlo:.3f}"] if tlo else []
        if any(g92):
            system = next((m for m in modes if m in WORK_SYSTEMS), "G54")
            zero = self.parameter_mm(system)
            if zero is None or self.grbl_status is None:
                self._log("warning", msg("the G92 offset in force before the reset could not be set again: "
                                         "{system} is not known", system=system))
                return tuple(lines)
            here = self.grbl_status.mpos
            values = [here[k] - zero[k] - g92[k] - (tlo if k == 2 else 0.0) for k in range(3)]
            lines.append("G92 " + " ".join(f"{a}{v:.3f}" for a, v in zip("XYZ", values, strict=True)))
        return tuple(lines)

    # ------------------------------------------------------------------ helpers

    def _source_line(self, index: int) -> int:
        job = self.job or self.last_job
        line_map = getattr(job, "line_map", None)
        if line_map is not None and 0 <= index < len(line_map):
            return int(line_map[index])
        return index + 1

    def _progress(self) -> None:
        now = self.clock()
        if now - self._last_progress >= PROGRESS_S:
            self._last_progress = now
            self.listener.on_progress(self.job.progress())


def held_modes(parser_state: str) -> tuple[str, ...]:
    """What of ``$G``'s parser state (``G0 G55 G17 G21 G90 G94 M5 M8 T0 F0 S0``) a reset
    loses and no job line sets again: the work system and the coolant (``("G55", "M8")``)."""
    words = parser_state.upper().split()
    systems = [w for w in words if w in WORK_SYSTEMS]
    return tuple(systems[:1]) + tuple(w for w in words if w in COOLANT)


__all__ = ["GrblJobControl", "ProgramStopEvent", "held_modes"]
