"""Commands of ``MotionController`` (queue, hold/resume/stop, homing, jog, parameters, faults).

Split from ``controller.py`` to keep both short; the mixin relies on the controller's
state (``axes``, ``planner``, ``job``, ``state``...) and its helpers (``_set_state``,
``_alarm``...). Refusals raise ``MotionError(code, text)``; bad parameters ``ValueError``.
"""

from __future__ import annotations

import math

from backend_sim.motion import servo
from backend_sim.motion.dialect import Move, soft_limit_violation
from backend_sim.motion.events import Alarm, Finished, Homed, MotionError, ProgramStop, StateChanged, Stopped
from backend_sim.motion.homing import Homing
from backend_sim.motion.overrides import Overrides

_S = {name: n for n, name in enumerate(servo.STATE)}
_PARAMS = {"KP": ("kp", 0.0, 1e4, 1.0), "KI": ("ki", 0.0, 1e5, 1e-3), "KD": ("kd", 0.0, 1e3, 1.0)}
_END_SETTLE_MS = 1000
_SPINDLE_MAX_WAIT_MS = 4000


class ControllerOps:
    # -- jobs ---------------------------------------------------------------------------
    def enqueue(self, move: Move) -> None:
        """Queue a parsed move; raises MotionError when full, in ALARM or while homing/jogging."""
        if self.state == "ALARM":
            raise MotionError("ALARM", "clear the alarm first")
        if self.state == "HOMING" or self.state == "JOG" and self.parked is None or self.stopping:
            raise MotionError("BUSY", f"machine is {'stopping' if self.stopping else self.state}")
        if self.free_slots() <= 0:
            raise MotionError("QUEUE_FULL", f"all {self.capacity} slots in use")
        if move.seq == 0:
            self.done_seq = -1  # a new stream
        if self.parked is not None:  # a touch-off jog runs: the move waits with the job
            self.parked.append(move)
            return
        self.job.add(move)
        if self.state == "IDLE":
            if self._cover:
                self.job.hold()
                self._set_state("HOLD")
            else:
                self.job.resume()
                self._set_state("RUN")

    def feed_hold(self) -> None:
        """RUN: decelerate on the path and stop (``Held`` when at rest). JOG: cancel the
        jog; HOMING: stop homing (``Stopped`` when at rest)."""
        if self.state == "RUN":
            self.job.hold()
            self._set_state("HOLD")
        elif self.state == "JOG":
            self.end_jog()
        elif self.state == "HOMING":
            self.stop()

    def resume(self, release_stop: bool = True) -> None:
        """Leave a feed hold, and (``release_stop``) go on past a program stop the job waits at."""
        release_stop = release_stop and self.waiting is not None
        if self.state != "HOLD" and not release_stop:
            return
        if self._cover:
            raise MotionError("COVER_OPEN", "close the cover to resume")
        if release_stop:
            self.return_moves()
            self.waiting = None
            if self.state == "HOLD":
                self.job.hold()  # the way back waits for the resume below
        if self.state != "HOLD":
            return
        if self.cover_rpm > 0:  # the cover stopped the spindle: back to speed first
            rpm, self.cover_rpm = self.cover_rpm, 0.0
            self.spindle_target = rpm
            self._drive_spindle()
            self.spin_up = (rpm, self.now_ms)
            self.wake()
            self._update_watch()
            return
        self.job.resume()
        self._set_state("RUN")

    def spun_up(self) -> bool:
        """While ``resume`` waits for the spindle: True once at speed (the job goes on)."""
        rpm, since = self.spin_up
        ready = self.spindle.ready(self.now_ms, self.overrides.spindle_rpm(rpm))
        if not (ready or self.now_ms - since > _SPINDLE_MAX_WAIT_MS):
            return False
        self.spin_up = None
        self.job.resume()
        self._set_state("RUN")
        return True

    def stop(self) -> None:
        """Decelerate on the path, then flush the queue and switch the spindle off (``Stopped``)."""
        if self.state in ("IDLE", "ALARM"):
            self.job.flush()
            self._spindle_off()
            self._events.append(Stopped())
            return
        if self.state == "HOMING":
            self.homing = None
        self.active.hold()
        self.stopping = True
        self._update_watch()

    def _finish_stop(self) -> None:
        self.stopping = False
        self.waiting = self.parked = None
        self.spin_up, self.cover_rpm = None, 0.0
        self.job.flush()
        self.planner.flush()
        self.job.resume()
        self.planner.resume()
        self._spindle_off()
        self._set_state("IDLE")
        self._events.append(Stopped())

    # -- homing and jog -------------------------------------------------------------
    def home(self, mode: str = "NORMAL") -> None:
        """Home all axes (Z, X, Y); "RECOVER" first backs away from the switches."""
        if mode not in ("NORMAL", "RECOVER"):
            raise ValueError(f"homing mode must be NORMAL or RECOVER, not {mode!r}")
        self._ready_to_move()
        if self.state == "ALARM":
            self.clear_alarm()
        self.homed = False
        self.homing = Homing(self, mode == "RECOVER")
        self._set_state("HOMING")

    def _homed(self) -> None:
        self.homing = None
        self.homed = True
        self._events.append(Homed())
        self._set_state("IDLE")

    def fail_homing(self, text: str) -> None:
        self._alarm("HOMING_FAILED", text)

    def shift_axis(self, k: int, delta: float) -> None:
        """Redefine axis ``k`` coordinates by ``delta`` mm (homing); nothing moves."""
        self.wake()
        a = self.axes[k]
        a[_S["off"]] += delta
        a[_S["sp"]] += delta
        pos = list(self.planner.pos)
        pos[k] += delta
        self.planner.reset_position(pos)

    def jog(self, axis: str, distance_mm: float, feed_mm_min: float) -> None:
        """Move one axis by ``distance_mm``; allowed unhomed, soft-limited once homed."""
        k = "XYZ".index(axis.upper()) if axis and axis.upper() in "XYZ" else -1
        if k < 0 or len(axis) != 1:
            raise ValueError(f"jog axis must be X, Y or Z, not {axis!r}")
        if not (math.isfinite(distance_mm) and math.isfinite(feed_mm_min) and feed_mm_min > 0):
            raise ValueError("jog needs a finite distance and a feed > 0")
        self._ready_to_move(allow_jog=True)
        start = self.planner.tail if self.state == "JOG" and not self.planner.holding else self.commanded_mm
        target = list(start)
        target[k] += distance_mm
        self.jog_to(start, tuple(target), feed_mm_min, f"jog {axis}")

    def jog_to(self, start, target, feed_mm_min: float, source: str) -> None:
        """Jog in a straight line from ``start`` (the commanded end) to ``target``,
        soft-limited once homed; the caller checked the machine may move."""
        move = Move(-1, "line", tuple(target), feed=feed_mm_min, source=source)
        if self.homed and (why := soft_limit_violation(start, move, self.profile.travel)):
            raise MotionError("SOFT_LIMIT", why)
        if self.waiting is not None:
            self._park()
        self.planner.add(move)
        self._set_state("JOG")

    def ready_to_jog(self) -> None:
        """Raise MotionError (COVER_OPEN, BUSY) unless the machine may start a jog now."""
        self._ready_to_move()

    def _ready_to_move(self, allow_jog: bool = False) -> None:
        if self._cover:
            raise MotionError("COVER_OPEN", "close the cover first")
        ok = ("IDLE", "ALARM") if not allow_jog else ("IDLE", "JOG")
        if self.at_stop() and (allow_jog or self.state != "JOG"):
            return  # a touch-off at a program stop (a new jog only once the last one ended)
        if self.state not in ok or self.stopping:
            raise MotionError("BUSY", f"machine is {self.state}")

    # -- parameters ----------------------------------------------------------------------
    def set_param(self, name: str, value: float) -> None:
        """KP_X KI_X KD_X (and _Y, _Z; or no suffix for all axes) and FERR (mm)."""
        key = str(name).upper()
        value = float(value)
        if key == "FERR":
            if not (math.isfinite(value) and 0.05 <= value <= 100.0):
                raise ValueError(f"FERR {value:g} out of range 0.05..100 mm")
            self.ferr = value
            return
        base, _, axis = key.partition("_")
        if base not in _PARAMS or axis not in ("", "X", "Y", "Z"):
            raise ValueError(f"unknown parameter {name!r}; known: KP_X KI_X KD_X (_Y _Z) FERR")
        field, lo, hi, scale = _PARAMS[base]
        if not (math.isfinite(value) and lo <= value <= hi):
            raise ValueError(f"{key} {value:g} out of range {lo:g}..{hi:g}")
        self.wake()
        for k in (range(3) if not axis else ["XYZ".index(axis)]):
            self.axes[k][_S[field]] = value * scale

    def get_param(self, name: str) -> float:
        key = str(name).upper()
        if key == "FERR":
            return self.ferr
        base, _, axis = key.partition("_")
        if base not in _PARAMS or axis not in ("X", "Y", "Z"):
            raise ValueError(f"unknown parameter {name!r}")
        field, _, _, scale = _PARAMS[base]
        return self.axes["XYZ".index(axis)][_S[field]] / scale

    # -- faults and resets -------------------------------------------------------------
    def clear_alarm(self) -> None:
        if self.state != "ALARM":
            return
        self._hold_here(self.measured_mm)
        self.servo_on = True
        self.wake()
        self._set_state("IDLE")

    def trip_limit(self, axis: str) -> None:
        """Fault injection: the switch of ``axis`` reports closed (a limit alarm)."""
        k = "XYZ".index(axis.upper())
        self._alarm("LIMIT", f"{axis.upper()} {'max' if k == 2 else 'min'}")

    def lose_encoder(self, axis: str) -> None:
        """Fault injection: the encoder of ``axis`` stops counting."""
        self.wake()
        a = self.axes["XYZ".index(axis.upper())]
        a[_S["c0"]] = -a[_S["c"]]
        a[_S["cpm"]] = 0.0

    def reset(self) -> None:
        """Power-on state: counts 0 (position unknown), not homed, queue empty, spindle off."""
        for k, a in enumerate(self.axes):
            a[_S["cpm"]] = self.model.counts_per_mm
            a[_S["c0"]] = math.floor(a[_S["x"]] * a[_S["cpm"]])
            a[_S["c"]], a[_S["off"]] = 0, 0.0
            self.pressed[k] = self._is_pressed(k)
        old, self.state = self.state, "IDLE"
        self.homed, self.stopping, self.homing, self.servo_on = False, False, None, True
        self.done_seq = -1
        self.waiting = self.parked = None
        self.spin_up, self.cover_rpm = None, 0.0
        self.brk = 0
        self.spindle.reset(self.now_ms)
        self.spindle_target = 0.0
        self.overrides = Overrides()
        self.planner.set_scales(1.0, 1.0)
        self._hold_here((0.0, 0.0, 0.0))
        if old not in (None, "IDLE"):
            self._events.append(StateChanged("IDLE"))

    def _is_pressed(self, k: int) -> bool:
        x = self.axes[k][_S["x"]]
        pressed = x <= self.switch[k] if k < 2 else x >= self.switch[k]
        self.axes[k][_S["lo"]], self.axes[k][_S["hi"]] = self._window(k, pressed)
        return pressed

    def _hold_here(self, position) -> None:
        """Setpoint := ``position`` (machine mm) with no jump in the PID; sources flushed."""
        self.wake()
        for k, a in enumerate(self.axes):
            a[_S["sp"]] = position[k]
            a[_S["ig"]] = a[_S["ep"]] = a[_S["df"]] = a[_S["pv"]] = 0.0
            self.errors[k] = 0.0
        self.job.reset_position(position)
        self.planner.reset_position(position)
        self._update_watch()

    @property
    def cover_open(self) -> bool:
        return self._cover

    @cover_open.setter
    def cover_open(self, value: bool) -> None:
        was, self._cover = self._cover, bool(value)
        if self._cover and not was:
            self._events.append(Alarm("COVER_OPEN", "cover opened"))
            if self.state in ("RUN", "HOLD") or self.parked is not None:  # a job's spindle: back on RESUME
                self.cover_rpm = self.spin_up[0] if self.spin_up else self.spindle_target
                self.spin_up = None
            self._spindle_off()
            if self.state == "RUN":
                self.feed_hold()
            elif self.state == "JOG":
                self.end_jog()  # a touch-off jog gives the job back, held
            elif self.state == "HOMING":
                self.stop()
            self._update_watch()

    # -- services for the planner and the simple interpolator ---------------------------
    def finished(self, move: Move) -> None:
        self.done_seq = move.seq
        self._events.append(Finished(move.seq, move.source, self.now_ms))

    def spindle_command(self, rpm: float, ms: int) -> bool:
        if ms == 1:
            self.spindle_target = rpm
            self._drive_spindle()
        if rpm <= 0:
            return True
        return self.spindle.ready(self.now_ms, self.overrides.spindle_rpm(rpm)) or ms > _SPINDLE_MAX_WAIT_MS

    def _drive_spindle(self) -> None:
        """Command the spindle model: the programmed speed times the spindle override."""
        self.spindle.command(self.now_ms, self.overrides.spindle_rpm(self.spindle_target))

    def set_override(self, verb: str, percent: int) -> None:
        """``R <id> FEED|SPINDLE|RAPID <percent>``: taken at once, in any state (protocol)."""
        self.overrides.set(verb, percent)
        feed, rapid = self.overrides.feed / 100.0, self.overrides.rapid / 100.0
        for source in {id(self.planner): self.planner, id(self.job): self.job}.values():
            if hasattr(source, "set_scales"):
                source.set_scales(feed, rapid)
        if verb == "SPINDLE" and self.spindle_target > 0:
            self._drive_spindle()
        self.wake()

    def program_wait(self, move: Move, ms: int) -> bool:
        """A program stop's wait (``stop_of``): reported once, done when ``resume`` releases it."""
        if ms == 1 and self.waiting is None:  # not again when re-queued after a touch-off
            self.waiting = move
            self._events.append(ProgramStop(move.stop_of, move.source))
        return self.waiting is None

    def end_of_program(self, ms: int) -> bool:
        if ms == 1:
            self._spindle_off()
        return self.settled() or ms > _END_SETTLE_MS

    def settled(self) -> bool:
        """Every axis within one count of its setpoint."""
        tol = 1.0 / self.model.counts_per_mm
        return all(-tol <= e <= tol for e in self.errors)

    def spindle_off(self) -> None:
        """``SPINDLE OFF`` whatever moves: the spindle stops now (a jog or homing goes
        on). A job's spindle is held as the cover holds it: a running job feed-holds,
        and RESUME brings the spindle back to speed before it goes on."""
        if self.state in ("RUN", "HOLD") and self.waiting is None and (self.spindle_target or self.spin_up):
            self.cover_rpm = self.spin_up[0] if self.spin_up else self.spindle_target
            self.spin_up = None
            self.feed_hold()
        self._spindle_off()
        self.wake()
        self._update_watch()

    def _spindle_off(self) -> None:
        if self.spindle_target:
            self.spindle_target = 0.0
            self.spindle.command(self.now_ms, 0.0)

    @property
    def spindle_on(self) -> bool:
        return self.spindle_target > 0

    # -- tests and tuning ---------------------------------------------------------------
    def drive(self, setpoints) -> list:
        """Feed raw setpoints (machine mm, one per 1 ms tick) to the servo loop, bypassing the
        planner (step and ramp responses, tuning); returns the measured positions. IDLE only;
        the machine then holds the last setpoint."""
        if self.state != "IDLE":
            raise MotionError("BUSY", f"machine is {self.state}")
        points = [tuple(float(v) for v in p) for p in setpoints]
        it = iter(points)
        measured: list = []
        self.source_step = it.__next__
        self.trace = measured.append
        try:
            done = 0
            while done < len(points):
                done += servo.run(self, len(points) - done)
                self._after_run()
                if self.state == "ALARM":
                    break
        finally:
            self.trace = None
            if self.state != "ALARM":
                self._hold_here(self.commanded_mm)
        mpc = 1.0 / self.model.counts_per_mm
        offs = [a[_S["off"]] for a in self.axes]
        return [tuple(c * mpc + o for c, o in zip(m, offs, strict=True)) for m in measured]
