"""The whole machine in one object: both MCUs, the links, the panel, faults, one clock.

Contract (docs/architecture.md): ``Simulator(profile=None, sd_dir=None, clock=None,
mode="planner")``; ``host_port`` is the pyserial-shaped host end; ``run_for(seconds)``
and ``run_until(predicate, timeout)`` advance the simulated clock as fast as possible
(deterministic for a given ``seed``); ``start(speed=1.0)`` / ``stop()`` run it on its
own thread in real time, at a speed factor, or (``speed=None``) as fast as possible.
``panel``, ``faults`` and ``exec_log`` are the test and GUI APIs.

The loop is event driven: it jumps straight to the next thing that can happen (a byte
that matters landing on a wire, a timer of the main MCU, the next chunk of at most
``MOTION_CHUNK_MS`` of motion) and skips the 1 ms ticks while the machine is at rest.
The motion controller is brought up to the clock whenever the CNC MCU receives bytes,
is due, or is touched from outside, and at the end of every ``run_*``; between those
(events of the main MCU and the host) it may lag by at most one motion chunk.
"""

from __future__ import annotations

import random
import threading
import time
from collections.abc import Callable
from pathlib import Path

from app.profile import MachineProfile
from backend_sim.clock import SimClock
from backend_sim.cnc_mcu import CncMcu
from backend_sim.exec_log import ExecLog
from backend_sim.fault_api import Faults
from backend_sim.flash import Flash
from backend_sim.host_port import HostPort
from backend_sim.main_mcu import MainMcu
from backend_sim.panel import Panel
from backend_sim.sd_card import SdCard
from backend_sim.wire import USB_BYTE_TIME, USB_LATENCY, Wire, to_ms, uart_byte_time

FAR_MS = 1 << 62
THREAD_SLICE_MS = 50


def default_sd_dir() -> Path:
    """The per-user folder that stands for the SD card."""
    import platformdirs

    return Path(platformdirs.user_data_dir("cnc-mill-controller")) / "sd"


def default_motion_factory(profile: MachineProfile, mode: str) -> Callable:
    from backend_sim.motion.controller import MotionController

    return lambda: MotionController(profile, mode=mode)


class Simulator:
    """The machine: see the module docstring. ``seed`` fixes boot ids and random faults;
    ``exec_log`` is a file to append executed lines to; ``motion_factory`` builds the
    motion controller (default: ``MotionController(profile, mode=mode)``)."""

    def __init__(self, profile: MachineProfile | None = None, sd_dir: str | Path | None = None,
                 clock: SimClock | None = None, mode: str = "planner", *, seed: int | None = None,
                 exec_log: str | Path | None = None, motion_factory: Callable | None = None) -> None:
        self.profile = profile or MachineProfile()
        self.clock = clock or SimClock()
        self.lock = threading.RLock()
        self.condition = threading.Condition(self.lock)
        self.rng = random.Random(seed)
        self.wires = self._make_wires(0 if seed is None else seed)
        self._usb_down, self._usb_up = self.wires["usb_down"], self.wires["usb_up"]
        self._uart_down, self._uart_up = self.wires["uart_down"], self.wires["uart_up"]
        self.exec_log = ExecLog(exec_log)
        self.sd = SdCard(sd_dir if sd_dir is not None else default_sd_dir())
        factory = motion_factory or default_motion_factory(self.profile, mode)
        flash = Flash(self.sd.folder, self.profile.travel.work_offset())
        self.cnc = CncMcu(self.profile, self.clock, self.wires["uart_up"], factory, self.exec_log,
                          self.rng, flash)
        self.main = MainMcu(self.profile, self.clock, self.wires["usb_up"], self.wires["uart_down"], self.sd)
        self.host_port = HostPort(self)
        self.panel = Panel(self)
        self.faults = Faults(self)
        self._thread: threading.Thread | None = None
        self._running = False

    def _make_wires(self, seed: int) -> dict[str, Wire]:
        uart = uart_byte_time(self.profile.link.baud)
        return {
            "usb_down": Wire("usb_down", USB_BYTE_TIME, USB_LATENCY, seed),
            "usb_up": Wire("usb_up", USB_BYTE_TIME, USB_LATENCY, seed),
            "uart_down": Wire("uart_down", uart, 0.0, seed),
            "uart_up": Wire("uart_up", uart, 0.0, seed),
        }

    # ------------------------------------------------------------------ as fast as possible

    def run_for(self, seconds: float) -> None:
        """Advance the simulated clock by ``seconds``."""
        with self.lock:
            end = self.clock.now_ms + round(seconds * 1000)
            if self._running:
                self._wait_running(lambda: False, end)
            else:
                self._step_to(end)

    def run_until(self, predicate: Callable[[], bool], timeout: float = 60.0) -> bool:
        """Advance until ``predicate()`` is true (checked after every event) or ``timeout``
        simulated seconds have passed; returns whether the predicate became true."""
        with self.lock:
            return self.run_until_locked(predicate, self.clock.now_ms + round(timeout * 1000))

    def run_until_locked(self, predicate: Callable[[], bool], end_ms: int | None) -> bool:
        if self._running:
            return self._wait_running(predicate, end_ms)
        end = FAR_MS if end_ms is None else end_ms
        while not predicate():
            if self.clock.now_ms >= end:
                return False
            self._step_to(min(end, self.clock.now_ms + 1000), predicate)
        return True

    def _wait_running(self, predicate: Callable[[], bool], end_ms: int | None) -> bool:
        while not predicate():
            if end_ms is not None and self.clock.now_ms >= end_ms:
                return False
            self.condition.wait(0.05)
        return True

    def _step_to(self, end_ms: int, predicate: Callable[[], bool] | None = None) -> None:
        clock, cnc, main = self.clock, self.cnc, self.main
        while clock.now_ms < end_ms:
            due, cnc_due = self._next_due(end_ms)
            clock.advance_to(due)
            if due >= cnc_due:
                cnc.catch_up()
            self._deliver()
            main.service()
            if predicate is not None and predicate():
                break
        cnc.catch_up()

    def _next_due(self, end_ms: int) -> tuple[int, int]:
        """The next ms anything happens, and the next ms the CNC MCU must run."""
        now = self.clock.now_ms
        cnc_due = self.cnc.next_due_ms()
        if cnc_due is None:
            cnc_due = FAR_MS
        t = self._uart_down.next_time()
        if t is not None:
            cnc_due = min(cnc_due, to_ms(t))
        due = min(end_ms, self.main.next_due_ms(), cnc_due)
        for wire in (self._usb_down, self._uart_up, self._usb_up):
            t = wire.next_time()
            if t is not None:
                due = min(due, to_ms(t))
        return max(due, now + 1), max(cnc_due, now + 1)

    def _deliver(self) -> None:
        now = self.clock.now
        data = self._usb_down.take(now)
        if data:
            self.main.receive_host(data)
        data = self._uart_down.take(now)
        if data:
            self.cnc.receive(data)
        data = self._uart_up.take(now)
        if data:
            self.main.receive_uart(data)
        data = self._usb_up.take(now)
        if data:
            self.host_port.deliver(data)
            self.condition.notify_all()

    # ------------------------------------------------------------------ own thread

    @property
    def running(self) -> bool:
        return self._running

    def start(self, speed: float | None = 1.0) -> None:
        """Run on a daemon thread: real time (1.0), a factor (20.0) or unpaced (None)."""
        if self._running:
            self.set_speed(speed)
            return
        with self.lock:
            self.clock.set_speed(speed)
            self._running = True
        self._thread = threading.Thread(target=self._thread_main, name="cnc-sim", daemon=True)
        self._thread.start()

    def set_speed(self, speed: float | None) -> None:
        """Change the speed factor of a running machine from any thread: simulated time
        goes on from where it is, at the new pace (a test slows the machine down so that
        a job it must catch mid-run cannot end first on a busy computer)."""
        with self.lock:
            self.clock.set_speed(speed)
            self.condition.notify_all()

    def stop(self) -> None:
        with self.lock:
            self._running = False
            self.condition.notify_all()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=5)
        self._thread = None

    def wake(self) -> None:
        """Something changed from outside (host write, button): recompute the next event."""
        self.cnc.wake()
        self.condition.notify_all()

    def _thread_main(self) -> None:
        while True:
            with self.lock:
                if not self._running:
                    return
                self._thread_slice()
            time.sleep(0)

    def _thread_slice(self) -> None:
        target = self.clock.target_ms()
        if target is None:
            self._step_to(self.clock.now_ms + THREAD_SLICE_MS)
            self.condition.notify_all()
            return
        if target > self.clock.now_ms:
            self._step_to(min(target, self.clock.now_ms + THREAD_SLICE_MS))
            self.condition.notify_all()
            if self.clock.now_ms < target:  # behind the wall: on at once (the lock is let go between slices)
                return
        wait = self.clock.wall_until(self._next_due(FAR_MS)[0])
        self.condition.wait(min(max(wait, 0.002), 0.05))
