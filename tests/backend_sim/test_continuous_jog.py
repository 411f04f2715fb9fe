"""Issue 21, hold-to-jog on the machine (docs/protocol.md, "Continuous jog"): keep-alives,
the 250 ms dead man, the diagonal, the soft-limit stop with a message, and the ends by
JOGEND, stop, hold, the cover. All on the simulator's clock, no sleeps."""

from __future__ import annotations

import math

import pytest

from app.comm.frame import Error, Log, Ok, Status
from backend_sim.continuous_jog import DEAD_MAN_MS
from tests.backend_sim.helpers import Host

KEEP_ALIVE_S = 0.025


@pytest.fixture
def homed(host: Host) -> Host:
    host.home()
    return host


def keep_jogging(host: Host, dirs: str, feed: float, seconds: float) -> list[int]:
    """Send ``R JOG`` every 25 ms (simulated) for ``seconds``; the ids sent."""
    ids, end = [], host.sim.clock.now + seconds
    while host.sim.clock.now < end - 1e-9:
        ids.append(host.realtime(f"JOG {dirs} {feed:g}"))
        due = host.sim.clock.now + KEEP_ALIVE_S
        host.sim.run_until(lambda due=due: host.sim.clock.now >= due - 1e-9, 1.0)
        host.pump()
    return ids


def at_rest(host: Host, since: float, timeout: float = 5.0) -> float:
    """Wait for the machine at rest in IDLE; the simulated time from ``since``."""
    mc = host.sim.cnc.mc
    assert host.sim.run_until(lambda: mc.state == "IDLE" and not mc.stopping, timeout)
    host.pump()
    return host.sim.clock.now - since


def no_alarm_since(host: Host, first: int) -> bool:
    return not any(isinstance(f, Status) and f.state == "ALARM" for f in host.frames[first:])


def stop_bound(host: Host, feed: float = 600) -> float:
    """50 ms (the frame's way) plus the deceleration from ``feed`` (S-curve: x 1.5)."""
    return 0.05 + 1.5 * feed / 60 / host.sim.profile.motion.accel_mm_s2


def answer_of(host: Host, cid: int):
    """The O or E of ``cid``, also when it came in before (keep_jogging pumps)."""
    return host.wait(lambda f: isinstance(f, Ok | Error) and f.id == cid, 2.0, start=0)


def logs(host: Host) -> list[str]:
    return [f.text for f in host.of(Log)]


def test_a_held_key_jogs_and_the_dead_man_stops_it_250_ms_after_the_last_keep_alive(homed):
    x0, first = homed.sim.cnc.mc.commanded_mm[0], len(homed.frames)
    ids = keep_jogging(homed, "X+", 600, 1.0)
    answers = [answer_of(homed, i) for i in ids[:3]]
    assert all(isinstance(a, Ok) and a.verb == "JOG" for a in answers), answers
    assert homed.sim.cnc.mc.state == "JOG"
    last_sent = homed.sim.clock.now - KEEP_ALIVE_S
    moved = homed.sim.cnc.mc.commanded_mm[0] - x0
    assert 5.0 < moved < 10.1  # 1 s at 600 mm/min, less the ramp
    homed.wait(lambda f: isinstance(f, Log) and "no keep-alive" in f.text, 2.0)
    stopped_by = homed.sim.clock.now - last_sent
    assert DEAD_MAN_MS / 1000 - 0.01 <= stopped_by <= DEAD_MAN_MS / 1000 + 0.03, stopped_by
    at_rest(homed, 0.0)
    assert no_alarm_since(homed, first)


def test_jogend_stops_at_once_and_an_axis_never_runs_on(homed):
    keep_jogging(homed, "Y+", 600, 0.5)
    released = homed.sim.clock.now
    answer = homed.answer(homed.realtime("JOGEND"))
    assert isinstance(answer, Ok) and answer.verb == "JOGEND"
    assert at_rest(homed, released) < stop_bound(homed)  # 600 mm/min decelerates in well under that
    y = homed.sim.cnc.mc.commanded_mm[1]
    homed.sim.run_for(1.0)
    assert homed.sim.cnc.mc.commanded_mm[1] == y
    assert not any("no keep-alive" in t for t in logs(homed))


def test_two_keys_jog_the_diagonal(homed):
    start, pressed = homed.sim.cnc.mc.commanded_mm, homed.sim.clock.now
    keep_jogging(homed, "X+Y+", 600, 0.6)
    homed.answer(homed.realtime("JOGEND"))
    took = at_rest(homed, pressed)
    end = homed.sim.cnc.mc.commanded_mm
    dx, dy, dz = (end[k] - start[k] for k in range(3))
    assert dx > 1.0 and abs(dx - dy) < 1e-6 and dz == 0.0
    assert math.hypot(dx, dy) <= 600 / 60 * took + 1e-6  # the feed is along the path


def test_a_new_direction_ends_the_jog_and_starts_once_at_rest(homed):
    keep_jogging(homed, "X+", 600, 0.3)
    turned = homed.realtime("JOG X+Y+ 600")
    refused = homed.answer(turned)
    assert isinstance(refused, Error) and refused.code == "BUSY" and "direction" in refused.text
    at_rest(homed, 0.0)
    y0 = homed.sim.cnc.mc.commanded_mm[1]
    keep_jogging(homed, "X+Y+", 600, 0.3)
    assert homed.sim.cnc.mc.commanded_mm[1] > y0


def test_the_soft_limit_stops_the_jog_at_the_edge_with_a_message_not_an_alarm(homed):
    assert homed.sim.cnc.mc.commanded_mm == (0.0, 0.0, homed.sim.profile.travel.z_max)  # homed
    homed.ok("JOG X 4 600")
    first = len(homed.frames)
    keep_jogging(homed, "X-Y+", 600, 2.0)  # the diagonal meets X- 0 first
    x, y, _ = homed.sim.cnc.mc.commanded_mm
    assert x == pytest.approx(0.0, abs=1e-6) and y == pytest.approx(4.0, abs=1e-6)
    assert "jog stopped at the soft limit X- 0" in logs(homed)
    refused = answer_of(homed, homed.realtime("JOG X-Y+ 600"))
    assert isinstance(refused, Error) and refused.code == "SOFT_LIMIT" and refused.text == "X- at 0"
    assert no_alarm_since(homed, first)
    assert homed.sim.cnc.mc.measured_mm[0] >= -0.05


@pytest.mark.parametrize("end", ["R STOP", "R HOLD", "C STOP", "cover"])
def test_stop_hold_and_the_cover_end_a_continuous_jog(homed, end):
    keep_jogging(homed, "X+", 600, 0.4)
    ended = homed.sim.clock.now
    if end == "cover":
        homed.sim.panel.set_cover(True)
    elif end.startswith("R"):
        homed.answer(homed.realtime(end[2:]))
    else:
        homed.answer(homed.command(end[2:]))
    assert at_rest(homed, ended) < stop_bound(homed)
    assert homed.sim.cnc.jogging.running is None
    if end == "cover":
        refused = homed.answer(homed.realtime("JOG X+ 600"))
        assert isinstance(refused, Error) and refused.code == "COVER_OPEN"


def test_a_pulled_cable_stops_the_jog_by_the_dead_man(homed):
    keep_jogging(homed, "X+", 600, 0.4)
    homed.sim.faults.unplug()
    cut = homed.sim.clock.now
    assert homed.sim.run_until(lambda: homed.sim.cnc.mc.state == "IDLE", 2.0)
    assert homed.sim.clock.now - cut < DEAD_MAN_MS / 1000 + 0.3  # plus the deceleration


def test_a_step_jog_or_a_job_refuses_a_continuous_jog(homed):
    step = homed.command("JOG X 5 300")
    homed.wait(lambda f: isinstance(f, Status) and f.state == "JOG")
    refused = homed.answer(homed.realtime("JOG Y+ 300"))
    assert isinstance(refused, Error) and refused.code == "BUSY"
    assert isinstance(homed.answer(step), Ok)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_noise_at_1e_2_per_byte_may_stop_a_jog_early_but_never_lets_it_run_on(homed, seed):
    """Each round: keep-alives for 0.3 s (two copies each, as the host sends them) on
    both hops at 1e-2 corrupted, dropped and duplicated bytes, then silence: the machine
    is at rest within 250 ms of the last keep-alive plus 25 ms (the main MCU's last
    repeat) plus the deceleration, whatever got through."""
    homed.sim.faults.set_rates(seed=seed, corrupt=1e-2, drop=1e-2, duplicate=1e-2)
    homed.heartbeat = False
    moved = 0.0
    for dirs in ("X+", "Y+", "X-", "Y-"):
        for _ in range(2):
            before = homed.sim.cnc.mc.commanded_mm
            sent = keep_two_copies(homed, dirs, 0.3)
            at_rest(homed, sent, 2.0)
            assert homed.sim.clock.now - sent <= DEAD_MAN_MS / 1000 + 0.025 + stop_bound(homed)
            assert homed.sim.cnc.mc.state == "IDLE"
            moved += math.dist(before, homed.sim.cnc.mc.commanded_mm)
    assert moved > 8 * 0.3 * 10 / 2  # most rounds jogged most of their time: noise did not stop it all


def keep_two_copies(host: Host, dirs: str, seconds: float) -> float:
    """Keep-alives as the host writes them (two copies, a new id every 25 ms); when the last left."""
    end = host.sim.clock.now + seconds
    while host.sim.clock.now < end - 1e-9:
        cid = host.next_id
        host.next_id += 1
        for _ in range(2):
            host.send(f"R {cid} JOG {dirs} 600")
        last, due = host.sim.clock.now, host.sim.clock.now + KEEP_ALIVE_S
        host.sim.run_until(lambda due=due: host.sim.clock.now >= due - 1e-9, 1.0)
        host.pump()
    return last
