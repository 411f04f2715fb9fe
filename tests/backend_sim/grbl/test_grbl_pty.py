"""The GRBL driver end to end over a real pseudo-terminal (pyserial) against the GRBL
simulator served in this process (so the machine's own record can be read)."""

from __future__ import annotations

import io
import os
import shutil
import subprocess
from pathlib import Path

import pytest
import serial

from app.comm.console_client import ConsoleError, load_program
from app.comm.grbl.console import GrblConsole
from app.comm.grbl.dialect import grbl_lines
from backend_sim.grbl.simulator import GrblSimulator
from backend_sim.serve import PtyServer

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
MACRO = """o100 sub
  G0 X[#1] Y[#2] Z2
  G1 Z-1 F100
  G0 Z2
o100 endsub
#3 = 0
o101 while [#3 LT 4]
  o100 call [10 + #3 * 5] [20]
  #3 = [#3 + 1]
o101 endwhile
M30
"""


@pytest.fixture
def rig():
    sim = GrblSimulator()
    server = PtyServer(sim)
    sim.start(speed=30.0)
    server.start()
    port = serial.Serial(server.path, 115200, timeout=0)
    out = io.StringIO()
    console = GrblConsole(port, out=out, quiet=True, at_stops="continue", timeout=300.0)
    console.connect()
    console.sim, console.text = sim, out
    yield console
    port.close()
    server.close()
    sim.stop()


def pace(sim, speed: float) -> None:
    """The simulated machine's speed factor from now on."""
    with sim.lock:
        sim.clock.set_speed(speed)
        sim.wake()


def _job_lines(path) -> list[str]:
    program = load_program(str(path))
    return [line.text for line in grbl_lines(program.device_lines) if line.text]


def _executed(sim) -> list[str]:
    return [line for line in sim.machine.executed if line not in ("G21 G90 G94 G17", "G4 P0")]


@pytest.mark.parametrize("name", ["star_passes.ngc", "potrace_logo.ngc"])
def test_samples_stream_to_the_end_each_line_once(rig, name):
    # 300 times real time: the sample's short arcs at F300 still take far longer to cut than
    # to send at 115200 baud, so the planner and the receive buffer fill as at 30
    pace(rig.sim, 300.0)
    rig.cmd_home()  # unhomed, the machine does not know where it stands
    rig.cmd_check(str(SAMPLES / name)) if name == "potrace_logo.ngc" else rig.cmd_run(str(SAMPLES / name))
    assert _executed(rig.sim) == _job_lines(SAMPLES / name)
    assert rig.sim.machine.overflowed == 0
    assert "job completed" in rig.text.getvalue()


def test_a_macro_program_streams_with_its_expansion(rig, tmp_path):
    path = tmp_path / "holes.ngc"
    path.write_text(MACRO)
    rig.cmd_home()  # unhomed, the machine does not know where it stands
    rig.cmd_run(str(path))
    lines = _job_lines(path)
    assert _executed(rig.sim) == lines and sum(line.startswith("G01 Z-1") for line in lines) == 4


def test_an_error_mid_job_stops_it_naming_the_line(rig):
    rig.cmd_home()  # unhomed, the machine does not know where it stands
    lines = ["G01 X10 Y10 F300", "G01 X20", "G05 X1", "G01 X30", "G01 X40"] + ["G01 Y20"] * 20
    jobs = len(rig.printer.jobs)
    assert rig.session.start_job(lines, line_map=list(range(101, 126)))
    with pytest.raises(ConsoleError, match="line 103"):
        rig._wait_job(jobs)
    job = rig.printer.jobs[-1]
    assert job.refused == 2 and "buffer" in job.reason
    assert "G01 Y20" not in rig.sim.machine.executed[-3:] or len(rig.sim.machine.executed) < 25


def test_hold_resume_and_stop(rig):
    rig.cmd_home()  # unhomed, the machine does not know where it stands
    lines = ["G01 X10 Y10 F200"] + [f"G01 X{10 + i % 2 * 20} Y{10 + i}" for i in range(40)]
    rig.session.start_job(lines)
    rig.wait(lambda: rig.session.grbl_status.state == "Run", 10.0, "run")
    rig.cmd_hold()
    assert rig.session.grbl_status.state == "Hold"
    said = rig.text.getvalue()
    assert "machine HOLDS [Hold:0, machine]: feed hold complete: Resume goes on" in said  # in words
    rig.session.resume()
    rig.wait(lambda: rig.session.grbl_status.state == "Run", 10.0, "run again")
    assert "machine: running again" in rig.text.getvalue()[len(said):]
    rig.cmd_stop()
    job = rig.printer.jobs[-1]
    assert not job.completed and "operator" in job.reason
    rig._fresh_status()
    assert rig.session.grbl_status.state == "Idle"  # held before the reset: no alarm 3


def test_the_door_is_said_in_words(rig):
    rig.command("$X")  # out of the homing lock GRBL starts in
    rig.sim.set_door(True)
    rig.wait(lambda: rig.session.grbl_status.state == "Door", 10.0, "the door state")
    rig.sim.set_door(False)
    rig.wait(lambda: rig.session.grbl_status.substate == 0, 10.0, "the door closed")
    said = rig.text.getvalue()
    assert "[Door:1, cover]: safety door open: the machine stopped; close it to go on" in said
    assert "[Door:0, cover]: safety door closed: Resume goes on" in said


def test_overrides_reach_the_machine(rig):
    rig.session.set_feed_override(130)
    rig.session.set_spindle_override(80)
    rig.session.set_rapid_override(25)
    rig.wait(lambda: rig.session.grbl_status.overrides == (130, 25, 80), 10.0, "the overrides")
    assert rig.sim.machine.overrides == [130, 25, 80]


def test_hold_to_jog_and_its_cancel(rig):
    rig.cmd_home()  # unhomed, the machine does not know where it stands
    start = rig.session.grbl_status.mpos[0]
    rig.session.jog_to_limit("X", +1, 600)
    rig.wait(lambda: rig.session.grbl_status.state == "Jog", 10.0, "the jog")
    rig.wait(lambda: rig.session.grbl_status.mpos[0] > start + 2, 30.0, "some travel")
    rig.session.jog_cancel()
    rig.wait(lambda: rig.session.grbl_status.state == "Idle", 10.0, "the cancel")
    moved = rig.session.grbl_status.mpos[0] - start
    assert 2 < moved < 100


def test_settings_round_trip_and_backup_diff(rig, tmp_path):
    rig.cmd_settings("save", str(tmp_path / "backup.txt"))
    rig.command("$110=450")
    rig.cmd_settings("diff", str(tmp_path / "backup.txt"))
    assert "$110" in rig.text.getvalue() and "450" in rig.text.getvalue()
    rig.cmd_settings("restore", str(tmp_path / "backup.txt"))
    rig.command("$$")
    assert float(rig.session.settings[110]) == 600.0 == rig.sim.machine.settings[110]


def test_alarm_lock_home_and_unlock(rig):
    assert rig.session.status.state == "ALARM"
    with pytest.raises(ConsoleError, match="error:9"):
        rig.command("G0 X1")
    rig.cmd_home()
    rig._fresh_status()
    assert rig.session.status.state == "IDLE" and rig.session.homed
    rig.sim.trip_limit("X")
    rig.wait(lambda: rig.session.alarm == 1, 10.0, "the limit alarm")
    assert "ALARM:1 hard limit switch hit" in rig.text.getvalue()
    rig.cmd_reset()
    rig.cmd_unlock()
    rig._fresh_status()
    assert rig.session.status.state == "IDLE"


def test_check_mode_lists_refused_lines_and_leaves_the_machine_still(rig):
    rig.cmd_unlock()
    rig.command("$C")
    lines = ["G01 X10 F100", "G05 X1", "G01 X20", "G38.2 Z-5 F10"]
    jobs = len(rig.printer.jobs)
    rig.session.start_job(lines)
    with pytest.raises(ConsoleError, match="2 refused"):
        rig._wait_job(jobs)
    assert rig.sim.machine.motion.state == "IDLE"
    rig.command("$C")
    assert not rig.session.check_mode


@pytest.mark.skipif(not os.environ.get("GRBL_SIM"), reason="GRBL_SIM does not name grbl-sim's executable")
def test_the_real_firmware_simulator(tmp_path):
    """grbl-sim (GRBL's own code on the computer) on a pty: the driver must satisfy it."""
    exe = shutil.which(os.environ["GRBL_SIM"]) or os.environ["GRBL_SIM"]
    socat = shutil.which("socat")
    if socat is None:
        pytest.skip("socat is needed to put grbl-sim on a pty")
    link = tmp_path / "grbl"
    proc = subprocess.Popen([socat, f"PTY,raw,echo=0,link={link}",
                             f"EXEC:{exe} -n -s /dev/null,pty,raw,echo=0"], cwd=tmp_path)  # its EEPROM.DAT
    try:
        for _ in range(100):
            if link.exists():
                break
            subprocess.run(["sleep", "0.05"], check=True)
        port = serial.Serial(str(link), 115200, timeout=0)
        out = io.StringIO()
        console = GrblConsole(port, out=out, quiet=True, at_stops="continue", timeout=600.0)
        console.connect()
        if console.session.alarm is not None:
            console.cmd_unlock()
        console.cmd_check(str(SAMPLES / "star_passes.ngc"))
        assert "job completed" in out.getvalue()
        port.close()
    finally:
        proc.terminate()
        proc.wait(5)


def test_link_loss_mid_job_offers_start_here_and_finishes(rig):
    rig.cmd_home()  # unhomed, the machine does not know where it stands
    lines = ["G01 X10 Y10 F600"] + [f"G01 X{10 + (i % 2) * 30} Y{10 + i}" for i in range(60)]
    rig.session.start_job(lines)
    rig.wait(lambda: rig.session.job is not None and rig.session.job.acked >= 20, 60.0, "some lines")
    path = rig.transport.port
    rig.transport.close()
    rig.session.detach("unplugged")
    assert rig.session.state.name == "INTERRUPTED"
    rig.transport = serial.Serial(path, 115200, timeout=0)
    rig.session.attach(rig.transport.write)
    rig.wait(lambda: rig.session.state.name == "RESTART_REQUIRED", 60.0, "the offer", through_loss=True)
    offered = rig.session.last_job.done + 1
    assert 0 < offered <= 61
    rig.wait(lambda: rig.session.grbl_status.state == "Idle", 120.0, "the machine to finish its buffer")
    job = rig.session.last_job
    assert job.done == job.acked  # the offer followed the buffer the machine ran meanwhile
    start = job.done + 1
    assert start >= offered and rig.session.state.name == "RESTART_REQUIRED"
    jobs = len(rig.printer.jobs)
    assert rig.session.confirm_restart()
    rig._wait_job(jobs)
    executed = _executed(rig.sim)
    assert executed[-(len(lines) - start):] == lines[start:]  # the restart ran each line once
    assert all(line in executed for line in lines)
