"""Issue 21, hold-to-jog on the host: the grammar of the two new ``R`` verbs, the
keep-alives of ``HoldToJog`` on a fake clock, and the session against the simulator
(press, hold, release, stop, lost link), all on simulated time."""

from __future__ import annotations

import itertools

import pytest

from app.comm.frame import Error, FrameError, Ok, RealtimeCommand, decode, parse_body
from app.comm.hold_jog import COPIES, KEEP_ALIVE_S, HoldToJog, directions
from tests.comm.simlink import FAST_HOMING, SimLink


@pytest.mark.parametrize("body, args", [("R 7 JOG X+ 600", ("X+", "600")),
                                        ("R 7 JOG X-Z+ 12.5", ("X-Z+", "12.5")), ("R 7 JOGEND", ())])
def test_jog_frames_round_trip(body, args):
    frame = parse_body(body)
    assert isinstance(frame, RealtimeCommand) and frame.args == args and frame.why == ""
    assert decode(frame.encode()) == frame


@pytest.mark.parametrize("body", ["R 7 JOG X+X- 600", "R 7 JOG X+Y+Z+ 600", "R 7 JOG X 600", "R 7 JOG X+ 0",
                                  "R 7 JOG X+ -5", "R 7 JOG X+ 1e3", "R 7 JOG X+", "R 7 JOG X+ 600 HOST",
                                  "R 7 JOGEND LINK", "R 7 JOG x+ 600", "R 7 JOG  X+ 600"])
def test_jog_frames_outside_the_grammar_are_bad(body):
    with pytest.raises(FrameError):
        parse_body(body)


def test_directions_combine_keys():
    assert directions(["Y+", "X+"]) == "X+Y+"
    assert directions(["X+", "X-"]) == ""  # opposite keys cancel out
    assert directions(["X+", "X-", "Z-"]) == "Z-"
    assert directions(["X+", "Y-", "Z+"]) == "X+Y-"  # at most two axes
    assert directions([]) == ""


def test_keep_alives_are_new_ids_two_copies_every_25_ms_and_stop_on_release():
    jog = HoldToJog(itertools.count(100).__next__)
    assert jog.due(0.0) == []
    assert not jog.hold(("X+",), 600)
    first = jog.due(0.0)
    assert len(first) == COPIES and first[0] == first[1] and first[0].args == ("X+", "600")
    assert jog.due(0.01) == []
    second = jog.due(KEEP_ALIVE_S)
    assert second[0].id > first[0].id
    jog.hold(("X+", "Y+"), 600)
    assert jog.due(KEEP_ALIVE_S + 0.001)[0].args[0] == "X+Y+"  # a new direction goes out at once
    assert jog.hold((), 600) is True  # released: the caller sends JOGEND
    assert jog.due(1.0) == []


def test_a_soft_limit_refusal_ends_keep_alives_until_the_keys_change_busy_does_not():
    jog = HoldToJog(itertools.count(1).__next__)
    jog.hold(("X+",), 600)
    sent = jog.due(0.0)[0]
    assert jog.on_answer(Error(sent.id, "BUSY", "jog changes direction")) and jog.jogging
    sent = jog.due(1.0)[0]
    assert jog.on_answer(Error(sent.id, "SOFT_LIMIT", "X+ at 150"))
    assert not jog.jogging and jog.due(2.0) == [] and jog.refused.code == "SOFT_LIMIT"
    assert not jog.hold(("X+",), 600)  # same keys: still refused
    assert jog.due(3.0) == []
    jog.hold(("X-",), 600)
    assert jog.due(4.0)[0].args[0] == "X-"
    assert not jog.on_answer(Ok(99999, "STOP", "IDLE"))  # not ours


@pytest.fixture
def link(tmp_path):
    link = SimLink(seed=3, sd_dir=tmp_path, check=False, profile=FAST_HOMING)
    link.home()
    return link


def sent_verbs(link) -> list[str]:
    return [e.text.split(" ")[2] for e in link.rec.of("on_frame") if e.direction == "tx" and e.kind == "R"]


def test_session_jogs_while_held_and_stops_within_50_ms_plus_deceleration_of_release(link):
    x0 = link.sim.cnc.mc.commanded_mm[0]
    assert link.session.jog_hold(("X+",), 600)
    link.run_for(1.0)
    assert link.sim.cnc.mc.state == "JOG" and link.sim.cnc.mc.commanded_mm[0] > x0 + 5
    assert link.session.jog_hold((), 600)
    released = link.now
    assert link.run_until(lambda: link.sim.cnc.mc.state == "IDLE", 1.0)
    decel = 600 / 60 / link.sim.profile.motion.accel_mm_s2
    assert link.now - released < 0.05 + 1.5 * decel
    assert "JOGEND" in sent_verbs(link)
    assert not any("no keep-alive" in e.text for e in link.rec.of("on_log"))


def test_session_runs_into_the_soft_limit_and_says_so_without_an_alarm(link):
    link.command_ok("JOG", "X", 3, 600)
    link.session.jog_hold(("X-",), 600)
    link.run_for(1.5)
    assert link.sim.cnc.mc.commanded_mm[0] == pytest.approx(0.0, abs=1e-6)
    texts = [e.text for e in link.rec.of("on_log")]
    assert "jog stopped at the soft limit X- 0" in texts
    assert any("the jog stopped: SOFT_LIMIT X- at 0" in t for t in texts)
    assert not link.session.hold_jog.jogging
    assert [a.code for a in link.rec.of("on_alarm")] == ["BOOT"]  # power-up only, no alarm of the jog


@pytest.mark.parametrize("how", ["stop", "pause"])
def test_stop_and_hold_cancel_a_held_jog(link, how):
    link.session.jog_hold(("Y+",), 600)
    link.run_for(0.5)
    getattr(link.session, how)()
    assert not link.session.hold_jog.jogging
    assert link.run_until(lambda: link.sim.cnc.mc.state == "IDLE" and not link.sim.cnc.mc.stopping, 1.0)
    y = link.sim.cnc.mc.commanded_mm[1]
    link.run_for(0.5)
    assert link.sim.cnc.mc.commanded_mm[1] == y


def test_a_lost_link_stops_the_keep_alives_and_the_machine_stops_by_its_dead_man(link):
    link.session.jog_hold(("X+",), 600)
    link.run_for(0.5)
    link.sim.faults.unplug()
    cut = link.now
    assert link.run_until(lambda: link.sim.cnc.mc.state == "IDLE", 1.0)
    assert link.now - cut < 0.25 + 0.025 + 0.3
    assert link.run_until(lambda: not link.session.hold_jog.jogging, 5.0)  # the session saw the link lost


def test_no_jog_during_a_job_or_without_a_link(link):
    link.session.detach("test")
    assert not link.session.jog_hold(("X+",), 600)


def test_hold_to_jog_at_a_program_stop_then_resume_finishes_the_job(link):
    """Touch-off (docs/protocol.md, "Program stops and tool changes"): during a job the
    keys jog only while the machine holds at a stop (flag ``W``); the job then goes on."""
    lines = ["G00 X10 Y10 Z5", "G01 Z-1 F300", "M06 T2", "G01 X20 F300"]
    assert link.session.start_job(lines)
    status = lambda: link.session.status  # noqa: E731
    assert link.run_until(lambda: status() is not None and status().state == "RUN", 10.0)
    assert not link.session.jog_hold(("Z-",), 300)  # running: no jog
    assert link.run_until(lambda: status() is not None and "W" in status().flags, 60.0)
    z = link.sim.cnc.mc.commanded_mm[2]
    assert link.session.jog_hold(("Z-",), 300)
    link.run_for(0.5)
    assert link.sim.cnc.mc.state == "JOG" and link.sim.cnc.mc.commanded_mm[2] < z - 1
    assert link.session.jog_hold((), 300)
    assert link.run_until(lambda: status().state == "HOLD" and "W" in status().flags, 5.0)
    assert link.session.resume()
    ended = lambda: link.rec.of("on_job_finished")  # noqa: E731
    assert link.run_until(ended, 60.0) and link.rec.last("on_job_finished").completed
    assert [seq for seq, _ in link.executed()] == list(range(len(lines)))
