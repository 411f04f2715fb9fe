"""The simulated GRBL 1.1 controller: receive buffer, line handling, ``$`` commands,
real-time bytes, alarms and reports, over this project's motion model.

Contract: ``GrblMachine(profile, clock, out_wire, motion)``; ``receive(bytes)`` takes
bytes as they land (real-time bytes are picked off at once and never buffered; the rest
fills a ``RX_BUFFER``-byte receive buffer, and bytes beyond it are lost as on the real
part); ``service()`` (the simulator calls it at every event and at ``next_due_ms``)
reads lines, plans them, runs the motion to the clock and answers. A line is read out
of the buffer when the machine parses it; a motion line is answered ``ok`` once it is in
the planner (``PLANNER_BLOCKS``), so a full planner stops the reading and the receive
buffer fills: the host's character counting is what keeps it from overflowing. A dwell
(``G4``) is answered when it has run, after everything before it (so ``G4 P0`` is a
sync). A reset clears the parser state, G92's offset with it (GRBL 1.1's ``gc_init``),
and keeps the G54-G59 offsets (EEPROM). Machine position (``MPos``) is the motion
model's measured millimetres minus ``origin`` (the travel's far corner), so the machine
space is ``[-$13x, 0]``.
A setting write (``$x=val``) stores to EEPROM for ``EEPROM_WRITE_MS``, with the serial
interrupt off as on the real part: every byte that lands meanwhile, real-time bytes too,
is lost (``lost_to_eeprom``), and the ``ok`` comes after the write.
"""

from __future__ import annotations

import contextlib

from backend_sim.grbl import reports
from backend_sim.grbl.commands import SystemCommands
from backend_sim.grbl.execute import GcodeState
from backend_sim.grbl.parser import MAX_LINE, GrblError, parse_block
from backend_sim.grbl.settings import DEFAULTS
from backend_sim.motion.dialect import Move
from backend_sim.motion.events import Alarm, Finished, Homed, MotionError

RX_BUFFER = 128
PLANNER_BLOCKS = 15
EEPROM_WRITE_MS = 25  # an ATmega328P writes an EEPROM byte in about 3.4 ms
VERSION = "1.1h"
WELCOME = f"Grbl {VERSION} ['$' for help]"
STATES = {"IDLE": "Idle", "RUN": "Run", "HOLD": "Hold", "JOG": "Jog", "HOMING": "Home", "ALARM": "Alarm"}


class GrblMachine(SystemCommands):
    """See the module docstring."""

    VERSION, PLANNER_BLOCKS, RX_BUFFER, EEPROM_WRITE_MS = VERSION, PLANNER_BLOCKS, RX_BUFFER, EEPROM_WRITE_MS

    def __init__(self, profile, clock, out_wire, motion) -> None:
        self.profile, self.clock, self.out_wire = profile, clock, out_wire
        self.settings = dict(DEFAULTS)
        t = profile.travel
        self.origin = (t.x_max, t.y_max, t.z_max)
        self.motion = motion
        self.gcode = GcodeState()
        self.gcode.offsets[0] = [t.work_x - t.x_max, t.work_y - t.y_max, t.work_z - t.z_max]
        self.rx = bytearray()
        self.overflowed = 0  # bytes lost to a full receive buffer
        self.lost_to_eeprom = 0  # bytes that landed while a setting was being written
        self.eeprom_until_ms: int | None = None  # a setting write in progress until then
        self.executed: list[str] = []  # every G-code line accepted (tests: each line once)
        self.report_due = False
        self.pending: tuple | None = None  # (actions, line) waiting for the planner
        self.waiting_seq: int | None = None  # a dwell/home answered when it finishes
        self.overrides = [100, 100, 100]
        self.report_count = 0
        self.show_wco = self.show_ov = True
        self._seq = 0
        self.speed_mm_min = 0.0
        self._last_ms = clock.now_ms
        self._last_state = motion.state
        self.power_up()

    # ------------------------------------------------------------------ resets

    def power_up(self) -> None:
        self.homed = False
        self.door = False
        self._restart(alarm=None, locked=bool(self.settings[22]))

    def _restart(self, alarm: int | None, locked: bool) -> None:
        """What a reset leaves: empty buffers, default modes, the welcome line."""
        self.rx.clear()
        self.pending, self.waiting_seq = None, None
        self.gcode = GcodeState(offsets=self.gcode.offsets)  # G54-G59 are in EEPROM; G92 is not
        self.sync_position()
        self.check_mode = False
        self.paused = False  # an M0 waiting for cycle start
        self.critical = False
        self.alarm = alarm
        self.locked = locked or alarm is not None
        self.show_wco = self.show_ov = True
        self.overrides = [100, 100, 100]  # GRBL starts every reset at 100 %
        self.eeprom_until_ms = None
        self.write("\r\n" + WELCOME)
        if self.door:
            self.write("[MSG:Check Door]")
        if self.locked:
            self.write("[MSG:'$H'|'$X' to unlock]")

    def soft_reset(self) -> None:
        moving = self.motion.state in ("RUN", "JOG", "HOMING") or (
            self.motion.state == "HOLD" and not self.motion.job.held_flag)
        homing = self.motion.state == "HOMING"
        if moving:
            self.motion._alarm("RESET", "reset while moving")  # halts where it is
            self.motion.events()
        else:
            self.motion.stop()
            self.motion.events()
        alarm = (6 if homing else 3) if moving else self.alarm if self.critical else None
        self._restart(alarm, locked=alarm is not None or (self.locked and not self.homed and
                                                          bool(self.settings[22])))
        if alarm is not None:
            self.homed = False
            self.write(f"ALARM:{alarm}")

    # ------------------------------------------------------------------ bytes in

    def receive(self, data: bytes) -> None:
        if self.eeprom_until_ms is not None:
            self.lost_to_eeprom += len(data)
            return
        for byte in data:
            handler = self.REALTIME.get(byte)
            if handler is not None:
                handler(self)
            elif len(self.rx) < RX_BUFFER:
                self.rx.append(byte)
            else:
                self.overflowed += 1

    def write(self, text: str) -> None:
        self.out_wire.write(text.encode("ascii") + b"\r\n", self.clock.now)

    # ------------------------------------------------------------------ time

    def next_due_ms(self) -> int | None:
        if self.eeprom_until_ms is not None:
            return self.eeprom_until_ms
        if self.report_due or (self.pending is None and b"\n" in self.rx and not self.paused):
            return self.clock.now_ms
        if not self.motion.idle():
            return self.clock.now_ms + 5
        return None

    def service(self) -> None:
        now = self.clock.now_ms
        if self.eeprom_until_ms is not None:
            if now < self.eeprom_until_ms:
                return
            self.eeprom_until_ms = None
            self.write("ok")
        if now > self._last_ms:
            before = self.motion.commanded_mm
            self.motion.advance(now - self._last_ms)
            after = self.motion.commanded_mm
            step = sum((a - b) ** 2 for a, b in zip(after, before, strict=True)) ** 0.5
            self.speed_mm_min = step / (now - self._last_ms) * 60000
            self._last_ms = now
        self._motion_events()
        while self._read_line():
            pass
        if self.report_due:
            self.report_due = False
            if not self.critical and self.motion.state != "HOMING":
                self.write(reports.status_report(self))

    def _read_line(self) -> bool:
        """Take and handle one line if the machine can; False when it must wait."""
        if self.pending is not None and not self._plan(*self.pending):
            return False
        if self.waiting_seq is not None or self.paused or self.critical:
            return False  # after a hard or soft limit GRBL reads nothing until it is reset
        end = self.rx.find(b"\n")
        if end < 0:
            return False
        raw = bytes(self.rx[:end]).rstrip(b"\r")
        del self.rx[: end + 1]
        self._line(raw.decode("latin-1"))
        return True

    def _line(self, text: str) -> None:
        if not text.strip():
            self.write("ok")
            return
        if len(text) + 1 > MAX_LINE:
            self.write("error:11")
            return
        if text.lstrip().startswith("$"):
            self.system_command(text.strip())
            return
        if self.locked or self.motion.state in ("JOG", "HOMING"):
            self.write("error:9")
            return
        if self.door:
            self.write("error:13")
            return
        try:
            actions = self.gcode.execute(parse_block(text))
        except GrblError as exc:
            self.write(f"error:{exc.code}")
            return
        self.executed.append(text)
        if self.check_mode:
            self.write("ok")
            return
        if self._soft_limit(actions):
            return
        if self._plan(actions, text):
            pass

    # ------------------------------------------------------------------ planning

    def _plan(self, actions, line) -> bool:
        """Queue ``actions``; False (kept pending) while the planner is full."""
        needed = sum(1 for a in actions if a[0] in ("move", "spindle", "dwell", "jog"))
        if needed and self.motion.free_slots() < needed:
            self.pending = (actions, line)
            return False
        if any(a[0] in ("dwell", "pause", "end") for a in actions) and not self.motion.idle():
            self.pending = (actions, line)  # a dwell, M0, M2 wait for the planner to empty
            return False
        self.pending = None
        answer_later = False
        for action in actions:
            answer_later |= self._act(action)
        if not answer_later:
            self.write("ok")
        return True

    def _act(self, action) -> bool:
        kind = action[0]
        if kind == "move":
            _, how, target, feed, arc = action
            self._enqueue(self._move(how, target, feed, arc))
        elif kind == "spindle":
            rpm = action[1] * self.overrides[2] / 100
            self._enqueue(Move(self._next_seq(), "spindle", self.motion.tail_mm, rpm=rpm))
        elif kind == "dwell":
            self.waiting_seq = self._next_seq()
            self._enqueue(Move(self.waiting_seq, "dwell", self.motion.tail_mm, seconds=action[1]))
            return True
        elif kind == "jog":
            if self.motion.state not in ("IDLE", "JOG"):
                self.write("error:8")
                return True
            self.motion.planner.add(Move(-1, "line", action[1], feed=action[2], source="jog"))
            self.motion._set_state("JOG")
        elif kind == "pause":
            self.paused = True
        elif kind == "end":
            self.write("[MSG:Pgm End]")
            self.overrides = [100, 100, 100]
            self.show_ov = True
        return False

    def _move(self, how: str, target, feed: float, arc) -> Move:
        machine = tuple(t + o for t, o in zip(target, self.origin, strict=True))
        if how == "rapid":
            rate = min(self.settings[110], self.settings[111], self.settings[112])
            return Move(self._next_seq(), "rapid", machine, feed=rate * self.overrides[1] / 100)
        feed = feed * self.overrides[0] / 100
        if how == "line":
            return Move(self._next_seq(), "line", machine, feed=feed)
        (cx, cy), clockwise = arc
        centre = (cx + self.origin[0], cy + self.origin[1])
        return Move(self._next_seq(), "arc", machine, feed=feed, center=centre, clockwise=clockwise)

    def _enqueue(self, move: Move) -> None:
        with contextlib.suppress(MotionError):  # an alarm stopped everything meanwhile:
            self.motion.enqueue(move)  # the line is lost, as GRBL's would be

    def _next_seq(self) -> int:
        self._seq += 1
        return self._seq

    def _soft_limit(self, actions) -> bool:
        if not self.settings[20] or not self.homed:
            return False
        for action in actions:
            if action[0] == "move" and not self.within_travel(action[2]):
                self.motion.feed_hold()
                self._raise_alarm(2, critical=True)
                return True
        return False

    def within_travel(self, target) -> bool:
        return all(-self.settings[130 + k] - 1e-6 <= target[k] <= 1e-6 for k in range(3))

    # ------------------------------------------------------------------ motion events

    def _motion_events(self) -> None:
        for event in self.motion.events():
            if isinstance(event, Finished) and event.seq == self.waiting_seq:
                self.waiting_seq = None
                self.write("ok")
            elif isinstance(event, Homed):
                self.homed, self.locked, self.alarm = True, False, None
                self.sync_position()
                self.write("ok")
            elif isinstance(event, Alarm):
                self._motion_alarm(event)
        state = self.motion.state
        if self._last_state in ("JOG", "HOMING") and state in ("IDLE", "ALARM"):
            self.sync_position()  # a jog or homing moved the machine under the parser
        self._last_state = state

    def sync_position(self) -> None:
        """The parser's position is where the machine stands (after a jog, homing, a reset)."""
        self.gcode.position = [c - o for c, o in zip(self.motion.commanded_mm, self.origin, strict=True)]

    def _motion_alarm(self, event: Alarm) -> None:
        if event.code == "COVER_OPEN" or self.critical:
            return
        code = {"LIMIT": 1, "HOMING_FAILED": 9}.get(event.code, 1)
        self._raise_alarm(code, critical=code == 1)

    def _raise_alarm(self, code: int, critical: bool) -> None:
        self.alarm, self.locked, self.homed = code, True, False if code != 2 else self.homed
        self.critical = critical
        self.pending, self.waiting_seq = None, None
        self.sync_position()
        self.write(f"ALARM:{code}")
        if critical:
            self.write("[MSG:Reset to continue]")

    def mpos(self) -> tuple[float, float, float]:
        return tuple(m - o for m, o in zip(self.motion.measured_mm, self.origin, strict=True))

    def state_name(self) -> str:
        if self.alarm is not None or self.motion.state == "ALARM" or self.locked:
            return "Alarm"
        if self.door:
            return "Door:1" if self.motion.cover_open else "Door:0"
        if self.check_mode:
            return "Check"
        state = self.motion.state
        if state == "HOLD" or self.paused:
            return "Hold:0" if self.paused or self.motion.job.held_flag else "Hold:1"
        if state == "IDLE" and (self.pending is not None or self.waiting_seq is not None):
            return "Run"
        return STATES.get(state, "Idle")
