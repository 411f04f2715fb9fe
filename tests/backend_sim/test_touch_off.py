"""Touch-off at a program stop on the simulator (docs/protocol.md, "Program stops and
tool changes": jog and ``ZERO`` taken while ``W``; ``RESUME`` returns to the held
position in work coordinates under the offset in force)."""

from __future__ import annotations

import pytest

from app.comm.frame import Error, Finished, Log, Ok, Status
from backend_sim.simulator import Simulator
from tests.backend_sim.conftest import FAST_HOMING
from tests.backend_sim.helpers import Host

# machine Z travel 0..30, work zero Z at machine 20: the top of the travel is work Z 10
PROGRAM = ["G00 X10 Y10 Z5", "G01 Z-2 F300", "G01 X20", "M06 T2", "G01 X30", "G01 Y20", "M05"]
STOP_SEQ = 3
TOL = 0.15  # measured positions: the simple mode's stepping overshoots a little


@pytest.fixture(params=["planner", "simple"])
def rig(request, tmp_path):
    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=1, mode=request.param)
    host = Host(sim)
    host.send("C 999999 PING")
    host.wait(lambda f: f.KIND == "S")
    host.home()
    yield sim, host
    sim.stop()


def _at_stop(sim, host) -> Status:
    host.stream(PROGRAM)
    host.wait(lambda f: isinstance(f, Log) and f.text.startswith(f"STOP {STOP_SEQ} "), 60)
    return _status(host, lambda s: s.state == "HOLD" and "W" in s.flags)


def _status(host, match, start=None) -> Status:
    return host.wait(lambda f: isinstance(f, Status) and match(f), 30, start)


def _answer(host, cid, timeout=30.0, start=None):
    return host.wait(lambda f: isinstance(f, Ok | Error) and f.id == cid, timeout, start)


def test_jog_and_zero_at_a_tool_change_and_resume_returns_under_the_new_offset(rig):
    sim, host = rig
    held = _at_stop(sim, host)
    assert (held.x, held.y, held.z) == pytest.approx((20.0, 10.0, 10.0), abs=TOL)
    start = len(host.frames)
    cid = host.command("JOG Z -12 600")
    jogging = _status(host, lambda s: s.state == "JOG")
    assert "W" in jogging.flags and jogging.why == "PROG"
    ok = _answer(host, cid)
    assert isinstance(ok, Ok) and ok.info == "Z -12"
    after = _status(host, lambda s: s.state == "HOLD")
    assert "W" in after.flags and after.z == pytest.approx(-2.0, abs=TOL)
    zero = host.ok("ZERO Z")
    assert zero.info.endswith("Z18.000")  # the new zero, machine mm
    host.ok("JOG Z 5 600")
    host.ok("JOG X 3 600")
    assert [seq for seq, _ in sim.exec_log] == [0, 1, 2]  # nothing of the job ran meanwhile
    assert not [f for f in host.frames[start:] if isinstance(f, Finished) and f.seq >= STOP_SEQ]
    host.ok("RESUME")
    host.wait(lambda f: isinstance(f, Finished) and f.seq >= STOP_SEQ, 60)
    assert sim.cnc.mc.commanded_mm[2] == pytest.approx(16.0, abs=1e-3)  # 18 - 2: the new tool's tip
    host.wait(lambda f: isinstance(f, Finished) and f.seq == len(PROGRAM) - 1, 60)
    cut = [f for f in host.of(Status) if f.done >= STOP_SEQ and f.x > 20.5]
    assert cut and all(f.z == pytest.approx(-2.0, abs=0.05) for f in cut)
    assert [seq for seq, _ in sim.exec_log] == list(range(len(PROGRAM)))


def test_the_way_back_lifts_first_then_x_y_then_down(rig):
    sim, host = rig
    _at_stop(sim, host)
    host.ok("JOG Z -12 600")
    host.ok("JOG X 5 600")
    start = len(host.frames)
    host.ok("RESUME")
    host.wait(lambda f: isinstance(f, Finished) and f.seq >= STOP_SEQ, 60)
    path = [(f.x, f.y, f.z) for f in host.frames[start:] if isinstance(f, Status)]
    top = max(range(len(path)), key=lambda k: path[k][2])
    assert path[top][2] == pytest.approx(10.0, abs=TOL)  # up to the top before X moves back
    assert all(x > 24.8 for x, _, _ in path[:top])
    assert all(z > 10.0 - TOL for x, _, z in path if 20.2 < x < 24.8)  # X back at the top
    host.wait(lambda f: isinstance(f, Finished) and f.seq == len(PROGRAM) - 1, 60)
    cut = [f for f in host.of(Status) if f.done >= STOP_SEQ and f.x > 20.5]
    assert cut and all(f.z == pytest.approx(-2.0, abs=0.05) for f in cut)  # no new zero: where it was


def test_what_stays_busy_at_a_stop_soft_limits_and_stop_ends_the_job(rig):
    sim, host = rig
    _at_stop(sim, host)
    assert host.refused("HOME").code == "BUSY"
    assert host.refused("SPINDLE 1000").code == "BUSY"
    assert host.refused("SET WCS 55").code == "BUSY"
    limit = host.refused("JOG Z -40 600")
    assert limit.code == "SOFT_LIMIT"
    _status(host, lambda s: s.state == "HOLD" and "W" in s.flags)
    host.command("JOG Z -10 60")  # slow: still running when ZERO and STOP come
    _status(host, lambda s: s.state == "JOG" and "W" in s.flags)
    assert host.refused("ZERO Z").code == "BUSY"
    assert host.refused("RESUME").code == "BUSY"
    cid = host.realtime("RESUME")
    assert _answer(host, cid).code == "BUSY"
    host.ok("STOP")
    idle = _status(host, lambda s: s.state == "IDLE")
    assert "W" not in idle.flags
    assert [seq for seq, _ in sim.exec_log] == [0, 1, 2]


def test_continuous_jog_at_a_stop_ends_back_at_the_stop(rig):
    sim, host = rig
    _at_stop(sim, host)
    cid = host.realtime("JOG Z- 300")
    assert isinstance(_answer(host, cid), Ok)
    _status(host, lambda s: s.state == "JOG" and "W" in s.flags)
    for _ in range(5):  # the key held for half a second: a keep-alive every 0.1 s
        sim.run_for(0.1)
        host.realtime("JOG Z- 300")
    cid = host.realtime("JOGEND")
    start = len(host.frames)
    assert isinstance(_answer(host, cid), Ok)
    held = _status(host, lambda s: s.state == "HOLD" and "W" in s.flags, start)
    assert held.z < 9.5
    host.ok("RESUME")
    host.wait(lambda f: isinstance(f, Finished) and f.seq == len(PROGRAM) - 1, 60)
    assert [seq for seq, _ in sim.exec_log] == list(range(len(PROGRAM)))


def test_a_pause_or_the_cover_ends_a_touch_off_jog_and_the_job_still_goes_on(rig):
    sim, host = rig
    _at_stop(sim, host)
    start = len(host.frames)
    jog = host.command("JOG Z -10 60")
    _status(host, lambda s: s.state == "JOG" and "W" in s.flags)
    host.ok("PAUSE")  # answered once the jog has stopped
    assert isinstance(_answer(host, jog, start=start), Ok)
    _status(host, lambda s: s.state == "HOLD" and "W" in s.flags)
    start = len(host.frames)
    jog = host.command("JOG Z -5 60")
    _status(host, lambda s: s.state == "JOG" and "W" in s.flags)
    sim.faults.open_cover()
    assert _answer(host, jog, start=start).code == "COVER_OPEN"
    _status(host, lambda s: s.state == "HOLD" and "W" in s.flags and "C" in s.flags)
    assert host.refused("RESUME").code == "COVER_OPEN"
    sim.faults.close_cover()
    host.ok("RESUME")
    host.wait(lambda f: isinstance(f, Finished) and f.seq == len(PROGRAM) - 1, 60)
    assert [seq for seq, _ in sim.exec_log] == list(range(len(PROGRAM)))
    cut = [f for f in host.of(Status) if f.done >= STOP_SEQ and f.x > 20.5]
    assert cut and all(f.z == pytest.approx(-2.0, abs=0.05) for f in cut)


def test_touch_off_in_a_job_run_from_the_sd_card(rig, tmp_path):
    sim, host = rig
    (tmp_path / "sd" / "tool.nc").write_text("\n".join(PROGRAM) + "\n")
    host.ok("SD RUN tool.nc")
    host.wait(lambda f: isinstance(f, Log) and f.text.startswith(f"STOP {STOP_SEQ} "), 60)
    _status(host, lambda s: s.state == "HOLD" and "W" in s.flags and "S" in s.flags)
    host.ok("JOG Z -12 600")
    host.ok("ZERO Z")
    host.ok("RESUME")
    assert sim.run_until(lambda: sim.main.sd_job is None, 60)
    assert [seq for seq, _ in sim.exec_log] == list(range(len(PROGRAM)))
    cut = [f for f in host.of(Status) if f.done >= STOP_SEQ and f.x > 20.5 and "S" in f.flags]
    assert cut and all(f.z == pytest.approx(-2.0, abs=0.05) for f in cut)  # under the new zero


def test_a_continuous_jog_is_busy_while_a_step_jog_runs_at_the_stop(rig):
    sim, host = rig
    _at_stop(sim, host)
    host.command("JOG Z -10 60")
    _status(host, lambda s: s.state == "JOG" and "W" in s.flags)
    cid = host.realtime("JOG X+ 300")
    assert _answer(host, cid).code == "BUSY"
