"""Issue 18 point 7: at any speed factor the host-facing link timers run in wall-clock
time, also when the simulation cannot keep up with the factor. The wall clock is
injected (``SimClock(wall=...)``) and the simulation stepped by hand slower than its
factor, so nothing here depends on how fast this machine is."""

import math

import pytest
import serial

from app.comm.deframer import Deframer
from app.comm.frame import Alarm, Nak, Ok, seal
from backend_sim.__main__ import build_parser
from backend_sim.clock import MAX_SPEED, SimClock
from backend_sim.protocol_sim import build_simulator
from backend_sim.simulator import Simulator
from tests.backend_sim.conftest import FAST_HOMING

SPEED = 50.0
WALL_STEP = 0.01


class FakeWall:
    def __init__(self) -> None:
        self.t = 1000.0

    def __call__(self) -> float:
        return self.t


class LaggingMachine:
    """A simulator paced at ``SPEED`` that only manages ``achieved`` times real time."""

    def __init__(self, tmp_path, achieved: float) -> None:
        self.wall = FakeWall()
        self.sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=1, clock=SimClock(wall=self.wall))
        self.sim.clock.set_speed(SPEED)
        self.achieved = achieved
        self.rx = Deframer()
        self.frames: list[tuple[float, object]] = []

    def send(self, data: bytes) -> None:
        self.sim.host_port.write(data)

    def step(self, wall_seconds: float) -> None:
        """``wall_seconds`` pass; the simulation advances ``achieved`` times as much."""
        for _ in range(max(1, round(wall_seconds / WALL_STEP))):
            self.wall.t += WALL_STEP
            self.sim.run_for(WALL_STEP * self.achieved)
            port = self.sim.host_port
            for item in self.rx.feed(port.read(port.in_waiting), self.wall.t):
                self.frames.append((self.wall.t, item))

    def first(self, kind, **fields):
        for t, frame in self.frames:
            if isinstance(frame, kind) and all(getattr(frame, k) == v for k, v in fields.items()):
                return t, frame
        return None


@pytest.mark.parametrize("achieved", [SPEED, 10.0, 2.0])
def test_host_lost_after_three_wall_seconds_however_slow_the_simulation(tmp_path, achieved):
    m = LaggingMachine(tmp_path, achieved)
    m.send(seal("C 1 PING"))
    m.step(0.05)
    assert m.first(Alarm, code="HOST_LOST") is None and m.frames, "the machine did not answer"
    silent_from = m.wall.t
    m.step(3.3)
    found = m.first(Alarm, code="HOST_LOST")
    assert found is not None, f"no HOST_LOST after 3.3 wall s at {achieved}x of {SPEED}x"
    assert 3.0 - 0.05 <= found[0] - silent_from <= 3.0 + 0.06, found[0] - silent_from


@pytest.mark.parametrize("achieved", [SPEED, 5.0])
def test_a_frame_split_over_300_wall_ms_is_taken(tmp_path, achieved):
    """The partial-frame timeout (500 ms) is wall time: at 50x, 300 ms are 15 s of the machine."""
    m = LaggingMachine(tmp_path, achieved)
    raw = seal("C 7 GET FERR")
    m.send(raw[:5])
    m.step(0.3)
    m.send(raw[5:])
    m.step(0.1)
    assert m.first(Ok, id=7) is not None, m.frames


def test_a_partial_frame_is_dropped_after_500_wall_ms(tmp_path):
    m = LaggingMachine(tmp_path, SPEED)
    m.send(seal("C 1 PING"))
    m.step(0.05)
    raw = seal("C 7 GET FERR")
    m.send(raw[:5])
    m.step(0.7)
    m.send(raw[5:])
    m.step(0.1)
    assert m.first(Ok, id=7) is None
    assert m.first(Nak) is not None


def test_link_time_is_simulated_time_when_unpaced():
    clock = SimClock(wall=lambda: pytest.fail("an unpaced clock read the wall"))
    clock.advance_to(2500)
    assert clock.link_now == 2.5
    assert clock.ms_at_link(3.0) == 3000


@pytest.mark.parametrize("text", ["inf", "-inf", "nan", "1e308", "1e3", "0", "0.0", "-1", "1001", "", "fast",
                                  "1_0", "0x10"])
def test_impossible_speeds_are_refused_at_the_argument(text, capsys):
    with pytest.raises(SystemExit):
        build_parser().parse_args(["--pty", f"--speed={text}"])
    err = capsys.readouterr().err
    assert "--speed" in err and ("plain number" in err or "at most" in err), err


@pytest.mark.parametrize("text,value", [("1", 1.0), ("0.5", 0.5), ("50", 50.0),
                                        (f"{MAX_SPEED:g}", MAX_SPEED)])
def test_possible_speeds_are_taken(text, value):
    assert build_parser().parse_args(["--pty", "--speed", text]).speed == value


@pytest.mark.parametrize("text", ["inf", "nan", "1e308", "0", "-2"])
def test_impossible_sim_url_speeds_are_refused(text):
    with pytest.raises(serial.SerialException, match="speed"):
        build_simulator({"speed": text})


def test_a_speed_refused_by_the_clock_too():
    clock = SimClock()
    for speed in (math.inf, math.nan, 1e308, 0.0, -1.0):
        with pytest.raises(ValueError):
            clock.set_speed(speed)
