"""Overrides on the simulator (docs/protocol.md, "Overrides"): applied while a job runs
within 100 ms of simulated time, without a stop on the path, kept across a hold."""

from __future__ import annotations

import pytest

from app.comm.frame import Ok, Status

FEED = 400.0  # mm/min in the jobs below (the profile caps feeds at 600)


def running(sim, host, lines):
    host.home()
    host.stream(lines)
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and f.x > 5)
    sim.run_for(0.3)  # at cruise speed
    return sim.cnc.mc.planner


def override(host, verb, pct):
    cid = host.realtime(f"{verb} {pct}")
    answer = host.answer(cid)
    assert isinstance(answer, Ok) and answer.verb == verb, answer
    return answer


def latest_status(host) -> Status:
    host.pump()
    return [f for f in host.frames if isinstance(f, Status)][-1]


def measured_speed(sim, seconds: float) -> float:
    """mm/s along X of the measured (encoder) position over the next ``seconds``."""
    x0 = sim.cnc.mc.measured_mm[0]
    sim.run_for(seconds)
    return (sim.cnc.mc.measured_mm[0] - x0) / seconds


def test_feed_override_applies_within_100_ms_without_stopping(sim, host):
    planner = running(sim, host, ["G01 X120 F400"])
    assert planner.v_raw == pytest.approx(FEED / 60)
    lowest = []
    sim.cnc.mc.trace = lambda *counts: lowest.append(planner.v_raw)
    override(host, "FEED", 50)
    sim.run_for(0.1)
    assert planner.v_raw == pytest.approx(FEED / 60 * 0.5)
    assert min(lowest) > 0.9 * FEED / 60 * 0.5  # slowed down, never stopped on the path
    steps = [a - b for a, b in zip(lowest, lowest[1:], strict=False)]
    assert max(steps) <= planner.accel * 1e-3 + 1e-9  # braked at the acceleration, no jump
    assert measured_speed(sim, 0.5) == pytest.approx(FEED / 60 * 0.5, rel=0.03)
    assert latest_status(host).overrides == (50, 100, 100)
    override(host, "FEED", 150)
    sim.run_for(0.2)
    assert planner.v_raw == pytest.approx(planner.max_feed)  # 600 mm/min: capped at the maximum


def test_feed_override_is_kept_across_a_hold(sim, host):
    planner = running(sim, host, ["G01 X120 F400"])
    override(host, "FEED", 20)
    host.answer(host.realtime("HOLD"))
    host.wait(lambda f: isinstance(f, Status) and f.state == "HOLD")
    sim.run_for(0.5)
    assert planner.v_raw == 0.0
    host.answer(host.realtime("RESUME"))
    sim.run_for(0.3)
    assert planner.v_raw == pytest.approx(FEED / 60 * 0.2)
    status = host.wait(lambda f: isinstance(f, Status) and f.state == "RUN")
    assert status.overrides == (20, 100, 100)


def test_feed_override_reaches_the_queued_moves_too(sim, host):
    planner = running(sim, host, ["G01 X30 F400", "G01 X30 Y30 F300"])
    override(host, "FEED", 50)
    second = lambda: host.tick() or host.pump() or (planner.blocks and planner.blocks[0].move.seq == 1)  # noqa: E731
    assert sim.run_until(second, 30)
    sim.run_for(1.0)
    assert planner.v_raw == pytest.approx(300 / 60 * 0.5)


def test_rapid_override_scales_g00(sim, host):
    host.home()
    host.stream(["G00 X140"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and f.x > 5)
    planner = sim.cnc.mc.planner
    assert planner.v_raw == pytest.approx(planner.rapid)
    override(host, "RAPID", 25)
    sim.run_for(0.1)  # braking at the full deceleration from the frame's arrival on
    assert planner.v_raw <= planner.rapid - planner.accel * 0.09
    sim.run_for(0.1)
    assert planner.v_raw == pytest.approx(planner.rapid * 0.25)


def test_spindle_override_ramps_the_spindle(sim, host):
    running(sim, host, ["M03 S4000", "G01 X120 F400"])
    mc = sim.cnc.mc
    assert mc.spindle.target == pytest.approx(mc.spindle.effective(4000))
    override(host, "SPINDLE", 50)
    assert mc.spindle.target == pytest.approx(2000)
    now = mc.now_ms
    assert mc.spindle.true_rpm(now) > 3000  # a ramp, no jump
    sim.run_for(1.5)
    status = latest_status(host)
    assert status.rpm == pytest.approx(2000, rel=0.05) and status.overrides == (100, 50, 100)


def test_an_override_repeat_is_answered_again_and_a_reset_clears_them(sim, host):
    cid = host.realtime("FEED 130")
    host.answer(cid)
    start = len(host.frames)
    host.send(f"R {cid} FEED 130")
    host.wait(lambda f: isinstance(f, Ok) and f.id == cid, start=start)
    assert sim.cnc.mc.overrides.feed == 130
    host.send("R 77 FEED 300")  # out of range: a bad frame, nothing taken
    sim.run_for(0.1)
    assert sim.cnc.mc.overrides.feed == 130
    host.ok("RESET")
    status = host.wait(lambda f: isinstance(f, Status) and f.overrides == (100, 100, 100))
    assert status.overrides == (100, 100, 100)


def press(sim, *buttons):
    for button in buttons:
        sim.panel.press(button)
        sim.run_for(0.05)


def test_the_oled_menu_sets_the_overrides_of_an_sd_job_and_the_host_sees_them(sim, host, tmp_path):
    (tmp_path / "sd" / "long.nc").write_text("G01 X100 F400\nG00 X0\n")
    host.home()
    host.ok("SD RUN long.nc")
    moving = lambda: host.tick() or sim.cnc.mc.state == "RUN" and sim.cnc.mc.measured_mm[0] > 3  # noqa: E731
    assert sim.run_until(moving, 20)
    planner = sim.cnc.mc.planner
    press(sim, "OK", *["DOWN"] * 5, "OK")
    assert sim.panel.oled_text()[0] == "OVERRIDES"
    assert [row.split() for row in sim.panel.oled_text()[2:5]] == [["Spindle", "100%"], ["Rapid", "100%"],
                                                                    ["Reset", "all"]]
    assert sim.panel.oled_text()[1].split() == ["Feed", "100%"]
    press(sim, "OK", "DOWN", "DOWN", "DOWN")  # edit the feed: 70 %
    assert sim.panel.oled_text()[1].split() == [">Feed", "70%"]
    sim.run_for(0.2)
    assert planner.v_raw == pytest.approx(FEED / 60 * 0.7)
    press(sim, "EXIT", "DOWN", "DOWN", "OK", "DOWN")  # rapid one step down: 50 %
    assert sim.cnc.mc.overrides.as_tuple() == (70, 100, 50)
    assert host.wait(lambda f: isinstance(f, Status) and f.overrides == (70, 100, 50)).has("S")
    override(host, "FEED", 150)  # the host's own override during the SD job
    sim.run_for(0.2)
    assert planner.v_raw == pytest.approx(planner.max_feed)
    press(sim, "EXIT", "DOWN", "OK")  # Reset all
    assert sim.cnc.mc.overrides.as_tuple() == (100, 100, 100)
    press(sim, "EXIT")
    assert sim.panel.oled_text()[0] == "MENU"
