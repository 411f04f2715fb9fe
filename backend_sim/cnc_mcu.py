"""The CNC MCU's protocol layer around the motion controller (docs/protocol.md).

Contract: ``CncMcu`` receives the bytes the UART lands (``receive``), runs the motion
controller for whole milliseconds (``run``), then turns what happened into frames on
its UART TX wire (``service``). It owns the ``D`` stream of a job (expected seq, ``A``
with free slots, duplicates re-acked, gaps and bad CRCs answered ``N expected`` once per
bad stretch, every later seq seen missing named at once, a probe answered with what is
missing: ``job_stream``), reports ``F <seq>`` cumulatively as lines finish, and sends ``S`` on every
state change, on ``PING``/``STATUS`` and at least every 50 ms while moving. With nothing
from the main MCU for 3 s while moving it holds (``X UART_LOST``). A refused
line (``E - <code> <seq> <text>``) flushes the queue and ends the job. Commands are in
``cnc_commands``; ``R`` real-time commands are taken ahead of everything that arrived
with them, once per id (``urgent.RecentIds``). The status's ``why`` says why it holds,
stopped a job short or is in ALARM (``self.why``, set where that happens). ``!``/0x18
at the start of a line are counted and logged, never acted on. Nothing here knows
about the host or the SD card.
"""

from __future__ import annotations

import random
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass

from app.comm.deframer import Deframer, Dropped, Legacy
from app.comm.frame import Ack as AckFrame
from app.comm.frame import Alarm, Command, Data, Error, Finished, Frame, Log, Nak, Ok, RealtimeCommand, Status
from app.profile import MachineProfile
from backend_sim import cnc_commands, program_stops
from backend_sim.answer_cache import AnswerCache
from backend_sim.continuous_jog import ContinuousJog
from backend_sim.exec_log import ExecLog
from backend_sim.flash import Flash
from backend_sim.job_stream import JobStream, Verdict
from backend_sim.motion import events as ev
from backend_sim.motion.dialect import DialectError, DialectParser, soft_limit_violation
from backend_sim.motion.events import MotionError
from backend_sim.outgoing import encode_fit
from backend_sim.urgent import LegacyCounter, RecentIds
from backend_sim.wire import Wire

STATUS_PERIOD_MS = 50
CHECK_F_EVERY = 8
MOTION_CHUNK_MS = 50
ALARM_WHY = {"LIMIT": "LIMIT", "SOFT_LIMIT": "SOFT", "COVER_OPEN": "COVER", "UART_LOST": "UART"}
"""An alarm's ``why`` in the status; any other alarm is ``FAULT``."""


@dataclass
class Pending:
    """A command whose ``O`` waits for an event (``HOME`` -> Homed, ``PAUSE`` -> Held ...)."""

    id: int
    verb: str
    awaits: type
    info: str = ""


class CncMcu:
    """The CNC MCU: D stream, commands, motion controller, status reports."""

    def __init__(self, profile: MachineProfile, clock, tx: Wire, motion_factory: Callable,
                 exec_log: ExecLog, rng: random.Random, flash: Flash | None = None) -> None:
        self.profile, self.clock, self.tx = profile, clock, tx
        self.motion_factory = motion_factory
        self.exec_log = exec_log
        self.rng = rng
        self.flash = flash or Flash(None, profile.travel.work_offset())
        self.systems, self.wcs = self.flash.load_systems()  # G54..G59 offsets, the active one
        self.offset = self.systems[self.wcs]  # the active system's: every work position uses it
        self.lost_ms = round(profile.link.lost_s * 1000)
        self.cover_open = False
        self.stops = program_stops.StopSettings()
        self.answers = AnswerCache()
        self.legacy = LegacyCounter()
        self.taken: Counter = Counter()  # verbs carried out since power-up (``R HOLD`` for R frames)
        self.boot()

    # ------------------------------------------------------------------ life cycle

    def boot(self) -> None:
        """Power-up or reset: new boot id, position unknown, queue and job gone."""
        self.boot_id = f"{self.rng.getrandbits(32):08X}"
        if getattr(self, "mc", None) is None:
            self.mc = self.motion_factory()
        else:
            self.mc.reset()
        self.mc.events()
        self.mc.cover_open = self.cover_open
        self.rx = Deframer(legacy=True)
        self.recent = RecentIds()
        self.jogging = ContinuousJog(self)
        self.why = ""
        self.job = JobStream()
        self.job_mdi = False  # JOB <n> MDI: no after-job action at its end
        self.parser = DialectParser(self.offset, tuple(self.mc.commanded_mm))
        self.check_mode = False
        self.pending: list[Pending] = []
        self.lines: dict[int, str] = {}
        self.state = self.mc.state
        self.next_status = 0
        self._busy = True
        self.mc_ms = self.rx_ms = self.clock.now_ms
        self.last_frame_ms = self.clock.now_ms
        self.uart_lost = False
        self.send(Alarm("BOOT", self.boot_id))
        self.send_status()

    def reset(self) -> None:
        """The RESET button or command: same machine, new boot, position unknown."""
        self.catch_up()
        self.boot()

    # ------------------------------------------------------------------ time

    @property
    def busy(self) -> bool:
        """Whether the motion controller needs its 1 ms ticks."""
        return not self.mc.idle()

    def next_due_ms(self) -> int | None:
        """When the CNC MCU next needs the clock: the next motion chunk or status."""
        partial = self.rx_ms + 501 if self.rx.pending() else None
        said = self.legacy.next_due()
        if said is not None:
            said_ms = max(self.clock.now_ms + 1, int(said * 1000) + 1)
            partial = said_ms if partial is None else min(partial, said_ms)
        if not self._busy:
            return partial
        base = self.mc_ms
        due = min(base + MOTION_CHUNK_MS, max(self.next_status, base + 1))
        if not self.uart_lost:
            due = min(due, self.last_frame_ms + self.lost_ms)
        if (dead_man := self.jogging.next_due_ms()) is not None:
            due = min(due, max(dead_man, self.clock.now_ms + 1))
        return due if partial is None else min(due, partial)

    def wake(self) -> None:
        """The motion controller was changed from outside (panel, faults): tick it again."""
        self._busy = True

    def catch_up(self) -> None:
        """Bring the motion controller up to the clock (it may lag while only the main
        MCU or the wires have something to do) and handle what it reports."""
        now = self.clock.now_ms
        if now > self.mc_ms:
            if self._busy:
                self.mc.advance(now - self.mc_ms)
            self.mc_ms = now
        self.service()

    def service(self) -> None:
        self._drain_events()
        self.jogging.tick()
        said = self.legacy.report(self.clock.now)
        if said is not None:
            self.send(said)
        if self.rx.pending():
            self._frames(self.rx.poll(self.clock.now))
        self._busy = busy = not self.mc.idle()
        if busy and self.clock.now_ms >= self.next_status:
            self.send_status()
        if busy and not self.uart_lost and self.clock.now_ms - self.last_frame_ms >= self.lost_ms:
            self._uart_silent()

    def _uart_silent(self) -> None:
        """Nothing from the main MCU for ``lost_s``: hold a running job on the path."""
        self.uart_lost = True
        if self.mc.state in ("RUN", "JOG"):
            self.mc.feed_hold()
            self.why = "UART"
        self.send(Alarm("UART_LOST", f"nothing from the main MCU for {self.lost_ms / 1000:g} s"))

    # ------------------------------------------------------------------ input

    def receive(self, data: bytes) -> None:
        self.catch_up()
        self.rx_ms = self.clock.now_ms
        self._frames(self.rx.feed(data, self.clock.now))
        self._busy = not self.mc.idle()

    def _frames(self, items: list) -> None:
        """Handle what arrived: ``R`` frames first (the fast lane), then the rest in order."""
        urgent = [item for item in items if isinstance(item, RealtimeCommand)]
        for item in urgent + [item for item in items if not isinstance(item, RealtimeCommand)]:
            _INPUT[type(item)](self, item)
        self._drain_events()

    def _on_legacy(self, item: Legacy) -> None:
        self.legacy.seen()

    def _on_dropped(self, item: Dropped) -> None:
        if self.job.open and self.job.bad_frame() is Verdict.NAK:
            self.send(Nak(self.job.expected))

    def _on_frame(self, frame: Frame) -> None:
        self.last_frame_ms = self.clock.now_ms
        self.uart_lost = False
        if isinstance(frame, RealtimeCommand):
            self._on_realtime_command(frame)
        elif isinstance(frame, Command):
            self._on_command(frame)
        elif isinstance(frame, Data):
            self._on_data(frame)

    def _on_command(self, cmd: Command) -> None:
        """Carry out ``cmd`` once; a repeated id gets the answers it already had (or,
        still running, the answer when it comes)."""
        if self.answers.remembers(cmd):
            for raw in self.answers.frames:
                self.tx.write(raw, self.clock.now)
            return
        self.answers.start(cmd)
        self.taken[cmd.verb] += 1
        cnc_commands.dispatch(self, cmd)

    def _on_realtime_command(self, frame: RealtimeCommand) -> None:
        """Carry out an ``R`` frame once per id; a repeat gets its answer again."""
        if self.recent.remembers(frame.id):
            for raw in self.recent.answers(frame.id):
                self.tx.write(raw, self.clock.now)
            return
        self.recent.start(frame.id)
        self.taken[f"R {frame.verb}"] += 1
        cnc_commands.realtime(self, frame)

    def _on_data(self, frame: Data) -> None:
        if not self.job.open:
            if frame.seq >= self.job.expected:  # below: a late copy of a line it took
                self.send(Error(None, "BAD_SEQ", f"{frame.seq} no job open"))
            return
        verdict = self.job.offer(frame.seq)
        if verdict is Verdict.REACK:
            self.send(AckFrame(self.job.expected - 1, self.free_slots()))
            missing = self.job.after_duplicate()
            if missing is not None:
                self.send(Nak(missing))
        elif verdict in (Verdict.NAK, Verdict.QUIET):
            holes = self.job.keep(frame.seq, frame.line, self.free_slots())  # selective repeat
            for seq in [self.job.expected] * (verdict is Verdict.NAK) + holes:
                self.send(Nak(seq))
        elif verdict is Verdict.QUEUE:
            self._queue_line(frame.seq, frame.line)
            self._queue_kept()

    def _queue_kept(self) -> None:
        """Queue the frames kept above a gap that was just filled (one ``A`` for them
        all, so its round trip is the resent frame's); ``N`` for the next gap."""
        kept = self.job.take() if self.job.open else None
        taken = kept is not None
        while kept is not None:
            self._queue_line(*kept, ack=False)
            kept = self.job.take() if self.job.open else None
        if taken and self.job.open or taken and self.job.acc == self.job.total - 1:
            self.send(AckFrame(self.job.acc, self.free_slots()))
        if self.job.open and self.job.gap_remains():
            self.send(Nak(self.job.expected))

    def _queue_line(self, seq: int, line: str, ack: bool = True) -> None:
        if seq >= self.job.total:
            return self.refuse_line(seq, "BAD_SEQ", f"beyond JOB {self.job.total}")
        if not self.check_mode and self.mc.free_slots() < program_stops.slots_needed(line):
            self.send(Nak(seq))
            return None
        start = self.parser.position
        try:
            move = self.parser.parse(seq, line)
        except DialectError as exc:
            return self.refuse_line(seq, exc.code, exc.text)
        if move.kind == "stop" and not self.check_mode:
            return self._queue_stop(move, line)
        violation = soft_limit_violation(start, move, self.profile.travel)
        if violation:
            return self.refuse_line(seq, "SOFT_LIMIT", violation)
        if move.moves_axes and not self.mc.homed and not self.check_mode:
            return self.refuse_line(seq, "NOT_HOMED", "home first")
        if not self.check_mode:
            try:
                self.mc.enqueue(move)
            except MotionError as exc:
                return self.refuse_line(seq, exc.code, exc.text)
            self.lines[seq] = line
        self.job.accepted(seq)
        if ack:
            self.send(AckFrame(seq, self.free_slots()))
        if self.check_mode:  # validated and finished at once: the dry run's executed log
            self.exec_log.add(seq, line)
            self._finished_up_to(seq, report=seq % CHECK_F_EVERY == CHECK_F_EVERY - 1)
        return None

    def _queue_stop(self, move, line: str) -> None:
        """A program stop: its moves (``program_stops.expand``) into the motion queue."""
        clearance = self.profile.travel.limits()[2][1]
        try:
            for part in program_stops.expand(move, self.parser, self.stops, clearance):
                self.mc.enqueue(part)
        except MotionError as exc:
            return self.refuse_line(move.seq, exc.code, exc.text)
        self.lines[move.seq] = line
        self.job.accepted(move.seq)
        self.send(AckFrame(move.seq, self.free_slots()))
        return None

    def refuse_line(self, seq: int, code: str, text: str) -> None:
        """``E - code seq text``: the line is refused, the queue flushed, the job ended."""
        self.why = "SOFT" if code == "SOFT_LIMIT" else "LINE"
        self.send(Error(None, code, f"{seq} {text}"))
        self.stop_job()

    # ------------------------------------------------------------------ motion events

    def _drain_events(self) -> None:
        finished = -2
        for event in self.mc.events():
            if isinstance(event, ev.Finished):
                finished = max(finished, self._on_finished(event))
                continue
            if finished >= -1:
                self._finished_up_to(finished)
                finished = -2
            _EVENTS[type(event)](self, event)
        if finished >= -1:
            self._finished_up_to(finished)
        if self.exec_log.failure is not None:
            self._exec_log_failed(self.exec_log.take_failure())

    def _exec_log_failed(self, text: str) -> None:
        """The record of executed lines cannot be written: the job stops, said once."""
        self.send(Alarm("EXEC_LOG", text))
        if self.job.open:
            self.stop_job()
            self.why = "FAULT"

    def _on_finished(self, event: ev.Finished) -> int:
        if event.seq < 0 or event.seq not in self.lines:
            return -2
        self.exec_log.add(event.seq, self.lines.pop(event.seq))
        return event.seq

    def _finished_up_to(self, seq: int, report: bool = True) -> None:
        """Lines up to ``seq`` finished: ``F`` (cumulative; in check mode only every
        ``CHECK_F_EVERY`` lines and the last, where every line finishes at once)."""
        last = self.job.finished(seq)
        if report or last:
            self.send(Finished(self.job.done))
        if last and self.job.open:
            self.why = ""
            self.job.close()
            self.send(Log(f"job done, {self.job.total} lines"))
            if not (self.check_mode or self.job_mdi):
                program_stops.after_job(self.mc, self.stops, self.offset, self.profile)
            self.send_status()

    def _on_alarm(self, event: ev.Alarm) -> None:
        self.send(Alarm(event.code, event.text))
        if event.code == "COVER_OPEN":
            if self.job.open or self.mc.state != "IDLE":
                self.why = "COVER"
            return self._cover_opened(event)
        self.why = ALARM_WHY.get(event.code, "FAULT")
        for pending in self.pending:
            self.send(Error(pending.id, event.code, event.text))
        self.pending.clear()
        self.job.close()
        self.lines.clear()

    def _on_program_stop(self, event: ev.ProgramStop) -> None:
        self.why = "PROG"
        self.send(Log(f"STOP {event.seq} {event.line}"))
        self.send_status()

    def _cover_opened(self, event: ev.Alarm) -> None:
        """Homing, a jog or a spindle command cut short by the cover: refused, at once."""
        for pending in [p for p in self.pending if p.verb in ("HOME", "JOG", "SPINDLE")]:
            self.pending.remove(pending)
            self.send(Error(pending.id, "COVER_OPEN", f"{pending.verb} stopped: {event.text}"))

    def _on_state(self, event: ev.StateChanged) -> None:
        self.state = event.state
        if event.state == "IDLE" or self.mc.waiting is not None and event.state in ("RUN", "HOLD"):
            self._on_done_event(event)  # a jog's answer (also a touch-off jog's at a stop)
        self.send_status()

    def _on_done_event(self, event) -> None:
        kind = type(event)
        for pending in [p for p in self.pending if p.awaits is kind]:
            self.pending.remove(pending)
            self.send(Ok(pending.id, pending.verb, pending.info))
        if kind is ev.Homed:
            self.reset_parser()

    # ------------------------------------------------------------------ helpers

    def await_event(self, cid: int, verb: str, awaits: type, info: str = "") -> None:
        self.pending.append(Pending(cid, verb, awaits, info))

    def stop_job(self) -> None:
        self.mc.stop()
        self.job.close()
        self.lines.clear()
        self.reset_parser()

    def reset_parser(self) -> None:
        self.parser = DialectParser(self.offset, tuple(self.mc.commanded_mm))

    def free_slots(self) -> int:
        return self.mc.free_slots() if not self.check_mode else self.mc.capacity

    def flags(self) -> str:
        flags = "H" if self.mc.homed else ""
        flags += "C" if self.cover_open else ""
        flags += "P" if self.mc.spindle_on else ""
        flags += "W" if self.mc.waiting is not None else ""
        return flags

    def status(self) -> Status:
        pos = self.mc.measured_mm
        x, y, z = (pos[k] - self.offset[k] for k in range(3))
        state = "HOLD" if self.mc.waiting is not None and self.mc.state != "JOG" else self.mc.state
        return Status(self.boot_id, state, x, y, z, self.job.acc, self.job.done,
                      self.free_slots(), int(round(self.mc.spindle_rpm)), self.flags(), self.why,
                      self.mc.overrides.as_tuple())

    def send_status(self) -> None:
        self.send(self.status())
        self.next_status = self.clock.now_ms + STATUS_PERIOD_MS

    def send(self, frame: Frame) -> None:
        raw = encode_fit(frame)
        self.answers.record(frame, raw)
        if isinstance(frame, Ok | Error):
            self.recent.record(frame.id, raw)
        self.tx.write(raw, self.clock.now)

    def set_cover(self, is_open: bool) -> None:
        self.catch_up()
        self.cover_open = is_open
        self.mc.cover_open = is_open
        self._drain_events()
        self.send_status()


_INPUT = {cls: CncMcu._on_frame for cls in Frame.__subclasses__()}
_INPUT.update({Legacy: CncMcu._on_legacy, Dropped: CncMcu._on_dropped})

_EVENTS = {
    ev.Alarm: CncMcu._on_alarm,
    ev.StateChanged: CncMcu._on_state,
    ev.Homed: CncMcu._on_done_event,
    ev.Held: CncMcu._on_done_event,
    ev.Stopped: CncMcu._on_done_event,
    ev.ProgramStop: CncMcu._on_program_stop,
}
