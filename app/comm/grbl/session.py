"""The host side of GRBL 1.1 / grblHAL as a plain object: bytes and time in, bytes out.

``GrblSession(write, listener, clock)`` has the shape of ``app.comm.session.Session``:
the owner calls ``feed(bytes)`` with what arrived, ``tick()`` as time passes and the
operator's calls (``operations.GrblOperations``); bytes go out through ``write``; an
``OSError`` from it is a link loss. Everything observable goes to the listener as the
frozen events of ``app.comm.events`` (status, progress, jobs, alarms, commands, link,
program stops, resume offers) and ``app.comm.grbl.events`` (reports, machine info,
settings).

- Lines (commands and job lines alike) are streamed by character counting against
  the receive buffer (``rx_size``: 128 on GRBL; grblHAL's from ``$I``'s ``[OPT:]`` or
  an idle ``Bf:``); each ``ok``/``error:N`` answers the oldest line in flight. An
  ``exclusive`` line (a setting write: GRBL stops reading while it writes its EEPROM)
  goes alone and nothing follows it until it is answered (send-and-wait).
- Status is polled with ``?`` every 0.2 s (0.1 s while a job or jog runs). No report for
  2 s is DEGRADED, 3 s LOST (while homing or after a critical alarm GRBL sends none:
  the silence timer waits).
- Nothing but ``?`` goes out before the machine's first welcome or report (a board that
  resets when the port opens loses what comes before its welcome). A welcome line
  (``Grbl 1.1h [...]``, ``GrblHAL ...``) is a reset: the receive buffer is empty, lines
  in flight are gone, a job in progress was cut off.
"""

from __future__ import annotations

import time
from collections.abc import Callable

from app.comm.driver import GRBL_CAPABILITIES
from app.comm.events import (
    AlarmEvent,
    CommandResult,
    FrameEvent,
    JobEvent,
    LinkEvent,
)
from app.comm.grbl import protocol as p
from app.comm.grbl.charcount import GRBL_RX_BUFFER, CharCounter
from app.comm.grbl.codes import alarm_text, error_text
from app.comm.grbl.events import GrblListener, GrblStatus, MachineInfo, SettingsEvent
from app.comm.grbl.job import GrblJob, Outgoing
from app.comm.grbl.jobflow import GrblJobControl
from app.comm.grbl.operations import GrblOperations
from app.comm.grbl.status import ReportMerger, to_status_event
from app.comm.grbl.verbs import FrameVerbs
from app.comm.heartbeat import LinkMonitor
from app.comm.listener import TRANSITIONS, SessionState
from app.comm.session_core import SessionCore
from app.i18n import msg

S = SessionState
POLL_IDLE_S = 0.2
POLL_RUNNING_S = 0.1
HOMING_SILENCE_S = 120.0
REFRESH = ("$I", "$$", "$#", "$G")  # read at connect and after every reset
MAX_LINE_BYTES = 1024  # a line from the machine longer than this is noise


class GrblSession(SessionCore, GrblJobControl, GrblOperations, FrameVerbs):
    """One connection to a GRBL machine; see the module docstring for the contract."""

    capabilities = GRBL_CAPABILITIES  # what the window offers; the overrides' ranges come from it

    def __init__(self, write: Callable[[bytes], object] | None = None,
                 listener: GrblListener | None = None, clock: Callable[[], float] = time.monotonic,
                 rx_size: int | None = None) -> None:
        self.listener = listener or GrblListener()
        self.clock = clock
        self.state = S.DISCONNECTED
        self.link = LinkMonitor(1.0, 2.0, 3.0)
        self.fixed_rx = rx_size
        self.counter = CharCounter(rx_size or GRBL_RX_BUFFER)
        self.merger = ReportMerger()
        self.info: MachineInfo | None = None
        self.settings: dict[int, str] = {}
        self.parameters: dict[str, str] = {}
        self.parser_state = ""
        self.grbl_status: GrblStatus | None = None
        self.status = None  # the last StatusEvent
        self.job: GrblJob | None = None
        self.boots = 0
        self.homed = False
        self.alarm: int | None = None
        self.critical = False  # [MSG:Reset to continue]: no reports until a reset
        self.check_mode = False
        self.optional_stop = True
        self.last_job: GrblJob | None = None  # for Start here after a cut-off
        self._reset_when_still = False  # stop() without a job: reset once at rest
        self._restart_on_welcome: GrblJob | None = None  # confirm_restart() after a link loss
        self._last_progress = float("-inf")
        self._write = write
        self._out = bytearray()
        self._rx = bytearray()
        self._queue: list[Outgoing] = []
        self._rows: dict[int, list[str]] = {}
        self._then: dict[int, Callable[[CommandResult], None]] = {}
        self._next_id = 1
        self._next_poll = 0.0
        self._contact = False
        self._settings_rows: list[tuple[int, str]] = []
        self._deferred: list[tuple] = []  # local answers waiting for a report (verbs.py)
        self._asked_reports: list[int] = []  # the operator's own ``?`` waiting for a report
        self.reports = 0  # status reports received
        self._handlers = {p.Ok: self._on_ok, p.Error: self._on_error, p.Alarm: self._on_alarm,
                          p.Welcome: self._on_welcome, p.Report: self._on_report,
                          p.SettingLine: self._on_setting, p.Feedback: self._on_feedback,
                          p.StartupLine: self._on_startup, p.Unknown: self._on_unknown}

    # ------------------------------------------------------------------ connection

    def attach(self, write: Callable[[bytes], object]) -> None:
        """A transport was opened: ask for a report and the build info."""
        self._rx.clear()
        self.counter.clear()
        self._contact = False  # no line goes out before the machine has spoken
        self._open_link(write)
        self._next_poll = self.clock()
        self.refresh()
        self.tick()

    def _after_detach(self) -> None:
        if self.job is None and self.state in (S.READY, S.CONNECTING):
            self._set_state(S.DISCONNECTED)

    @property
    def busy(self) -> bool:
        return self.job is not None

    # ------------------------------------------------------------------ bytes in, time

    def feed(self, data: bytes) -> None:
        """Bytes read from the transport; whole lines are handled at once."""
        self._rx += data
        while True:
            end = self._rx.find(b"\n")
            if end < 0:
                if len(self._rx) > MAX_LINE_BYTES:
                    self._on_unknown(p.Unknown(self._rx[:80].decode("ascii", "replace"), "line too long"))
                    self._rx.clear()
                break
            raw = bytes(self._rx[:end]).rstrip(b"\r")
            del self._rx[: end + 1]
            if raw:
                self._receive(raw.decode("ascii", "replace"))
        self.tick()

    def tick(self) -> None:
        """Let time pass: status polls, the silence timer, lines that now fit."""
        now = self.clock()
        if self.attached:
            if self._silence_expected():
                self.link.heard(now)
            self._check_silence(now)
            if now >= self._next_poll and not self.critical:
                self._realtime(p.STATUS_QUERY, quiet=True)
                running = self.job is not None or (self.status is not None and self.status.state == "JOG")
                period = POLL_RUNNING_S if running else POLL_IDLE_S
                self._next_poll = max(self._next_poll + period, now - period / 2)
            self._pump()
        self._flush()

    def _silence_expected(self) -> bool:
        homing = any(o.text == "$H" for o in self.counter.items())
        return self.critical or (homing and self.link.silent_for(self.clock()) < HOMING_SILENCE_S)

    # ------------------------------------------------------------------ lines out

    def command(self, text: str, exclusive: bool = False,
                then: Callable[[CommandResult], None] | None = None) -> int:
        """Queue the line ``text`` (a ``$`` command or G-code); its answer comes to
        ``on_command_done`` as a ``CommandResult`` whose ``rows`` are the messages the
        machine printed before its ``ok``."""
        cid = self._next_id
        self._next_id += 1
        self._queue.append(Outgoing("command", text.strip(), cid, exclusive))
        if then is not None:
            self._then[cid] = then
        if self.attached:
            self.tick()
        return cid

    def _pump(self) -> None:
        if not self._contact:
            return  # a board that resets on open would lose lines sent before its welcome
        while True:
            oldest = self.counter.oldest()
            if oldest is not None and oldest.exclusive:
                return
            out = self._queue[0] if self._queue else (self.job.next_out() if self.job else None)
            if out is None:
                return
            data = out.text.encode("ascii", "replace") + b"\n"
            if (out.exclusive and len(self.counter)) or not self.counter.fits(len(data)):
                return
            if self._queue:
                self._queue.pop(0)
            else:
                self.job.sent_out(out)
            self.counter.sent(out, len(data))
            if out.kind == "command":
                self._rows[out.index] = []
            self._out += data
            self.listener.on_frame(FrameEvent("tx", out.kind, out.text))

    def _realtime(self, byte: bytes, quiet: bool = False) -> None:
        """Send a real-time byte now, ahead of nothing (it is never buffered by GRBL)."""
        if not self.attached:
            return
        self._out += byte
        if not quiet:
            name = p.REALTIME_NAMES.get(byte, f"0x{byte[0]:02X}")
            self.listener.on_frame(FrameEvent("tx", "^", name))
        self._flush()

    # ------------------------------------------------------------------ lines in

    def _receive(self, text: str) -> None:
        item = p.parse_line(text)
        if not isinstance(item, p.Unknown):
            self._heard(self.clock())
        kind = self._rx_kind(item)
        self.listener.on_frame(FrameEvent("rx", kind, text, ok=not isinstance(item, p.Unknown)))
        self._handlers[type(item)](item)
        if kind == "report":
            self.answer_asked_reports(text)

    def _rx_kind(self, item) -> str:
        """The console kind of a line (``p.STREAM_KINDS`` are hidden unless asked for): "<"
        a polled report, "report" one the operator asked for (``?``), "ok" the answer to a
        streamed line, "preamble" the rows of a job's own reads, "rx" the rest (a
        command's ``ok`` and rows, messages, errors)."""
        if isinstance(item, p.Report):
            return "report" if self._asked_reports else "<"
        oldest = self.counter.oldest()
        streamed = oldest is not None and oldest.kind != "command"
        if isinstance(item, p.Ok):
            return "ok" if streamed else "rx"
        if isinstance(item, p.Feedback) and item.kind != "MSG" and streamed:
            return "preamble"  # the [GC:..] and $# rows a job reads first
        return "rx"

    def _answered(self) -> Outgoing | None:
        out = self.counter.answered()
        if out is None:
            self._log("warning", msg("an answer came for no line sent"))
        return out

    def _on_ok(self, item: p.Ok) -> None:
        out = self._answered()
        if out is None:
            return
        if out.kind == "command":
            self._command_done(CommandResult(out.index, out.text, ok=True,
                                             rows=tuple(self._rows.pop(out.index, ()))))
        elif self.job is not None:
            self._job_ok(out)

    def _on_error(self, item: p.Error) -> None:
        out = self._answered()
        if out is None:
            return
        text = error_text(item.code)
        if out.kind == "command":
            self._log("error", msg("{line}: error {code}: {what}", line=out.text, code=item.code, what=text),
                      "machine")
            rows = tuple(self._rows.pop(out.index, ()))
            self._command_done(CommandResult(out.index, out.text, ok=False, info=text,
                                             code=f"error:{item.code}", rows=rows))
        elif self.job is not None:
            self._job_error(out, item.code, text)

    def _on_alarm(self, item: p.Alarm) -> None:
        self.alarm = item.code
        self.homed = False
        text = alarm_text(item.code)
        self.listener.on_alarm(AlarmEvent(f"ALARM:{item.code}", text))
        self._log("error", msg("alarm {code}: {what}", code=item.code, what=text), "machine")
        if self.job is not None and not self.job.stopping:
            self._end_job(False, msg("alarm {code}: {what}", code=item.code, what=text))

    def _on_welcome(self, item: p.Welcome) -> None:
        self._contact = True
        self.boots += 1
        lost = self.counter.clear()
        self._queue = [o for o in self._queue if o.text not in REFRESH]
        for out in lost:
            if out.kind == "command":
                self._command_done(CommandResult(out.index, out.text, ok=False,
                                                 info=msg("the machine was reset"), code="RESET"))
        self.merger.reset()
        self.merger.inches = self.settings.get(13) == "1"
        restart = self._restart_on_welcome
        homed = self.homed and restart is not None  # this host's reset at rest kept the position
        self.homed, self.critical, self.check_mode, self.alarm = homed, False, False, None
        if self.fixed_rx is None:
            self.counter.capacity = GRBL_RX_BUFFER
        self.info = MachineInfo(item.flavour, item.version, rx_size=self.counter.capacity)
        self._notify("on_machine_info", self.info)
        self._log("info", msg("machine: {text}", text=item.text), "machine")
        if self.job is not None:
            self._job_reset()
        self.refresh()
        if restart is not None and self.state is S.STARTING:
            self._restart(restart)
        self._restart_on_welcome = None

    def _on_report(self, item: p.Report) -> None:
        self._contact = True
        status = self.merger.merge(item, self.clock())
        self.grbl_status = status
        if item.rx_free is not None and not len(self.counter) and self.fixed_rx is None \
                and item.rx_free > self.counter.capacity:
            self.counter.capacity = item.rx_free  # grblHAL reports its own, larger buffer
        if status.state == "Check":
            self.check_mode = True
        if status.state == "Alarm" and self.alarm is None:
            self.alarm = 0  # locked since power-up (homing enabled)
        elif status.state != "Alarm":
            self.alarm = None
        job = self.job
        if self.state is S.CONNECTING:
            self._set_state(S.READY)
        still = status.state in ("Idle", "Alarm", "Check") or (
            status.state in ("Hold", "Door") and status.substate == 0)
        if job is not None:
            self._job_report(status)
        else:
            self._follow_cut_off_job(status)  # before the reset below: what finished first
            if self._reset_when_still and still:
                self._reset_when_still = False
                self._realtime(p.SOFT_RESET)
        job = self.job
        waiting = job is not None and job.stop_at is not None
        acc = job.acked if job else -1
        done = job.done if job else -1
        self.status = to_status_event(status, f"grbl-{self.boots}", acc, done, self.position_trusted,
                                      waiting)
        self._notify("on_grbl_status", status)
        self.listener.on_status(self.status)
        self.reports += 1
        self.answer_deferred()

    def _on_setting(self, item: p.SettingLine) -> None:
        self._settings_rows.append((item.number, item.value))
        self._row(f"${item.number}={item.value}")

    def _on_feedback(self, item: p.Feedback) -> None:
        self._row(f"[{item.kind}:{item.text}]")
        handler = getattr(self, f"_feedback_{item.kind.lower()}", None)
        if handler is not None:
            handler(item.text)
        elif item.kind in ("G54", "G55", "G56", "G57", "G58", "G59", "G28", "G30", "G92", "TLO", "PRB"):
            self.parameters[item.kind] = item.text

    def _on_startup(self, item: p.StartupLine) -> None:
        level = "info" if item.result == "ok" else "error"
        self._log(level, msg("startup line {line}: {result}", line=item.line, result=item.result), "machine")

    def _on_unknown(self, item: p.Unknown) -> None:
        self._row(item.text)
        if item.why:
            self._log("warning", msg("unreadable line from the machine ({why}): {text}",
                                     why=item.why, text=item.text))

    def _row(self, text: str) -> None:
        out = self.counter.oldest()
        if out is not None and out.kind == "command" and out.index in self._rows:
            self._rows[out.index].append(text)

    # ------------------------------------------------------------------ feedback kinds

    def _feedback_msg(self, text: str) -> None:
        self._log("info", text, "machine")
        if text == "Reset to continue":
            self.critical = True
        elif text == "Enabled":
            self.check_mode = True
        elif text == "Disabled":
            self.check_mode = False

    def _feedback_gc(self, text: str) -> None:
        self.parser_state = text

    def _feedback_ver(self, text: str) -> None:
        if self.info is None:
            self.info = MachineInfo("grbl", text.split(":")[0].lstrip("v").split(".20")[0])
        self.info = MachineInfo(self.info.flavour, self.info.version, text, self.info.options,
                                self.counter.capacity, self.info.planner_blocks)

    def _feedback_firmware(self, text: str) -> None:
        if self.info is not None and text.lower() == "grblhal":
            self.info = MachineInfo("grblhal", self.info.version, self.info.build, self.info.options,
                                    self.counter.capacity, self.info.planner_blocks)

    def _feedback_opt(self, text: str) -> None:
        parts = text.split(",")
        blocks = int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else None
        if len(parts) > 2 and parts[2].isdigit() and self.fixed_rx is None:
            self.counter.capacity = int(parts[2])
        base = self.info or MachineInfo("grbl", "")
        self.info = MachineInfo(base.flavour, base.version, base.build, text, self.counter.capacity, blocks)
        self._notify("on_machine_info", self.info)

    # ------------------------------------------------------------------ results, state, log

    def _command_done(self, result: CommandResult) -> None:
        if result.ok:
            self._after_command(result)
        then = self._then.pop(result.id, None)
        self.listener.on_command_done(result)
        if then is not None:
            then(result)

    def _after_command(self, result: CommandResult) -> None:
        if result.verb == "$$":
            self.settings = dict(self._settings_rows)
            self.answer_deferred()
            self.merger.inches = self.settings.get(13) == "1"
            self._notify("on_settings", SettingsEvent(tuple(self._settings_rows)))
        elif result.verb == "$H":
            self.homed, self.alarm = True, None
        elif result.verb == "$X":
            self.alarm = None
        elif "=" in result.verb and result.verb[1:].split("=")[0].isdigit():
            number, _, value = result.verb[1:].partition("=")
            self.settings[int(number)] = value
        self._settings_rows = [] if result.verb == "$$" else self._settings_rows

    def _link_lost(self, reason: str) -> None:
        self._error("LINK_LOST", msg("link to the machine lost: {reason}", reason=reason))
        for out in [o for o in self.counter.clear() if o.kind == "command"] + self._queue:
            self._command_done(CommandResult(out.index, out.text, ok=False, info=reason, code="LINK_LOST"))
        for cid, verb, args, _answer in self._deferred:
            self._command_done(CommandResult(cid, verb, args, ok=False, info=reason, code="LINK_LOST"))
        self._deferred.clear()
        for cid in self._asked_reports:
            self._command_done(CommandResult(cid, "?", (), ok=False, info=reason, code="LINK_LOST"))
        self._asked_reports.clear()
        self._queue.clear()
        self._job_link_lost(reason)

    def _silence_reason(self) -> str:
        return msg("no status report for {seconds:g} s", seconds=self.link.lost_s)

    def _emit_link(self, reason: str = "") -> None:
        silent = self.link.silent_for(self.clock()) if self.attached else 0.0
        self.listener.on_link_changed(LinkEvent(self.link.state.value, silent, 0.0, False, reason))

    def _notify(self, name: str, event) -> None:
        """A GRBL-only event, for a listener that has its method (a plain
        ``SessionListener`` does not)."""
        method = getattr(self.listener, name, None)
        if method is not None:
            method(event)

    def _end_job(self, completed: bool, reason: str) -> None:
        job, self.job = self.job, None
        if job is None:
            return
        self.last_job = job
        self.listener.on_progress(job.progress())
        self.listener.on_job_finished(JobEvent("job", completed, reason, job.done, job.total, job.name,
                                               job.refused))
        self._settle()

    def _settle(self) -> None:
        """No job: READY while attached (DISCONNECTED where the state table allows)."""
        target = S.READY if self.attached else S.DISCONNECTED
        if target in TRANSITIONS[self.state]:
            self._set_state(target)
