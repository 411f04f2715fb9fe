"""Recovery of a job after a link loss or a machine reset: the half of ``JobControl``
that decides what the operator is offered.

``Recovery`` is mixed into ``Session`` through ``JobControl``. Contract: a link loss
while a job runs interrupts it (an upload fails, a stop under way ends as stopped);
once the link is back and a status arrives, the same boot id offers a resume from
``acc+1`` (``RESUME_OFFERED``: the machine kept its position) and a new boot id asks
for a restart from ``done+1`` after homing (``RESTART_REQUIRED``); a reset seen while
connected does the same for a job and ends an upload. The offers go to the listener's
``on_resume_offer``; the operator's answer is ``JobControl.resume_after_reconnect``
or ``confirm_restart``.
"""

from __future__ import annotations

from app.comm.events import ResumeOffer, StatusEvent
from app.comm.listener import JOB_STATES, RECOVERY_STATES, SessionState
from app.i18n import msg

S = SessionState


class Recovery:
    """Interruption and the resume or restart offer (see the module docstring)."""

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
