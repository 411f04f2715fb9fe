"""The CNC MCU's motion side: queue, planner or simple interpolator, servo, homing, faults.

Contract (the CNC MCU protocol layer drives it, one call per 1 ms tick or ``advance``):
``enqueue(Move)`` while ``free_slots()``; ``tick()``/``advance(ms)`` run the machine;
``events()`` drains ``Finished``/``Alarm``/``Homed``/``StateChanged``/``Held``/
``Stopped``. Positions are machine mm: ``measured_mm`` from the encoder counts (never
the truth), ``commanded_mm`` the setpoint, ``true_mm`` the simulated truth (tests).
The controller does not check "homed" or soft limits before ``enqueue`` (the MCU does,
with ``soft_limit_violation``); ``jog`` checks soft limits once homed. At power-on the
counts are 0 and ``measured_mm`` reads (0, 0, 0) wherever the machine stands.
"""

from __future__ import annotations

import math

from app.profile import MachineProfile
from backend_sim.motion import fastpath, servo
from backend_sim.motion.controller_ops import ControllerOps
from backend_sim.motion.events import Alarm, Held, StateChanged
from backend_sim.motion.homing import switch_positions
from backend_sim.motion.motor import MotorModel
from backend_sim.motion.planner import Planner
from backend_sim.motion.simple import SimpleInterpolator
from backend_sim.motion.spindle import SpindleModel
from backend_sim.motion.touch_off import TouchOff

AXES = "XYZ"
_S = {name: n for n, name in enumerate(servo.STATE)}
D_FILTER_MS = 2.0
OVERTRAVEL_MM = 3.0  # hard stop beyond each switch
FAR_END_MM = 5.0  # hard stop beyond the far end of travel
_IDLE_CHUNK = 20


class MotionController(ControllerOps, TouchOff):
    """See the module docstring; commands live in ``ControllerOps``."""

    def __init__(self, profile: MachineProfile | None = None, mode: str = "planner",
                 start_mm=(50.0, 50.0, 20.0), capacity: int = 16):
        if mode not in ("planner", "simple"):
            raise ValueError(f"mode must be 'planner' or 'simple', not {mode!r}")
        self.profile = profile = profile or MachineProfile()
        self.mode, self.capacity = mode, capacity
        self.model = MotorModel.from_profile(profile)
        kv, ka, kc = self.model.ff_gains()
        self.ff = (kv, ka, kc, 0.5) if mode == "planner" else (0.0, 0.0, 0.0, 0.5)
        self.d_alpha = 1.0 - math.exp(-1.0 / D_FILTER_MS)
        self._ferr = profile.pid.following_error_mm
        self.switch = switch_positions(profile.travel)
        self._events: list = []
        self.errors = [0.0, 0.0, 0.0]
        self.trace = None  # tests: a callable receiving (c0, c1, c2) counts every tick
        self.now_ms = 0
        self.spindle = SpindleModel(profile)
        self.spindle_target = 0.0
        self.axes = [self._axis_state(k, start_mm[k]) for k in range(3)]
        self.planner = Planner(profile, self, self._events)
        self.job = self.planner if mode == "planner" else SimpleInterpolator(profile, self, self._events)
        self.loop_constants = servo.constants(self)
        self._cover = False
        self.pressed = [False, False, False]
        self.state = None
        self.spin_up: tuple[float, int] | None = None  # (rpm, since ms): RESUME waits for the spindle
        self.cover_rpm = 0.0  # the job's spindle speed the cover stopped
        self.waiting = None  # the program stop the job waits at
        self.parked = None  # the job's queue while a touch-off jog runs at a stop
        self.reset()

    # -- construction -------------------------------------------------------------
    def _axis_state(self, k: int, x: float) -> list:
        cpm = self.model.counts_per_mm
        pid = self.profile.pid
        st = [0.0] * len(servo.STATE)
        st[_S["x"]], st[_S["cpm"]] = float(x), cpm
        st[_S["kp"]], st[_S["ki"]], st[_S["kd"]] = pid.kp, pid.ki / pid.rate_hz, pid.kd
        st[_S["c"]] = 0
        st[_S["c0"]] = math.floor(x * cpm)
        return st

    def _window(self, k: int, pressed: bool) -> tuple[float, float]:
        sw = self.switch[k]
        far = (self.profile.travel.x_max, self.profile.travel.y_max, 0.0)[k]
        if k < 2:  # switch at the minimum end
            return (sw - OVERTRAVEL_MM, sw) if pressed else (sw, far + FAR_END_MM)
        return (sw, sw + OVERTRAVEL_MM) if pressed else (-FAR_END_MM, sw)

    @property
    def ferr(self) -> float:
        """Following-error limit, mm (``SET FERR``)."""
        return self._ferr

    @ferr.setter
    def ferr(self, value: float) -> None:
        self._ferr = value
        self.loop_constants = servo.constants(self)

    # -- read-only state ----------------------------------------------------------
    @property
    def measured_mm(self) -> tuple[float, float, float]:
        mpc = 1.0 / self.model.counts_per_mm
        return tuple(a[_S["c"]] * mpc + a[_S["off"]] for a in self.axes)  # type: ignore[return-value]

    @property
    def true_mm(self) -> tuple[float, float, float]:
        return tuple(a[_S["x"]] for a in self.axes)  # type: ignore[return-value]

    @property
    def commanded_mm(self) -> tuple[float, float, float]:
        return tuple(a[_S["sp"]] for a in self.axes)  # type: ignore[return-value]

    @property
    def following_error_mm(self) -> tuple[float, float, float]:
        """Setpoint minus encoder-measured position, per axis."""
        return tuple(c - m for c, m in zip(self.commanded_mm, self.measured_mm, strict=True))  # type: ignore

    @property
    def counts(self) -> tuple[int, int, int]:
        return tuple(int(a[_S["c"]]) for a in self.axes)  # type: ignore[return-value]

    @property
    def spindle_rpm(self) -> float:
        return self.spindle.measured_rpm(self.now_ms)

    @property
    def tail_mm(self) -> tuple[float, float, float]:
        """Where the last queued move ends (the start of the next one), machine mm."""
        return self.job.tail if self.state in ("RUN", "HOLD") else self.commanded_mm

    def free_slots(self) -> int:
        return max(0, self.capacity - len(self.job) - len(self.parked or ()))

    def idle(self) -> bool:
        """State IDLE or ALARM, nothing queued or stopping, every axis at rest and the
        spindle at its speed: the machine will not change until a command (the MCU may
        stop ticking it)."""
        return (self.state in ("IDLE", "ALARM") and not self.stopping and self._restful()
                and self.spindle.settled(self.now_ms))

    def events(self) -> list:
        out = self._events[:]
        self._events.clear()
        return out

    # -- time ----------------------------------------------------------------------
    def tick(self) -> None:
        self.advance(1)

    def advance(self, ms: int) -> None:
        """Run ``ms`` ticks; fast-forwards exactly while at rest with nothing to do."""
        left = int(ms)
        while left > 0:
            if self._restful():
                self.now_ms += left
                return
            fast = fastpath.entry(self.planner) if self.active is self.planner else None
            done = servo.run_fused(self, left, fast) if fast is not None else 0
            if done:  # mid-block: nothing for supervise() to see until it breaks
                left -= done
            elif self.watch or (self.active is self.planner and self.planner.blocks):
                left -= servo.run(self, 1)  # boundaries and rests: step() and supervise() per tick
            else:
                busy = self.state in ("RUN", "HOMING", "JOG") or self.stopping
                left -= servo.run(self, left if busy else min(left, _IDLE_CHUNK))
            self._after_run()
            if self.watch:
                self.supervise()

    def _after_run(self) -> None:
        brk, self.brk = self.brk, 0
        if 1 <= brk <= 3:
            self._switch_crossed(brk - 1)
        if brk and self.servo_on:
            for k, e in enumerate(self.errors):
                if abs(e) > self.ferr:
                    self._alarm("FOLLOWING_ERROR", f"{AXES[k]} {e:+.3f} mm beyond {self.ferr:g} mm")
                    break
        if self.state == "RUN" and self.job.idle():
            self._set_state("IDLE")

    def _restful(self) -> bool:
        """At rest and nothing will change: the state is a fixed point of the loop."""
        if self.state not in ("IDLE", "HOLD", "ALARM") or self.stopping or self.spin_up is not None:
            return False
        if self.state != "ALARM" and not self.source_quiet():
            return False
        rest = _S["rest"]
        return all(a[rest] for a in self.axes)

    def wake(self) -> None:
        """Axis state was changed from outside the servo loop: recompute every axis."""
        rest = _S["rest"]
        for a in self.axes:
            a[rest] = False

    def source_quiet(self) -> bool:
        src = self.active
        return (src.idle() or src.holding) and src.at_rest()

    # -- supervision (after every tick while ``watch``) --------------------------------
    def supervise(self) -> None:
        if self.stopping:
            if self.active.at_rest():
                self._finish_stop()
        elif self.spin_up is not None:
            self.spun_up()
        elif self.state == "HOLD":
            if self.job.just_held():
                self._events.append(Held())
                self._update_watch()
        elif self.state == "HOMING":
            if self.homing is not None and self.homing.poll() and self.state == "HOMING":
                self._homed()
        elif self.state == "JOG" and self.parked is not None:
            if self.planner.idle() or self.planner.holding and self.planner.at_rest():
                self._unpark()
        elif self.state == "JOG" and self.planner.idle():
            self._set_state("IDLE")

    def _set_state(self, state: str) -> None:
        if state == "IDLE":
            self.job.reset_position(self.commanded_mm)
            self.planner.reset_position(self.commanded_mm)
        if state != self.state:
            self.state = state
            self._events.append(StateChanged(state))
        self._update_watch()

    def _update_watch(self) -> None:
        self.watch = self.stopping or self.state in ("HOMING", "JOG") or self.spin_up is not None or (
            self.state == "HOLD" and not self.job.held_flag)
        self.active = self.job if self.state in ("RUN", "HOLD") else self.planner
        self.source_step = self.active.step

    # -- switches and alarms ---------------------------------------------------------
    def _switch_crossed(self, k: int) -> None:
        a = self.axes[k]
        x, lo, hi = a[_S["x"]], a[_S["lo"]], a[_S["hi"]]
        if lo < x < hi:
            return
        pressed = x <= self.switch[k] if k < 2 else x >= self.switch[k]
        self.wake()
        if pressed == self.pressed[k]:  # against a hard stop
            a[_S["x"]] = x = min(max(x, lo + 1e-6), hi - 1e-6)
            a[_S["v"]] = 0.0
            a[_S["c"]] = (x * a[_S["cpm"]]) // 1.0 - a[_S["c0"]]
            return
        self.pressed[k] = pressed
        a[_S["lo"]], a[_S["hi"]] = self._window(k, pressed)
        if not pressed:
            return
        homing = self.homing if self.state == "HOMING" else None  # None: a stopped homing decelerating
        if homing is not None and homing.on_switch(k, self.measured_mm[k]):
            return
        self._alarm("LIMIT", f"{AXES[k]} {'max' if k == 2 else 'min'}")

    def _alarm(self, code: str, text: str) -> None:
        self._events.append(Alarm(code, text))
        self.wake()
        self.servo_on = False
        self.homed = False
        self.stopping = False
        self.homing = None
        self.waiting = self.parked = None
        self.spin_up, self.cover_rpm = None, 0.0
        self._spindle_off()
        self._set_state("ALARM")
        self._hold_here(self.measured_mm)
