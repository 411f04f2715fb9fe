"""The main MCU: relay between host (USB) and CNC MCU (UART), its own commands, watchdogs.

Contract:
- host frames: ``D`` and the commands that are not its own go down the UART (a
  forwarded command again every 50 ms while unanswered, for half a second); its own
  commands are ``PING``/``STATUS`` (answered with the last ``S`` of the CNC MCU, with
  the flags it owns: ``L``, ``U``, ``S``) and ``SD ...`` (``main_sd``). A repeated
  command id (the same as the last; ``PING``/``STATUS`` are never remembered) is not
  executed again: its answers are sent again, or, for a forwarded command not yet
  answered, it is forwarded again (the CNC MCU answers a repeated id from its cache).
  A bad host frame is answered ``N expected`` once per bad stretch, with
  ``expected`` mirrored from the stream (the CNC MCU's ``N`` for that same seq is
  not passed on twice). A resent ``D`` frame (seq at or below the highest relayed in
  this stream) goes down ahead of the new frames waiting for the UART
  (``Wire.write_priority``), so a gap is filled while the frames above it arrive. The
  relayed ``D`` frames are kept until the CNC MCU acknowledges them (``relay``): the
  CNC MCU's ``N`` for a kept frame, and 20 ms without an acknowledgement, send it down
  again (not passed up); a host's copy of a frame the CNC MCU has is answered with
  its last ``A``.
- ``R`` real-time commands go down ahead of every queue (``Wire.write_urgent``), sent
  again every 5 ms until the CNC MCU answers (``urgent.UrgentRelay``); a repeat of one
  still going down is dropped, of one answered gets the answer again. ``R STOP`` also
  abandons an upload and ends an SD job. ``!``/0x18 at the start of a line are counted
  and logged (``L ignored ...``), never acted on.
- CNC frames go up (``S`` with merged flags), except the answers to the main MCU's own
  commands (ids from ``OWN_ID0``) and, during ``SD RUN``, the stream's ``A``/``N``/``F``.
- heartbeat: 3 s without a valid host frame while connected (in link time,
  ``SimClock.link_now``: wall-clock seconds at any speed factor, so a host needs no
  knowledge of the factor) -> flag ``L``, ``X HOST_LOST``, LED blinks fast, buzzer
  beeps, a host job feed-holds (its own ``R HOLD LINK``; an SD job carries on). The
  UART hop likewise (it sends the CNC MCU a ``PING`` after 0.1 s without sending
  anything, and every 0.1 s while nothing has come back for 0.1 s): ``U``,
  ``X UART_LOST``; both ends of the
  UART are the machine's, so it runs on machine time. Until the host has sent one
  valid frame nothing goes up (as USB CDC with no host reading).
"""

from __future__ import annotations

import enum

from app.comm.deframer import Deframer, Dropped, Legacy
from app.comm.frame import (
    Ack,
    Alarm,
    Command,
    Data,
    Error,
    Frame,
    Info,
    Nak,
    Ok,
    RealtimeCommand,
    Status,
)
from backend_sim import main_sd
from backend_sim.answer_cache import AnswerCache
from backend_sim.outgoing import encode_fit
from backend_sim.relay import DataRelay, Reforward
from backend_sim.sd_card import SdCard
from backend_sim.urgent import LegacyCounter, UrgentRelay
from backend_sim.wire import Wire, to_ms

OWN_ID0 = 1_000_000_000


class LinkState(enum.Enum):
    """A link as the main MCU sees it: UNKNOWN (the host has never spoken), OK, LOST."""

    UNKNOWN = "unknown"
    OK = "ok"
    LOST = "lost"


PING_PERIOD_S = 0.1  # docs/protocol.md: lost pings must not make the CNC MCU hold as UART_LOST
SILENT_PING_S = 0.1
HOUSEKEEPING_S = 0.1


class MainMcu:
    def __init__(self, profile, clock, host_tx: Wire, uart_tx: Wire, sd: SdCard) -> None:
        self.profile, self.clock = profile, clock
        self.host_tx, self.uart_tx, self.sd = host_tx, uart_tx, sd
        self.lost_s = profile.link.lost_s
        self.menu = None
        self.boot()

    def boot(self) -> None:
        """Power-up or MRESET: links unknown, no upload, no SD job, nothing cached."""
        if getattr(self, "upload", None) is not None:
            self.upload.abort()
            self.sd.remove_partials()
        now = self.clock.now
        self.host_rx = Deframer(legacy=True)
        self.uart_rx = Deframer()
        self.urgent = UrgentRelay()
        self.legacy = LegacyCounter()
        self.host_link = LinkState.UNKNOWN
        self.uart_link = LinkState.OK
        self.last_host = self.clock.link_now
        self.last_uart = now
        self.next_ping = now + PING_PERIOD_S
        self.last_own_ping = now
        self.next_housekeeping = now + HOUSEKEEPING_S
        self.status: Status | None = None
        self.last_relayed: Status | None = None
        self.answers = AnswerCache()
        self.expected = 0
        self.relayed = -1
        self.relay = DataRelay()  # D frames relayed, not yet acknowledged by the CNC MCU
        self.nak_sent: int | None = None  # N sent in this bad stretch (the main MCU's or passed on)
        self.own_nak: int | None = None  # the N the main MCU sent itself, for a bad host frame
        self.upload = None
        self.sd_job = None
        self.own_id = OWN_ID0
        self.own_pending: dict[int, object] = {}
        self.reforward = Reforward()
        self.notice = "ready"

    # ------------------------------------------------------------------ time

    def next_due_ms(self) -> int:
        due = min(self.next_ping, self._silent_ping_at())
        if self.host_rx.pending() or self.uart_rx.pending():
            due = min(due, self.next_housekeeping)
        if self.uart_link is LinkState.OK:
            due = min(due, self.last_uart + self.lost_s)
        job_due = self.sd_job.next_due() if self.sd_job is not None else None
        others = (job_due, self.urgent.next_due(), self.legacy.next_due(),
                  self.reforward.next_due(self._answered), self.relay.next_due())
        for other in others:
            if other is not None and other < due:
                due = other
        due_ms = to_ms(due)
        if self.host_link is LinkState.OK:
            due_ms = min(due_ms, self.clock.ms_at_link(self.last_host + self.lost_s))
        return max(due_ms, self.clock.now_ms + 1)

    def service(self) -> None:
        now = self.clock.now
        if now >= self.next_housekeeping:
            self.next_housekeeping = now + HOUSEKEEPING_S
            if not (self.host_rx.pending() or self.uart_rx.pending()):
                return self._timers(now)
            self._host_items(self.host_rx.poll(now))
            self._uart_items(self.uart_rx.poll(now))
        return self._timers(now)

    def _silent_ping_at(self) -> float:
        """When to ask a CNC MCU that has said nothing for a second (every 0.25 s), even
        while D frames go down: a CNC MCU waiting out a gap is quiet, not lost."""
        return max(self.last_uart + PING_PERIOD_S, self.last_own_ping + SILENT_PING_S)

    def _timers(self, now: float) -> None:
        if now >= self.next_ping or now >= self._silent_ping_at():
            self.next_ping = now + PING_PERIOD_S
            self.last_own_ping = now
            self.send_cnc_own("PING", callback=None)
        for raw in self.urgent.due(now):
            self.uart_tx.write_urgent(raw, now)
        self._down_again(self.relay.probe(now))
        again = self.reforward.take(now, self._answered)
        if again is not None:
            self.to_cnc(again)
        said = self.legacy.report(now)
        if said is not None:
            self.to_host(said)
        self._watchdogs(now)
        if self.sd_job is not None:
            self.sd_job.poll(now)
            main_sd.check_job(self)

    def _watchdogs(self, now: float) -> None:
        if self.host_link is LinkState.OK and self.clock.link_now - self.last_host >= self.lost_s:
            self.host_link = LinkState.LOST
            self.notice = "HOST LOST"
            self.to_host(Alarm("HOST_LOST", f"no valid host frame for {self.lost_s:g} s"))
            main_sd.abandon_upload(self, "host lost")
            if self.sd_job is None and self.status is not None and self.status.state == "RUN":
                self.send_urgent_own("HOLD", "LINK")
        if self.uart_link is LinkState.OK and now - self.last_uart >= self.lost_s:
            self.uart_link = LinkState.LOST
            self.notice = "UART LOST"
            self.to_host(Alarm("UART_LOST", f"no frame from the CNC MCU for {self.lost_s:g} s"))
            self.to_host(self.merged_status())

    # ------------------------------------------------------------------ host side

    def receive_host(self, data: bytes) -> None:
        self._host_items(self.host_rx.feed(data, self.clock.now))

    def _host_items(self, items: list) -> None:
        for item in items:
            if isinstance(item, Legacy):
                self.legacy.seen()
            elif isinstance(item, Dropped):
                self._host_bad()
            else:
                self._host_alive()
                self._host_frame(item)

    def _host_alive(self) -> None:
        self.last_host = self.clock.link_now
        if self.host_link is LinkState.LOST:
            self.notice = "host back"
        self.host_link = LinkState.OK

    def _host_realtime(self, frame: RealtimeCommand) -> None:
        """An ``R`` frame of the host: down in the fast lane, once per id (docs/protocol.md)."""
        if self.urgent.forwarding(frame.id):
            return
        answers = self.urgent.recent.answers(frame.id)
        for raw in answers:
            self.host_tx.write(raw, self.clock.now)
        if answers or self.urgent.recent.remembers(frame.id):  # given up on: down again, no side effects
            if not answers:
                self._urgent_down(frame)
            return
        if frame.verb == "STOP":
            self._before_stop(frame)
        elif frame.verb == "RESET":
            self._before_reset(frame)
        self._urgent_down(frame)

    def send_urgent_own(self, verb: str, why: str) -> None:
        """The main MCU's own ``R`` frame (host lost, panel), with the reason it holds."""
        self.own_id += 1
        self._urgent_down(RealtimeCommand(self.own_id, verb, why))

    def _urgent_down(self, frame: RealtimeCommand) -> None:
        raw = encode_fit(frame)
        self.urgent.forward(frame, raw, self.clock.now)
        self.uart_tx.write_urgent(raw, self.clock.now)

    def _host_bad(self) -> None:
        if self.upload is not None:
            return main_sd.upload_bad_frame(self)
        if self.nak_sent is None:
            self.nak_sent = self.own_nak = self.expected
            self.to_host(Nak(self.expected))
        return None

    def _host_frame(self, frame: Frame) -> None:
        if isinstance(frame, RealtimeCommand):
            self._host_realtime(frame)
        elif isinstance(frame, Command):
            self._host_command(frame)
        elif isinstance(frame, Data):
            self._host_data(frame)

    def _host_data(self, frame: Data) -> None:
        if self.upload is not None:
            return main_sd.upload_data(self, frame)
        if self.sd_job is not None:
            return None
        if frame.seq == self.expected:
            self.expected += 1
            self.nak_sent = None
        raw, now = encode_fit(frame), self.clock.now
        if frame.seq <= self.relayed:  # a resend: answered here, or ahead of the new frames
            answers = self.relay.answer_for(frame.seq, now)
            for answer in answers:
                self.to_host(answer)
            if answers:
                return None
            self.relay.relayed(frame.seq, raw, now)
            return self._down_again(raw)
        self.relay.relayed(frame.seq, raw, now)
        self.relayed = frame.seq
        self.to_cnc(frame)
        return None

    def _down_again(self, raw: bytes | None) -> bool:
        """A ``D`` frame down again in the priority lane; False if there is none."""
        if raw is None:
            return False
        self.uart_tx.write_priority(raw, self.clock.now)
        self.next_ping = self.clock.now + PING_PERIOD_S
        return True

    def _host_command(self, cmd: Command) -> None:
        handler = _OWN.get(cmd.verb)
        if self.answers.remembers(cmd):
            return self._repeat(cmd, own=handler is not None)
        self.answers.start(cmd)
        if handler is not None:
            handler(self, cmd)
        else:
            self._forward(cmd)
        return None

    def _repeat(self, cmd: Command, own: bool) -> None:
        """A retry: the answers again, or a forwarded command not yet answered forwarded
        again (its first copy may have been lost on the UART; the CNC MCU deduplicates)."""
        for raw in self.answers.frames:
            self.host_tx.write(raw, self.clock.now)
        if not self.answers.answered and not own:
            self.to_cnc(cmd)

    @property
    def last_id(self) -> int | None:
        """The remembered host command id (answers to it are kept for a retry)."""
        return self.answers.id

    def _forward(self, cmd: Command) -> None:
        hook = _BEFORE_FORWARD.get(cmd.verb)
        if hook is not None and hook(self, cmd) is False:
            return
        self.to_cnc(cmd)
        self.reforward.start(cmd, self.clock.now)

    def _answered(self, cmd: Command) -> bool:
        """``cmd`` is answered, or no longer the remembered command."""
        return self.answers.id != cmd.id or self.answers.answered

    def _before_job(self, cmd: Command) -> bool:
        if self.sd_job is not None or self.upload is not None:
            self.answer(Error(cmd.id, "BUSY", "SD job or upload in progress"))
            return False
        self.expected, self.nak_sent, self.relayed = 0, None, -1
        self.relay.reset()
        return True

    def _before_resume(self, cmd: Command) -> bool:
        if cmd.args[:1] == ("FROM",) and len(cmd.args) == 2 and cmd.args[1].isdigit():
            self.expected, self.nak_sent = int(cmd.args[1]), None
            self.relayed = self.expected - 1
            self.relay.reset()
        return True

    def _before_stop(self, cmd: Command) -> bool:
        main_sd.abandon_upload(self, "stopped by host")
        if self.sd_job is not None:
            main_sd.stop_job(self, "stopped by host")
        return True

    def _before_reset(self, cmd: Command) -> bool:
        main_sd.abandon_upload(self, "reset")
        return True

    def _ping(self, cmd: Command) -> None:
        self.host_tx.write(encode_fit(self.merged_status()), self.clock.now)

    def answer(self, frame: Frame) -> None:
        """Send an answer to the last host command, and keep it for a repeated id."""
        raw = encode_fit(frame)
        self.answers.frames.append(raw)
        self.host_tx.write(raw, self.clock.now)

    def to_host(self, frame: Frame) -> None:
        if self.host_connected:
            self.host_tx.write(encode_fit(frame), self.clock.now)

    # ------------------------------------------------------------------ CNC side

    def to_cnc(self, frame: Frame) -> None:
        """Send down the UART; a PING follows after a second of silence (the CNC MCU's
        heartbeat, and the question whose answer shows the UART is alive)."""
        self.uart_tx.write(encode_fit(frame), self.clock.now)
        self.next_ping = self.clock.now + PING_PERIOD_S

    def send_cnc_own(self, verb: str, *args: str, callback=None) -> int:
        """Send one of the main MCU's own commands down; ``callback(frame)`` gets its O/E."""
        self.own_id += 1
        if callback is not None:
            self.own_pending[self.own_id] = callback
        self.to_cnc(Command(self.own_id, verb, tuple(args)))
        return self.own_id

    def receive_uart(self, data: bytes) -> None:
        self._uart_items(self.uart_rx.feed(data, self.clock.now))

    def _uart_items(self, items: list) -> None:
        for item in items:
            if isinstance(item, Frame):
                self._uart_alive()
                self._uart_frame(item)

    def _uart_alive(self) -> None:
        now = self.clock.now
        self.last_uart = now
        if self.uart_link is LinkState.LOST:
            self.uart_link = LinkState.OK
            self.notice = "UART back"

    def _uart_frame(self, frame: Frame) -> None:
        if isinstance(frame, Status):
            return self._cnc_status(frame)
        cid = getattr(frame, "id", None)
        if isinstance(frame, Ok | Error) and self.urgent.answered(cid, encode_fit(frame)):
            if cid < OWN_ID0:  # the host's R frame: its answer goes up
                self.to_host(frame)
            return None
        if isinstance(frame, Ok | Error | Info) and cid is not None and cid >= OWN_ID0:
            return self._own_answer(frame)
        if self.sd_job is not None and main_sd.job_frame(self, frame):
            return None
        if isinstance(frame, Nak):
            return self._cnc_nak(frame)
        if isinstance(frame, Ack):
            self.expected = max(self.expected, frame.seq + 1)
            self.relay.on_ack(frame, self.clock.now)
        if cid is not None and cid == self.last_id and isinstance(frame, Ok | Error | Info):
            return self.answer(frame)
        self.to_host(frame)
        return None

    def _cnc_nak(self, frame: Nak) -> None:
        if self.own_nak == frame.seq:  # named already for a bad host frame: not twice
            self.own_nak = None
            return
        self.expected, self.nak_sent = frame.seq, frame.seq
        if not self._down_again(self.relay.resend(frame.seq, self.clock.now)):  # the UART hop is its own
            self.to_host(frame)

    def _cnc_status(self, frame: Status) -> None:
        """Keep the CNC's status; pass it on unless it repeats the last one (ping answers)."""
        self.status = frame
        if self.sd_job is not None:
            self.sd_job.on_status(frame.free)
        merged = self.merged_status()
        if merged != self.last_relayed:
            self.last_relayed = merged
            self.to_host(merged)

    def _own_answer(self, frame: Frame) -> None:
        if isinstance(frame, Info):
            return
        callback = self.own_pending.pop(frame.id, None)
        if callback is not None:
            callback(frame)

    # ------------------------------------------------------------------ status, panel

    def flags(self) -> str:
        own = ("L" if self.host_lost else "") + ("U" if self.uart_lost else "")
        own += "S" if self.sd_job is not None else ""
        cnc = self.status.flags if self.status is not None else ""
        return "".join(f for f in "HCLUPSW" if f in cnc + own)

    def merged_status(self) -> Status:
        """The CNC MCU's last status with the main MCU's flags (boot ``0``: none yet)."""
        s = self.status or Status("0", "ALARM", 0.0, 0.0, 0.0, -1, -1, 0, 0)
        flags = self.flags()
        if flags == s.flags:
            return s
        return Status(s.boot, s.state, s.x, s.y, s.z, s.acc, s.done, s.free, s.rpm, flags, s.why)

    @property
    def host_connected(self) -> bool:
        """The host has sent a valid frame since power-up (it may be lost since)."""
        return self.host_link is not LinkState.UNKNOWN

    @property
    def host_lost(self) -> bool:
        return self.host_link is LinkState.LOST

    @property
    def uart_lost(self) -> bool:
        return self.uart_link is LinkState.LOST

    @property
    def alert(self) -> bool:
        return self.host_lost or self.uart_lost

    @property
    def led(self) -> bool:
        """Heartbeat: 1 Hz blink; fast 5 Hz blink while a link is lost."""
        period = 200 if self.alert else 1000
        return self._link_ms() % period < period // 2

    @property
    def buzzer(self) -> bool:
        """Beeps 200 ms every second while a link is lost."""
        return self.alert and self._link_ms() % 1000 < 200

    def _link_ms(self) -> int:
        return int(self.clock.link_now * 1000)


_OWN = {
    "PING": MainMcu._ping,
    "STATUS": MainMcu._ping,
    "SD": main_sd.command,
}

_BEFORE_FORWARD = {
    "JOB": MainMcu._before_job,
    "RESUME": MainMcu._before_resume,
    "STOP": MainMcu._before_stop,
    "RESET": MainMcu._before_reset,
}
