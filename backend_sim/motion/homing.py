"""Homing sequences (HOME NORMAL / RECOVER) as a generator polled once per tick.

Contract: ``homing_script(ctl, recover)`` yields while work is in progress and returns
when the machine stands at home. Per axis, Z first (to lift the tool), then X, then Y:
seek the switch at ``homing_mm_min``; when the switch closes (``ctl`` calls
``on_switch``) decelerate on the path, declare the trip point to be the switch position
(X -10, Y -10, Z 40 machine with the default 10 mm back-off), then move to home
(X 0, Y 0, Z 30). RECOVER first moves every axis ``home_backoff_mm`` away from its
switch (after a limit alarm the switch may still be pressed).
"""

from __future__ import annotations

from backend_sim.motion.dialect import Move

ORDER = (2, 0, 1)
# direction of travel towards each axis' switch: X min, Y min, Z max
TOWARDS = (-1.0, -1.0, 1.0)


def switch_positions(travel) -> tuple[float, float, float]:
    """Machine coordinates of the X min, Y min and Z max switches."""
    b = travel.home_backoff_mm
    return (-b, -b, travel.z_max + b)


def home_positions(travel) -> tuple[float, float, float]:
    return (0.0, 0.0, travel.z_max)


class Homing:
    """State of one homing run; ``poll()`` returns True when it has finished."""

    def __init__(self, ctl, recover: bool):
        self.ctl = ctl
        self.trip: dict[int, float] = {}
        self.seeking: int | None = None
        self._gen = self._script(recover)

    def poll(self) -> bool:
        try:
            next(self._gen)
        except StopIteration:
            return True
        return False

    def on_switch(self, axis: int, measured: float) -> bool:
        """A switch closed; True if homing expected it (else it is a limit alarm)."""
        if axis != self.seeking or axis in self.trip:
            return False
        self.trip[axis] = measured
        self.ctl.planner.hold()
        return True

    def _move(self, target) -> Move:
        feed = self.ctl.profile.motion.homing_mm_min
        return Move(-1, "line", tuple(target), feed=feed, source="homing")

    def _wait_idle(self):
        planner = self.ctl.planner
        yield
        while not (planner.idle() or (planner.holding and planner.at_rest())):
            yield

    def _script(self, recover: bool):
        ctl = self.ctl
        travel = ctl.profile.travel
        pressed = [k for k in range(3) if ctl.pressed[k]]
        if pressed and not recover:
            yield
            ctl.fail_homing(f"{'XYZ'[pressed[0]]} switch pressed: home with RECOVER")
            return
        if recover:
            away = [p - t * travel.home_backoff_mm for p, t in zip(ctl.commanded_mm, TOWARDS, strict=True)]
            ctl.planner.add(self._move(away))
            yield from self._wait_idle()
        spans = (travel.x_max, travel.y_max, travel.z_max)
        for k in ORDER:
            target = list(ctl.commanded_mm)
            target[k] += TOWARDS[k] * (spans[k] + 3 * travel.home_backoff_mm)
            self.seeking = k
            ctl.planner.add(self._move(target))
            yield from self._wait_idle()
            if k not in self.trip:
                ctl.fail_homing(f"{'XYZ'[k]} switch not found")
                return
            ctl.planner.flush()
            ctl.planner.resume()
            ctl.shift_axis(k, switch_positions(travel)[k] - self.trip[k])
            target = list(ctl.commanded_mm)
            target[k] = home_positions(travel)[k]
            ctl.planner.add(self._move(target))
            yield from self._wait_idle()
        self.seeking = None
