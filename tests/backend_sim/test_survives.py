"""Issue 18: the machine survives what the world does to it (docs/protocol.md,
"Machine conventions"): a full card, a full disk under the exec log, an upload onto
the running file, SPINDLE OFF while jogging, one grammar for SET values, the value
ranges of the host's loader."""

import pytest

from app.comm.frame import Alarm, Data, Error, Log, Ok, Status
from backend_sim.simulator import Simulator
from tests.backend_sim.conftest import FAST_HOMING
from tests.backend_sim.full_disk import FullDisk
from tests.backend_sim.helpers import Host
from tests.backend_sim.test_main_mcu import PROGRAM, put

OLD = ["G00 Z9", "G00 X1 Y1"]
UPLOAD_BYTES = len("\n".join(PROGRAM)) + 1


@pytest.mark.parametrize("budget", [0, 1, 6, 7, 20, UPLOAD_BYTES - 1])
def test_full_card_during_sd_put_is_sd_full_and_the_machine_answers_on(sim, host, tmp_path, budget):
    assert isinstance(put(host, "part.ngc", OLD), Ok)
    disk = FullDisk(budget)
    sim.sd.open_for_write = disk.open
    refusal = put(host, "part.ngc", PROGRAM)
    assert isinstance(refusal, Error) and refusal.code == "SD_FULL", refusal
    assert "No space" in refusal.text and disk.failures == 1
    folder = tmp_path / "sd"
    assert sorted(p.name for p in folder.iterdir()) == ["part.ngc"], "the partial file was left"
    assert (folder / "part.ngc").read_text() == "\n".join(OLD) + "\n"
    assert sim.main.upload is None and sim.running is False
    assert host.ok("SD LIST").info == "LIST 1"
    del sim.sd.open_for_write  # the card has room again
    assert isinstance(put(host, "part.ngc", PROGRAM), Ok)
    assert (folder / "part.ngc").read_text() == "\n".join(PROGRAM) + "\n"


def test_an_io_error_of_the_card_is_sd_error(sim, host, tmp_path):
    def broken(path, mode="wb"):
        raise OSError(5, "Input/output error")

    sim.sd.open_for_write = broken
    assert put(host, "part.ngc", PROGRAM).code == "SD_ERROR"
    assert list((tmp_path / "sd").iterdir()) == []
    host.ok("SD LIST")


@pytest.mark.parametrize("budget", [0, 3, 12, 40])
def test_full_disk_under_the_exec_log_stops_the_job_with_an_alarm(tmp_path, budget):
    log = tmp_path / "exec.log"
    sim = Simulator(FAST_HOMING, sd_dir=tmp_path / "sd", seed=1, exec_log=log)
    disk = FullDisk(budget, raw=True)
    sim.exec_log.open_append = disk.open
    host = Host(sim)
    host.send("C 999999 PING")
    host.wait(lambda f: f.KIND == "S")
    host.home()
    program = [f"G01 X{k % 7 + 1} Y{k % 5 + 1} F3000" for k in range(40)]
    alarm = stream_until_alarm(sim, host, program)
    assert "not logged" in alarm.text and "No space" in alarm.text
    host.wait(lambda f: isinstance(f, Status) and f.state == "IDLE", timeout=30)
    text = log.read_bytes()
    assert text == b"" or text.endswith(b"\n"), "a torn line was left"
    logged = [line.split("\t", 1) for line in text.decode().splitlines()]
    assert [(int(seq), line) for seq, line in logged] == [(k, program[k]) for k in range(len(logged))]
    assert len(logged) < len(program)
    assert not sim.cnc.job.open
    host.ok("GET FERR")  # the link is up, the machine answers


def stream_until_alarm(sim, host, program: list[str]) -> Alarm:
    """Stream ``program`` within the credit window until ``X EXEC_LOG`` comes."""
    host.ok(f"JOB {len(program)}")
    alarms = lambda: [f for f in host.frames if isinstance(f, Alarm) and f.code == "EXEC_LOG"]  # noqa: E731
    for seq, line in enumerate(program):
        def room(seq=seq) -> bool:
            host.tick()
            host.pump()
            return bool(alarms()) or seq - 1 - host.acked < min(host.free, 8)

        assert sim.run_until(room, 60)
        if alarms():
            break
        host.send(Data(seq, line).body())
    assert sim.run_until(lambda: host.tick() or host.pump() or alarms(), 60), "no X EXEC_LOG"
    return alarms()[0]


def test_sd_put_onto_the_running_file_is_busy(sim, host):
    lines = [f"G01 X{k % 9 + 1} F600" for k in range(30)]
    assert isinstance(put(host, "run.ngc", lines), Ok)
    host.home()
    host.ok("SD RUN run.ngc")
    assert host.refused("SD PUT run.ngc 5 1234").code == "BUSY"
    assert host.refused("SD DEL run.ngc").code == "BUSY"
    assert sim.main.upload is None
    assert isinstance(put(host, "other.ngc", PROGRAM), Ok)  # another file is fine


def test_spindle_off_during_a_long_jog_is_allowed(sim, host):
    host.home()
    host.ok("SPINDLE 2000", timeout=20)
    jog = host.command("JOG X 100 60")
    host.wait(lambda f: isinstance(f, Status) and f.state == "JOG")
    off = host.ok("SPINDLE OFF")
    assert off.info == "OFF"
    assert sim.cnc.mc.state == "JOG" and not sim.cnc.mc.spindle_on
    host.ok("STOP")
    host.wait(lambda f: isinstance(f, Ok | Error) and f.id == jog, start=0)


def test_spindle_off_during_a_job_holds_it_and_resume_spins_back(sim, host):
    host.home()
    program = ["M03 S2000"] + [f"G01 X{k % 9 + 1} F300" for k in range(10)]
    host.stream(program, len(program))
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and "P" in f.flags, timeout=30)
    host.ok("SPINDLE OFF")
    host.wait(lambda f: isinstance(f, Status) and f.state == "HOLD" and "P" not in f.flags, timeout=10)
    host.ok("RESUME")
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN" and "P" in f.flags, timeout=30)
    host.wait(lambda f: f.KIND == "F" and f.seq == len(program) - 1, timeout=120)


@pytest.mark.parametrize("text", ["SET OPTSTOP -0", "SET AFTERJOB 3.0", "SET CHECK 01", "SET CHECK +1",
                                  "SET STOPSPINDLE 1.", "SET AFTERJOB 03", "SET OPTSTOP .0", "SET CHECK 1.0"])
def test_one_grammar_for_every_set_choice(sim, host, text):
    assert host.refused(text).code == "BAD_ARGS"


@pytest.mark.parametrize("text,code", [("SET AFTERJOB 4", "BAD_PARAM"), ("SET CHECK 2", "BAD_PARAM"),
                                       ("SET FERR 0.01", "BAD_PARAM"), ("SET KP_X -1", "BAD_PARAM")])
def test_a_value_outside_its_range_is_bad_param(sim, host, text, code):
    assert host.refused(text).code == code


@pytest.mark.parametrize("text", ["SET OPTSTOP 0", "SET AFTERJOB 3", "SET CHECK 1", "SET FERR 2.5",
                                  "SET KP_X 10.", "SET KD .5"])
def test_set_values_in_the_grammar_are_taken(sim, host, text):
    assert host.ok(text).info == text[4:]


@pytest.mark.parametrize("line", ["G04 P1000000000", "G04 P3600.001", "G01 X10 F0.0001",
                                  "G00 X1000001", "G02 X1 Y1 I2000000 J0 F100", "M03 S1000000000",
                                  "G01 X1 F1000000000"])
def test_the_machine_refuses_what_the_loader_refuses(sim, host, line):
    host.home()
    host.ok("JOB 1")
    host.send(Data(0, line).body())
    refusal = host.wait(lambda f: isinstance(f, Error) and f.id is None)
    assert refusal.code == "BAD_VALUE", refusal
    assert refusal.text.startswith("0 ")


@pytest.mark.parametrize("line", ["G04 P3600", "G01 X10 F0.001", "M03 S3000"])
def test_the_edges_of_the_ranges_are_taken(sim, host, line):
    host.ok("SET CHECK 1")
    host.ok("JOB 1")
    host.send(Data(0, line).body())
    host.wait(lambda f: f.KIND == "F" and f.seq == 0)


@pytest.mark.parametrize("text", ["JOG X 1000001 300", "JOG X 1 0.0001", "JOG X 1 1000000000",
                                  "SPINDLE 1000000000"])
def test_jog_and_spindle_values_out_of_range_are_bad_value(sim, host, text):
    host.home()
    assert host.refused(text).code == "BAD_VALUE"


def test_the_machine_s_numbers_are_the_loader_s():
    from app.gcode import limits
    from app.gcode.motion import LIMIT_MM
    from backend_sim import value_ranges

    assert value_ranges.MAX_NUMBER == limits.MAX_NUMBER
    assert value_ranges.MIN_FEED == limits.MIN_FEED
    assert value_ranges.MAX_DWELL_S == limits.MAX_DWELL_S
    assert value_ranges.MAX_COORD_MM == LIMIT_MM


def test_logs_say_nothing_of_a_healthy_upload(sim, host):
    assert isinstance(put(host, "a.ngc", PROGRAM), Ok)
    assert not [f for f in host.of(Log) if "abandoned" in f.text]


def test_pause_during_a_jog_is_answered_once_stopped(sim, host):
    """Found by the conformance kit: a PAUSE that cancelled a jog was never answered."""
    host.home()
    jog = host.command("JOG X 100 300")
    host.wait(lambda f: isinstance(f, Status) and f.state == "JOG")
    assert host.ok("PAUSE", timeout=10).verb == "PAUSE"
    assert sim.cnc.mc.state == "IDLE" and sim.cnc.mc.commanded_mm[0] < 100
    host.wait(lambda f: isinstance(f, Ok | Error) and f.id == jog, start=0)


def test_pause_during_homing_stops_it_and_is_answered(sim, host):
    home = host.command("HOME")
    host.wait(lambda f: isinstance(f, Status) and f.state == "HOMING")
    assert host.ok("PAUSE", timeout=10).verb == "PAUSE"
    assert sim.cnc.mc.state == "IDLE" and not sim.cnc.mc.homed
    refusal = host.wait(lambda f: isinstance(f, Ok | Error) and f.id == home, start=0, timeout=5)
    assert isinstance(refusal, Error) and refusal.code == "NOT_HOMED" and "PAUSE" in refusal.text


def test_stop_during_homing_answers_the_home(sim, host):
    home = host.command("HOME")
    host.wait(lambda f: isinstance(f, Status) and f.state == "HOMING")
    host.ok("STOP", timeout=10)
    refusal = host.wait(lambda f: isinstance(f, Ok | Error) and f.id == home, start=0, timeout=5)
    assert isinstance(refusal, Error) and refusal.code == "NOT_HOMED"


def test_two_copies_of_r_reset_in_one_chunk_reset_once(sim, host):
    """Found by the conformance kit under load: the host writes each R frame twice back to
    back; when both copies reached the CNC MCU in one chunk, the reset made it forget the
    id and the second copy reset it again (a new boot the host never asked for)."""
    from app.comm.frame import seal

    boots = []
    send = sim.cnc.send
    sim.cnc.send = lambda frame: (boots.append(frame) if isinstance(frame, Alarm) and frame.code == "BOOT"
                                  else None) or send(frame)
    with sim.lock:
        sim.cnc.receive(seal("R 77 RESET") * 2)
        sim.cnc.receive(seal("R 77 RESET"))
    assert len(boots) == 1
