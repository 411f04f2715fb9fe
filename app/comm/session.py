"""The host side of docs/protocol.md as a plain object: bytes in, time, calls; frames out.

``Session(write, listener, clock)`` never sleeps, never starts a thread and never
reads a port: the owner (the worker, the console, a test) calls ``feed(bytes)`` with
whatever arrived, ``tick()`` as time passes (every 5-10 ms), and the operator calls
(``start_job``, ``pause``, ``stop``, ...). Frames are written with ``write(bytes)``;
an ``OSError`` from it (pyserial's ``SerialException`` is one) is a link loss, never
a crash. ``clock()`` gives seconds; inject a fake one for deterministic tests, and
``ids`` (a function giving the next command id) for repeatable ones; by default the ids
are the process's sequence (``commands.next_command_id``).

Everything observable goes to the ``SessionListener`` as frozen events. Streams
(``stream.py``) use the selective-repeat credit window of ``window.py``; commands
(``commands.py``) carry one outstanding id retried with the same id; the link
monitor (``heartbeat.py``) pings every 0.25 s (also while a command is outstanding)
and calls the link degraded after 2 s and lost after 3 s of silence; real-time
commands (``R`` frames, ``realtime.py``) go out twice, then every 10 ms until answered;
the resend rate of the last minute (``link_health.py``) rides on every ``LinkEvent``
(at most one a second while it changes); each hold, stop or alarm the status explains
(``why``, ``holds.py``) is reported once with ``on_hold``, and logged when this host
did not ask for it. Job
recovery after a link loss: same boot id ->
``RESUME_OFFERED`` (``resume_after_reconnect``); new boot id -> ``RESTART_REQUIRED``
(home, then ``confirm_restart`` restarts at done+1 behind the modal preamble).
"""

from __future__ import annotations

import time
from collections.abc import Callable

from app.comm import deframer as dfr
from app.comm import frame as fr
from app.comm.commands import CommandQueue, next_command_id
from app.comm.events import (
    AlarmEvent,
    CommandResult,
    FrameEvent,
    JobEvent,
    LinkEvent,
    ResumeOffer,
    StatusEvent,
)
from app.comm.heartbeat import LinkMonitor
from app.comm.hold_jog import HoldToJog
from app.comm.holds import HoldWatch, source_words
from app.comm.jobs import UNKNOWN_BOOT, JobControl
from app.comm.link_health import ResendMeter
from app.comm.listener import JOB_STATES, SENDING_STATES, SessionListener, SessionState
from app.comm.realtime import NAMES, UrgentCommands
from app.comm.rtt import RttEstimator
from app.comm.session_core import SessionCore
from app.comm.stops import StopWatch
from app.comm.stream import Stream
from app.comm.window import MAX_WINDOW
from app.i18n import msg
from app.profile import Link

S = SessionState
HEALTH_EVERY_S = 1.0


class Session(SessionCore, JobControl):
    """One connection to the machine; see the module docstring for the contract."""

    def __init__(self, write: Callable[[bytes], object] | None = None,
                 listener: SessionListener | None = None,
                 clock: Callable[[], float] = time.monotonic, link: Link | None = None,
                 ids: Callable[[], int] | None = None) -> None:
        link = link or Link()
        self.listener = listener or SessionListener()
        self.clock = clock
        self.state = S.DISCONNECTED
        self.link = LinkMonitor(link.heartbeat_s, link.degraded_s, link.lost_s)
        self.commands = CommandQueue(ids=ids or next_command_id)
        self.urgent = UrgentCommands(self.commands.take_id)
        self.hold_jog = HoldToJog(self.commands.take_id)
        self.health = ResendMeter()
        self.holds = HoldWatch()
        self.asked_hold = False  # this host asked for the hold or stop under way
        self._stop_taken = False  # the machine answered this host's R STOP
        self.deframer = dfr.Deframer()
        self.rtt = RttEstimator()
        self.stream: Stream | None = None
        self.status: StatusEvent | None = None
        self.boot: str | None = None
        self.homed_boot: str | None = None
        self.lines: list[str] = []
        self.mdi = False  # the job's lines were typed: JOB <n> MDI
        self.program_stops = StopWatch()
        self.max_window = MAX_WINDOW
        self._write = write
        self._out = bytearray()
        self._then: dict[int, Callable[[CommandResult], None]] = {}
        self._warned = False
        self._health_shown: tuple[int, float] = (0, float("-inf"))  # percent shown, when
        self._last_progress = (None, float("-inf"))
        self._handlers: dict[str, Callable] = {
            "A": self._on_ack, "N": self._on_nak, "F": self._on_finished, "O": self._on_answer,
            "E": self._on_answer, "I": self._on_answer, "S": self._on_status,
            "X": self._on_alarm, "L": self._on_machine_log, "D": self._on_unexpected,
            "C": self._on_unexpected, "R": self._on_unexpected,
        }

    # ------------------------------------------------------------------ connection

    def attach(self, write: Callable[[bytes], object]) -> None:
        """A transport was opened: start talking (ask for a status)."""
        self.deframer = dfr.Deframer()
        self.urgent.clear()
        self.holds.forget()
        self._last_progress = (None, float("-inf"))
        self.program_stops.forget()
        self._open_link(write)
        self.submit("STATUS")

    def _after_detach(self) -> None:
        if self.state in (S.READY, S.CONNECTING, S.UPLOADING, S.STOPPING):
            self._set_state(S.DISCONNECTED)

    # ------------------------------------------------------------------ bytes in, time

    def feed(self, data: bytes) -> None:
        """Bytes read from the transport; frames are handled at once."""
        now = self.clock()
        for item in self.deframer.feed(data, now):
            self._receive(item, now)
        self.tick()

    def tick(self) -> None:
        """Let time pass: timeouts, heartbeat, resends, real-time repeats, new D frames."""
        now = self.clock()
        for item in self.deframer.poll(now):
            self._receive(item, now)
        self._check_silence(now)
        self._tick_realtime(now)
        self._tick_commands(now)
        self._tick_stream(now)
        self._check_quality(now)
        self._flush()

    # ------------------------------------------------------------------ commands

    def submit(self, verb: str, *args: object, urgent: bool = False,
               then: Callable[[CommandResult], None] | None = None) -> int:
        """Queue command ``verb args`` and return its id; the result comes to on_command_done."""
        command = self.commands.submit(verb, tuple(str(a) for a in args), urgent)
        if urgent and self.commands.outstanding is not None:
            dropped = self.commands.supersede()
            self._command_done(CommandResult(dropped.id, dropped.frame.verb, dropped.frame.args,
                                             False, msg("superseded by {verb}", verb=verb), "SUPERSEDED"))
        if then is not None:
            self._then[command.id] = then
        if self.attached:
            self.tick()
        return command.id

    def send_command(self, text: str) -> int | None:
        """A command typed by the operator (``HOME``, ``JOG X 10 300``); None if empty."""
        words = text.strip().upper().split()
        return self.submit(words[0], *words[1:]) if words else None

    def _command_done(self, result: CommandResult) -> None:
        if result.verb == "HOME" and result.ok:
            self.homed_boot = self.boot
        then = self._then.pop(result.id, None)
        self.listener.on_command_done(result)
        if then is not None:
            then(result)

    def _tick_commands(self, now: float) -> None:
        if not self.attached:
            return
        frames, timed_out = self.commands.due(now)
        for result in timed_out:
            self._command_done(result)
        if self.link.ping_due(now):
            frames += self.commands.heartbeat(frames)
            self.link.pinged(now)
        for command in frames:
            self._send(command)

    # ------------------------------------------------------------------ real time

    def request_urgent(self, verb: str) -> None:
        """Send ``R <id> verb`` now and repeat it until answered (docs/protocol.md)."""
        self.urgent.request(verb, self.clock())
        self.tick()

    def jog_hold(self, keys: tuple[str, ...], feed: float) -> bool:
        """Hold-to-jog: the jog keys held now (``("X+", "Y+")``; ``()`` on release) at
        ``feed`` mm/min. Keep-alives go out from the next tick, ``R JOGEND`` on release
        (docs/protocol.md, "Continuous jog"); False (nothing sent) without a link or
        during a job, except while it holds at a program stop (flag ``W``: the touch-off)."""
        at_stop = self.status is not None and "W" in self.status.flags
        if keys and (not self.attached or self.busy and not at_stop):
            return False
        if self.hold_jog.hold(keys, feed):
            self.request_urgent("JOGEND")
        elif self.attached:
            self.tick()
        return True

    def set_override(self, verb: str, percent: int) -> bool:
        """``R <id> FEED|SPINDLE|RAPID <percent>`` (docs/protocol.md, "Overrides"): the
        absolute value, repeated until answered; refused when out of its range."""
        allowed = fr.OVERRIDE_RANGES.get(verb)
        if allowed is None or percent not in allowed:
            return self._refuse("BAD_ARGS", msg("override {verb}: {percent} is outside its range",
                                                verb=verb, percent=percent))
        if not self.attached:
            return self._refuse("NOT_CONNECTED", msg("not connected"))
        self.urgent.request(verb, self.clock(), int(percent))
        self.tick()
        return True

    def set_feed_override(self, percent: int) -> bool:
        """The driver-neutral call (``SerialWorker.machine_call``): ``R FEED <percent>``."""
        return self.set_override("FEED", percent)

    def set_spindle_override(self, percent: int) -> bool:
        return self.set_override("SPINDLE", percent)

    def set_rapid_override(self, percent: int) -> bool:
        return self.set_override("RAPID", percent)

    def _tick_realtime(self, now: float) -> None:
        for frame in self.urgent.expired(now):
            what = NAMES[frame.verb]
            self._error("REALTIME_UNCONFIRMED", msg("the machine did not confirm the {what}", what=what))
            self._urgent_unanswered(frame)
        if self.attached:
            for frame in self.urgent.due(now) + self.hold_jog.due(now):
                self._send(frame)

    # ------------------------------------------------------------------ incoming

    def _receive(self, item: fr.Frame | dfr.Dropped, now: float) -> None:
        if isinstance(item, dfr.Dropped):
            text = item.raw.decode("ascii", "replace")
            self.listener.on_frame(FrameEvent("rx", "?", f"{item.reason}: {text!r}", ok=False))
            return
        self._heard(now)
        self.listener.on_frame(FrameEvent("rx", item.KIND, item.body()))
        self._handlers[item.KIND](item, now)

    def _on_unexpected(self, frame: fr.Frame, now: float) -> None:
        self._log("warning", f"unexpected frame from the machine: {frame.body()}")

    def _on_answer(self, frame: fr.Ok | fr.Error | fr.Info, now: float) -> None:
        if isinstance(frame, fr.Error) and frame.id is None:
            self._line_refused(frame)
            return
        if not isinstance(frame, fr.Info) and self.hold_jog.on_answer(frame):
            if self.hold_jog.refused is frame:
                self._log("warning", msg("the jog stopped: {code} {text}", code=frame.code, text=frame.text))
            return
        urgent = self.urgent.on_answer(frame) if not isinstance(frame, fr.Info) else None
        if urgent is not None:
            ok = isinstance(frame, fr.Ok)
            info = frame.info if ok else frame.text
            self._command_done(CommandResult(frame.id, urgent.verb, (), ok, info, "" if ok else frame.code))
            self._urgent_answered(urgent, ok, info)
            return
        result = self.commands.on_answer(frame)
        if result is not None:
            self._command_done(result)

    def _on_alarm(self, frame: fr.Alarm, now: float) -> None:
        self.listener.on_alarm(AlarmEvent(frame.code, frame.text))
        self._log("error", f"alarm {frame.code} {frame.text}".strip(), "machine")
        self._job_alarm(frame.code, frame.text)

    def _on_machine_log(self, frame: fr.Log, now: float) -> None:
        self._log("info", frame.text, "machine")

    def _on_status(self, frame: fr.Status, now: float) -> None:
        overrides = frame.overrides
        if overrides is None and self.status is not None and self.status.boot == frame.boot:
            overrides = self.status.overrides  # a status too long for `ovr` goes without it
        event = StatusEvent(frame.boot, frame.state, frame.x, frame.y, frame.z, frame.acc,
                            frame.done, frame.free, frame.rpm, frame.flags, now, frame.why,
                            overrides)
        self.status = event
        self.listener.on_status(event)
        old_boot = self.boot
        if event.boot != UNKNOWN_BOOT:
            self.boot = event.boot
        if self.state is S.CONNECTING:
            self._set_state(S.READY)
        if old_boot is not None and event.boot not in (old_boot, UNKNOWN_BOOT):
            self._log("warning", msg("the machine was reset (boot id {old} -> {new})", old=old_boot,
                                              new=event.boot))
            self._machine_reset(event)
        result = self.commands.on_status()
        if result is not None:
            self._command_done(result)
        self.urgent.on_status(event.state)
        self._job_status(event, now)
        self._report_hold(event)

    def _report_hold(self, event: StatusEvent) -> None:
        """Tell the listener (and the log, when not asked for) why the machine holds."""
        hold = self.holds.update(event, self.asked_hold)
        if hold is None:
            return
        if hold.why and not hold.asked:
            said = {"source": source_words(hold.source), "reason": hold.text}
            self._log("warning", msg("the machine holds ({source}): {reason}", **said) if hold.state == "HOLD"
                      else msg("the machine stopped ({source}): {reason}", **said))
        self.listener.on_hold(hold)

    # ------------------------------------------------------------------ link

    def _silence_reason(self) -> str:
        return msg("no valid frame for {seconds:g} s", seconds=float(self.link.lost_s))

    def _link_lost(self, reason: str) -> None:
        self.hold_jog.cancel()
        self._error("LINK_LOST", msg("link to the machine lost: {reason}", reason=reason))
        self._job_link_lost(reason)
        for result in self.commands.fail_all("LINK_LOST", reason):
            self._command_done(result)

    def _emit_link(self, reason: str = "") -> None:
        now = self.clock()
        rate = self.health.rate(now)
        silent = self.link.silent_for(now) if self.attached else 0.0
        self._health_shown = (round(rate * 100), now)
        self.listener.on_link_changed(LinkEvent(self.link.state.value, silent, rate, self._warned, reason,
                                                self.health.sent(now), self.health.resent(now)))

    def _check_quality(self, now: float) -> None:
        """The resend rate of the last minute: warn while it is high (logged when the
        warning starts and ends), and show its figure at most once a second."""
        bad = self.health.warning(now)
        if bad != self._warned:
            self._warned = bad
            said = {"rate": float(self.health.rate(now)), "sent": self.health.sent(now)}
            if bad:
                self._log("warning", msg("poor link: {rate:.0%} of the {sent} frames of the last minute "
                                         "were resent", **said))
            else:
                self._log("info", msg("link quality back: {rate:.0%} of the {sent} frames of the last "
                                      "minute were resent", **said))
            self._emit_link()
        shown, when = self._health_shown
        if round(self.health.rate(now) * 100) != shown and now - when >= HEALTH_EVERY_S:
            self._emit_link()

    # ------------------------------------------------------------------ output and helpers

    def _send(self, frame: fr.Frame) -> None:
        self._out += frame.encode()
        self.listener.on_frame(FrameEvent("tx", frame.KIND, frame.body()))

    def _finish_stream(self, completed: bool, reason: str) -> None:
        stream, self.stream = self.stream, None
        if stream is not None:
            event = JobEvent(stream.kind, completed, reason, stream.program_index(stream.done),
                             stream.program_total, stream.name, stream.refused)
            self.listener.on_progress(stream.progress())
            self.listener.on_job_finished(event)
        self._set_state(S.READY if self.attached else S.DISCONNECTED)

    def _offer(self, offer: ResumeOffer, state: SessionState) -> None:
        self._set_state(state)
        self.listener.on_resume_offer(offer)

    @property
    def busy(self) -> bool:
        return self.state in JOB_STATES or self.state in SENDING_STATES
