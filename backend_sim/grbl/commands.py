"""The simulated GRBL's ``$`` system commands and real-time bytes (a mixin of
``GrblMachine``), as GRBL 1.1's commands documentation describes them:

``$`` help, ``$$`` settings (not while a job runs or holds: error 8), ``$x=val`` and ``$#``
parameters (Idle or Alarm only, not Jog, Door or Check: error 8; a write keeps the machine
deaf while it writes its EEPROM, ``machine.EEPROM_WRITE_MS``),
``$G`` parser state, ``$I`` build info, ``$N`` startup lines (none stored), ``$C``
check mode (leaving it resets), ``$X`` unlock, ``$H`` homing (``$22`` off: error 5),
``$J=`` jog (G91/G90, G20/G21, G53, X Y Z and a required F; soft limits: error 15),
``$SLP``; anything else error 3. Real time: ``?`` report, ``~`` cycle start, ``!`` feed
hold (cancels a jog), 0x18 soft reset, 0x84 safety door, 0x85 jog cancel, 0x90-0x9D
overrides (feed and spindle 10-200 %, rapid 100/50/25 %). An override applies to the
moves planned after it (the motion model has no override of a move under way).
"""

from __future__ import annotations

import contextlib
import math

from backend_sim.grbl import reports
from backend_sim.grbl.parser import GrblError, clean, parse_block
from backend_sim.grbl.settings import check, format_setting
from backend_sim.motion.events import MotionError

HELP = "[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]"


class SystemCommands:
    # ------------------------------------------------------------------ $ commands

    def system_command(self, text: str) -> None:
        line = clean(text)
        if line.startswith("$J="):
            self._jog(line[3:])
            return
        if "=" in line and line[1:].split("=")[0].isdigit():
            self._write_setting(line)
            return
        handler = self.SYSTEM.get(line)
        if handler is None:
            self.write("error:3")
            return
        handler(self)

    def _help(self) -> None:
        self.write(HELP)
        self.write("ok")

    def _cycling(self) -> bool:
        """A job or a hold under way: GRBL refuses ``$$`` then (error 8: its print-out takes
        too long)."""
        return self.motion.state in ("RUN", "HOLD") or self.pending is not None or self.paused

    def _idle_or_alarm(self) -> bool:
        """GRBL's state is Idle or Alarm (not Run, Hold, Jog, Door or Check): what ``$#`` and a
        setting write need (error 8 otherwise)."""
        return (self.motion.state in ("IDLE", "ALARM") and self.pending is None and not self.paused
                and not self.check_mode and not self.door)

    def _print_settings(self) -> None:
        if self._cycling():
            self.write("error:8")
            return
        for number, value in sorted(self.settings.items()):
            self.write(format_setting(number, value))
        self.write("ok")

    def _write_setting(self, line: str) -> None:
        if not self._idle_or_alarm():
            self.write("error:8")
            return
        number, _, value = line[1:].partition("=")
        try:
            self.settings[int(number)] = check(self.settings, int(number), value)
        except ValueError as exc:
            self.write(f"error:{exc.args[0]}")
            return
        self.eeprom_until_ms = self.clock.now_ms + self.EEPROM_WRITE_MS  # "ok" once written

    def _print_parameters(self) -> None:
        if not self._idle_or_alarm():
            self.write("error:8")
            return
        for row in reports.parameters(self):
            self.write(row)
        self.write("ok")

    def _print_modes(self) -> None:
        self.write(f"[GC:{self.gcode.modes_text()}]")
        self.write("ok")

    def _print_build(self) -> None:
        self.write(f"[VER:{self.VERSION}.20190830:cnc-sim]")
        self.write(f"[OPT:V,{self.PLANNER_BLOCKS},{self.RX_BUFFER}]")
        self.write("ok")

    def _print_startup(self) -> None:
        self.write("$N0=")
        self.write("$N1=")
        self.write("ok")

    def _toggle_check(self) -> None:
        if self.motion.state != "IDLE" or self.locked:
            self.write("error:8" if not self.locked else "error:9")
            return
        if self.check_mode:
            self.write("[MSG:Disabled]")
            self.write("ok")
            self.soft_reset()
            return
        self.check_mode = True
        self.write("[MSG:Enabled]")
        self.write("ok")

    def _unlock(self) -> None:
        if self.locked:
            self.locked, self.alarm = False, None
            self.motion.clear_alarm()
            self.sync_position()
            self.write("[MSG:Caution: Unlocked]")
        self.write("ok")

    def _home(self) -> None:
        if not self.settings[22]:
            self.write("error:5")
            return
        if self.motion.state not in ("IDLE", "ALARM") or self.check_mode:
            self.write("error:8")
            return
        try:
            self.motion.home()
        except MotionError:
            self.write("error:8")

    def _sleep(self) -> None:
        self.write("[MSG:Sleeping]")
        self.write("ok")

    SYSTEM = {"$": _help, "$$": _print_settings, "$#": _print_parameters, "$G": _print_modes,
              "$I": _print_build, "$N": _print_startup, "$C": _toggle_check, "$X": _unlock,
              "$H": _home, "$SLP": _sleep}

    # ------------------------------------------------------------------ jog

    def _jog(self, words: str) -> None:
        if self.locked or self.door:
            self.write("error:9")
            return
        if self.motion.state not in ("IDLE", "JOG") or self.pending is not None:
            self.write("error:8")
            return
        try:
            target, feed = self._jog_target(words)
        except GrblError as exc:
            self.write(f"error:{exc.code}")
            return
        if self.settings[20] and self.homed and not self.within_travel(target):
            self.write("error:15")
            return
        machine = tuple(t + o for t, o in zip(target, self.origin, strict=True))
        if self.check_mode:
            self.write("ok")
            return
        self._plan([("jog", machine, feed)], "$J=" + words)

    def _jog_target(self, words: str):
        block = parse_block(words)
        if set(block.m) or set(block.g) - {"distance", "units", "non_modal"} or \
                block.g.get("non_modal", 530) != 530 or set(block.values) - set("XYZFN"):
            raise GrblError(16)
        if "F" not in block.values or not block.axes:
            raise GrblError(16)
        inches = block.g.get("units", 200 if self.gcode.inches else 210) == 200
        absolute = block.g.get("distance", 900 if self.gcode.absolute else 910) == 900
        scale = 25.4 if inches else 1.0
        machine = block.g.get("non_modal") == 530
        here = self.motion.planner.tail if self.motion.state == "JOG" else self.motion.commanded_mm
        here = [h - o for h, o in zip(here, self.origin, strict=True)]
        wco = (0.0, 0.0, 0.0) if machine else self.gcode.wco()
        target = list(here)
        for k, axis in enumerate("XYZ"):
            if axis in block.axes:
                value = block.axes[axis] * scale
                target[k] = value + wco[k] if absolute or machine else here[k] + value
        feed = block.values["F"] * scale
        if not (feed > 0 and all(math.isfinite(t) for t in target)):
            raise GrblError(33)
        return tuple(target), feed

    # ------------------------------------------------------------------ real time

    def _rt_status(self) -> None:
        self.report_due = True

    def _rt_cycle_start(self) -> None:
        if self.paused:
            self.paused = False
        elif self.door and not self.motion.cover_open:
            self.door = False
            self._resume_motion()
        elif self.motion.state == "HOLD":
            self._resume_motion()

    def _resume_motion(self) -> None:
        with contextlib.suppress(MotionError):
            self.motion.resume()

    def _rt_feed_hold(self) -> None:
        if self.motion.state in ("RUN", "JOG"):
            self.motion.feed_hold()
        elif self.motion.state == "IDLE" and (self.pending is not None or b"\n" in self.rx):
            self.paused = True  # hold before the next motion starts

    def _rt_reset(self) -> None:
        self.soft_reset()

    def _rt_door(self) -> None:
        self.set_door(True)

    def set_door(self, opened: bool) -> None:
        """The safety door switch (0x84 opens it; the simulator's API closes it)."""
        if opened:
            if self.motion.state == "HOMING":
                self.motion.stop()
                self._raise_alarm(7, critical=False)
                return
            self.door = True
            self.motion.cover_open = True
            self.write("[MSG:Check Door]")
        else:
            self.motion.cover_open = False
            if self.door:
                self.write("[MSG:Check Door]")

    def _rt_jog_cancel(self) -> None:
        if self.motion.state == "JOG":
            self.motion.stop()
            self.pending = None

    def _override(self, which: int, value: int | None, step: int = 0) -> None:
        old = self.overrides[which]
        new = 100 if value is None else value
        if step:
            new = max(10, min(200, old + step))
        if new != old:
            self.overrides[which] = new
            self.show_ov = True

    REALTIME = {
        ord("?"): _rt_status, ord("~"): _rt_cycle_start, ord("!"): _rt_feed_hold, 0x18: _rt_reset,
        0x84: _rt_door, 0x85: _rt_jog_cancel,
        0x90: lambda m: m._override(0, None), 0x91: lambda m: m._override(0, 0, 10),
        0x92: lambda m: m._override(0, 0, -10), 0x93: lambda m: m._override(0, 0, 1),
        0x94: lambda m: m._override(0, 0, -1),
        0x95: lambda m: m._override(1, 100), 0x96: lambda m: m._override(1, 50),
        0x97: lambda m: m._override(1, 25),
        0x99: lambda m: m._override(2, None), 0x9A: lambda m: m._override(2, 0, 10),
        0x9B: lambda m: m._override(2, 0, -10), 0x9C: lambda m: m._override(2, 0, 1),
        0x9D: lambda m: m._override(2, 0, -1),
    }
