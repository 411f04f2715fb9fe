"""Small frozen dataclasses that the session reports and the worker's signals carry.

Every event is immutable and holds only plain values (str, int, float, tuples), so it
can cross threads safely and be compared in tests. No Qt here.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class StateEvent:
    """The session moved from ``old`` to ``new`` (names of ``SessionState``)."""

    old: str
    new: str


@dataclass(frozen=True)
class StatusEvent:
    """One ``S`` frame of the machine, with the host time it arrived."""

    boot: str
    state: str
    x: float
    y: float
    z: float
    acc: int
    done: int
    free: int
    rpm: int
    flags: str
    time: float = 0.0
    why: str = ""  # why it holds, stopped a job short or is in ALARM ("" none or unknown)

    @property
    def homed(self) -> bool:
        return "H" in self.flags

    @property
    def position(self) -> tuple[float, float, float]:
        return (self.x, self.y, self.z)


@dataclass(frozen=True)
class ProgramStopEvent:
    """The machine holds at a program stop (docs/protocol.md, "Program stops").

    ``index`` is the program line index of the stop's device line, ``line`` its text
    (``M00``, ``M01``, ``M06 T2``), ``code`` 0, 1 or 6 and ``tool`` the tool an
    ``M06`` names (None: not named). ``RESUME`` continues, ``STOP`` ends the job.
    """

    index: int
    line: str
    code: int
    tool: int | None = None


@dataclass(frozen=True)
class HoldEvent:
    """The machine holds, stopped a job short or is in ALARM, and says why (``S`` field
    ``why``, docs/protocol.md "Why the machine holds"), or (``why`` "") runs again.

    ``state`` is the machine's state, ``source`` who or what caused it (``host``,
    ``panel``, ``cover``, ``link``, ``program``, ``machine``), ``text`` the reason in
    words (an ``app.i18n`` message) and ``asked`` whether this host asked for it (its
    own hold or stop): a hold not asked for must reach the operator.
    """

    why: str
    state: str
    source: str = ""
    text: str = ""
    asked: bool = False


@dataclass(frozen=True)
class ProgressEvent:
    """Progress of the stream ``kind`` ("job" or "upload"), in program line indices.

    ``done`` is the last finished line (-1 for none), ``acked`` the last line the
    machine has queued, ``sent`` the last line sent; ``resends`` counts resent frames.
    """

    kind: str
    total: int
    done: int
    acked: int
    sent: int
    resends: int = 0
    resend_rate: float = 0.0

    @property
    def fraction(self) -> float:
        return (self.done + 1) / self.total if self.total else 1.0


@dataclass(frozen=True)
class LinkEvent:
    """Link health: ``state`` is CONNECTED, DEGRADED, LOST or DISCONNECTED.

    ``silent_s`` is the time since the last valid frame; ``resend_rate`` the share of
    the D frames sent in the last minute that were resends (``sent_last_min`` of them,
    ``resent_last_min`` resends), as Klipper shows its retransmit counter;
    ``quality_warning`` is set while it is over 10 % (of at least 20 frames).
    """

    state: str
    silent_s: float = 0.0
    resend_rate: float = 0.0
    quality_warning: bool = False
    reason: str = ""
    sent_last_min: int = 0
    resent_last_min: int = 0


@dataclass(frozen=True)
class AlarmEvent:
    """An ``X`` frame (LIMIT, SOFT_LIMIT, COVER_OPEN, HOST_LOST, UART_LOST, BOOT, ...)."""

    code: str
    text: str = ""


@dataclass(frozen=True)
class LogEvent:
    """A line for the log: ``level`` is "info", "warning" or "error"; ``source`` "host" or "machine"."""

    level: str
    text: str
    source: str = "host"


@dataclass(frozen=True)
class FrameEvent:
    """Traffic for the console: ``direction`` "tx" or "rx"; ``ok`` False for a dropped line.

    ``kind`` is the frame letter (``D``, ``A``, ``R`` ...),
    or ``?`` for a line that was not a valid frame (``text`` then says why).
    """

    direction: str
    kind: str
    text: str
    ok: bool = True


@dataclass(frozen=True)
class CommandResult:
    """The end of command ``id``: ``ok`` with ``info`` and ``rows`` (``I`` lines), or refused.

    ``code`` is the machine's error code, ``TIMEOUT`` when it never answered,
    ``LINK_LOST`` / ``SUPERSEDED`` / ``REFUSED`` for host-side endings.
    """

    id: int
    verb: str
    args: tuple[str, ...] = ()
    ok: bool = True
    info: str = ""
    code: str = ""
    rows: tuple[str, ...] = field(default_factory=tuple)


@dataclass(frozen=True)
class JobEvent:
    """A stream ended: ``completed`` only if every line finished (job) or was stored (upload)."""

    kind: str
    completed: bool
    reason: str
    done: int
    total: int
    name: str = ""
    refused: int = -1  # the program line the machine refused (-1: none)


@dataclass(frozen=True)
class ErrorEvent:
    """A host-side error worth a dialog: ``code`` is a stable name (RETRIES_EXHAUSTED, ...)."""

    code: str
    text: str


@dataclass(frozen=True)
class ResumeOffer:
    """After a reconnect during a job: how it can continue.

    ``same_boot``: the machine kept its position; ``resume_after_reconnect()`` sends
    ``RESUME FROM from_seq``. Otherwise the machine was reset: ``needs_home`` and the
    operator must call ``confirm_restart()``, which restarts at ``from_seq`` (done+1)
    with the modal state restored.
    """

    same_boot: bool
    from_seq: int
    done: int
    total: int
    needs_home: bool
    reason: str = ""
