"""The simulated GRBL machine with its serial link and one clock.

``GrblSimulator(profile=None, clock=None, baud=115200, seed=None, motion_factory=None)``
has the parts of ``backend_sim.simulator.Simulator`` that the host port, the pty and
TCP servers and ``sim://`` use: ``host_port`` (pyserial-shaped), ``wires``
(``usb_down`` host -> machine, ``usb_up`` back), ``lock``/``condition``, ``clock``,
``run_for``/``run_until`` (as fast as possible, deterministic), ``start(speed)``/``stop``
(own thread), ``wake``. Both directions run at ``baud`` 8N1 (10 bits a byte) behind a
USB-serial converter's ``LATENCY_S``: the speed of a real GRBL's link, so streaming
figures measured against it are honest. ``machine`` is the ``GrblMachine``;
``set_door(open)`` works the safety door switch, ``trip_limit(axis)`` a limit switch.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from app.profile import MachineProfile
from backend_sim.clock import SimClock
from backend_sim.grbl.machine import PLANNER_BLOCKS, GrblMachine
from backend_sim.host_port import HostPort
from backend_sim.simulator import Simulator
from backend_sim.wire import Wire, to_ms, uart_byte_time

FAR_MS = 1 << 62
LATENCY_S = 0.001
THREAD_SLICE_MS = 50


def default_motion(profile: MachineProfile):
    from backend_sim.motion.controller import MotionController

    return MotionController(profile, capacity=PLANNER_BLOCKS)


class GrblSimulator:
    """See the module docstring."""

    panel = None  # no OLED and buttons: a GRBL board has none

    def __init__(self, profile: MachineProfile | None = None, clock: SimClock | None = None,
                 baud: int = 115200, seed: int | None = None,
                 motion_factory: Callable | None = None) -> None:
        self.profile = profile or MachineProfile()
        self.clock = clock or SimClock()
        self.lock = threading.RLock()
        self.condition = threading.Condition(self.lock)
        byte_time = uart_byte_time(baud)
        seed = seed or 0
        self.wires = {"usb_down": Wire("usb_down", byte_time, LATENCY_S, seed),
                      "usb_up": Wire("usb_up", byte_time, LATENCY_S, seed)}
        motion = (motion_factory or default_motion)(self.profile)
        self.machine = GrblMachine(self.profile, self.clock, self.wires["usb_up"], motion)
        self.host_port = HostPort(self)
        self._thread: threading.Thread | None = None
        self._running = False

    # ------------------------------------------------------------------ the test API

    def set_door(self, opened: bool) -> None:
        with self.lock:
            self.machine.set_door(opened)
            self.wake()

    def trip_limit(self, axis: str) -> None:
        with self.lock:
            self.machine.motion.trip_limit(axis)
            self.wake()

    # ------------------------------------------------------------------ runners
    # The mill's simulator's, unchanged: they need only the clock, the lock, the
    # condition, ``_running``/``_thread`` and ``_step_to``/``_thread_main`` below.
    run_for = Simulator.run_for
    run_until = Simulator.run_until
    run_until_locked = Simulator.run_until_locked
    _wait_running = Simulator._wait_running
    running = Simulator.running
    start = Simulator.start
    stop = Simulator.stop

    def _step_to(self, end_ms: int, predicate: Callable[[], bool] | None = None) -> None:
        clock, machine = self.clock, self.machine
        while True:
            self._deliver()
            machine.service()
            if (predicate is not None and predicate()) or clock.now_ms >= end_ms:
                return
            clock.advance_to(self._next_due(end_ms))

    def _next_due(self, end_ms: int) -> int:
        now = self.clock.now_ms
        due = end_ms
        machine_due = self.machine.next_due_ms()
        if machine_due is not None:
            due = min(due, machine_due)
        for wire in self.wires.values():
            t = wire.next_time()
            if t is not None:
                due = min(due, to_ms(t))
        return max(due, now + 1)

    def _deliver(self) -> None:
        now = self.clock.now
        data = self.wires["usb_down"].take(now)
        if data:
            self.machine.receive(data)
        data = self.wires["usb_up"].take(now)
        if data:
            self.host_port.deliver(data)
            self.condition.notify_all()

    def wake(self) -> None:
        self.condition.notify_all()

    def _thread_main(self) -> None:
        while True:
            with self.lock:
                if not self._running:
                    return
                target = self.clock.target_ms()
                now = self.clock.now_ms
                if target is None or target > now:
                    end = now + THREAD_SLICE_MS if target is None else min(target, now + THREAD_SLICE_MS)
                    self._step_to(end)
                    self.condition.notify_all()
                if target is not None and self.clock.now_ms >= self.clock.target_ms():
                    due = min(self._next_due(FAR_MS), self.clock.now_ms + THREAD_SLICE_MS)
                    wait = self.clock.wall_until(due)
                    self.condition.wait(min(max(wait, 0.001), 0.05))
            time.sleep(0)
