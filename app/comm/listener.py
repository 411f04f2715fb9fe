"""The session's listener interface and its state machine.

``SessionListener`` is a plain class of no-op ``on_*`` methods (OctoPrint's
``MachineComPrintCallback`` style); the worker, the console and the tests override
what they need. Every method receives one frozen event of ``app.comm.events``.

``SessionState`` is the host's view of what it is doing, with the frozenset groupings
the session and the GUI test against, and ``TRANSITIONS`` the moves allowed.
"""

from __future__ import annotations

import enum

from app.comm.events import (
    AlarmEvent,
    CommandResult,
    ErrorEvent,
    FrameEvent,
    HoldEvent,
    JobEvent,
    LinkEvent,
    LogEvent,
    ProgramStopEvent,
    ProgressEvent,
    ResumeOffer,
    StateEvent,
    StatusEvent,
)


class SessionState(enum.Enum):
    DISCONNECTED = "DISCONNECTED"  # no transport
    CONNECTING = "CONNECTING"  # transport open, no status yet
    READY = "READY"  # connected, no stream
    STARTING = "STARTING"  # JOB sent, waiting for its O
    STREAMING = "STREAMING"  # job running, D frames flowing
    PAUSED = "PAUSED"  # job in feed hold
    STOPPING = "STOPPING"  # stop sent, waiting for the status to confirm
    UPLOADING = "UPLOADING"  # SD PUT stream
    INTERRUPTED = "INTERRUPTED"  # job cut off by a link loss, waiting for the machine
    RESUME_OFFERED = "RESUME_OFFERED"  # same boot: resume_after_reconnect() continues
    RESTART_REQUIRED = "RESTART_REQUIRED"  # new boot: home, then confirm_restart()
    RESUMING = "RESUMING"  # RESUME FROM sent, waiting for its O


S = SessionState
JOB_STATES = frozenset({S.STARTING, S.STREAMING, S.PAUSED, S.STOPPING, S.RESUMING})
SENDING_STATES = frozenset({S.STREAMING, S.PAUSED, S.UPLOADING})
RECOVERY_STATES = frozenset({S.INTERRUPTED, S.RESUME_OFFERED, S.RESTART_REQUIRED})
BUSY_STATES = JOB_STATES | RECOVERY_STATES | {S.UPLOADING}
CONNECTED_STATES = frozenset(set(S) - {S.DISCONNECTED})

_ANY = frozenset(S)
TRANSITIONS: dict[SessionState, frozenset[SessionState]] = {
    S.DISCONNECTED: frozenset({S.CONNECTING}),
    S.CONNECTING: frozenset({S.READY, S.DISCONNECTED, S.INTERRUPTED}),
    S.READY: frozenset({S.STARTING, S.UPLOADING, S.RESUMING, S.DISCONNECTED}),
    S.STARTING: frozenset({S.STREAMING, S.READY, S.STOPPING, S.INTERRUPTED, S.RESTART_REQUIRED}),
    S.STREAMING: frozenset({S.PAUSED, S.STOPPING, S.READY, S.INTERRUPTED, S.RESTART_REQUIRED}),
    S.PAUSED: frozenset({S.STREAMING, S.STOPPING, S.READY, S.INTERRUPTED, S.RESTART_REQUIRED}),
    S.STOPPING: frozenset({S.READY, S.DISCONNECTED}),
    S.UPLOADING: frozenset({S.READY, S.DISCONNECTED}),
    S.INTERRUPTED: frozenset({S.RESUME_OFFERED, S.RESTART_REQUIRED, S.READY, S.CONNECTING}),
    S.RESUME_OFFERED: frozenset({S.RESUMING, S.RESTART_REQUIRED, S.INTERRUPTED, S.READY}),
    S.RESTART_REQUIRED: frozenset({S.STARTING, S.INTERRUPTED, S.READY}),
    S.RESUMING: frozenset({S.STREAMING, S.PAUSED, S.STOPPING, S.INTERRUPTED, S.RESTART_REQUIRED, S.READY}),
}


class SessionListener:
    """Receives everything the session reports; every method is a no-op here."""

    def on_state_changed(self, event: StateEvent) -> None: ...

    def on_status(self, event: StatusEvent) -> None: ...

    def on_progress(self, event: ProgressEvent) -> None: ...

    def on_link_changed(self, event: LinkEvent) -> None: ...

    def on_alarm(self, event: AlarmEvent) -> None: ...

    def on_log(self, event: LogEvent) -> None: ...

    def on_frame(self, event: FrameEvent) -> None: ...

    def on_command_done(self, event: CommandResult) -> None: ...

    def on_job_finished(self, event: JobEvent) -> None: ...

    def on_error(self, event: ErrorEvent) -> None: ...

    def on_resume_offer(self, event: ResumeOffer) -> None: ...

    def on_program_stop(self, event: ProgramStopEvent) -> None: ...

    def on_hold(self, event: HoldEvent) -> None: ...
