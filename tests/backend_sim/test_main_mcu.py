"""The main MCU: heartbeat and UART watchdogs, SD card commands, SD RUN, relaying."""

from __future__ import annotations

import zlib

import pytest

from app.comm.frame import Ack, Alarm, Data, Error, Info, Log, Nak, Ok, Status
from backend_sim.sd_card import crc32_of_lines

PROGRAM = ["G00 Z5", "G00 X5 Y5", "G01 Z4 F600", "G01 X8", "G00 Z5"]


def put(host, name: str, lines: list[str], crc: int | None = None):
    crc = crc32_of_lines(lines) if crc is None else crc
    cid = host.command(f"SD PUT {name} {len(lines)} {crc:08x}")
    for seq, line in enumerate(lines):
        host.send(Data(seq, line).body())
    return host.answer(cid)


def test_host_lost_after_3_s_then_back(sim, host):
    host.heartbeat = False
    t0 = sim.clock.now
    alarm = host.wait(lambda f: isinstance(f, Alarm) and f.code == "HOST_LOST", timeout=5)
    assert alarm and 2.9 <= sim.clock.now - t0 <= 3.1
    assert sim.main.host_lost
    leds = set()
    beeps = set()
    for _ in range(20):
        sim.run_for(0.05)
        leds.add(sim.panel.led)
        beeps.add(sim.panel.buzzer)
    assert leds == {True, False} and beeps == {True, False}
    host.heartbeat = True
    host.command("PING")
    host.wait(lambda f: isinstance(f, Status) and not f.has("L"), timeout=0.2)
    assert not sim.main.host_lost and not sim.panel.buzzer


def test_uart_lost_and_back(sim, host):
    sim.faults.cut_uart()
    host.wait(lambda f: isinstance(f, Alarm) and f.code == "UART_LOST", timeout=5)
    host.command("STATUS")
    assert host.wait(lambda f: isinstance(f, Status)).has("U")
    sim.faults.restore_uart()
    sim.run_for(1.5)
    host.command("STATUS")
    assert not host.wait(lambda f: isinstance(f, Status)).has("U")


def test_sd_put_list_delete_round_trip(sim, host, tmp_path):
    answer = put(host, "part.nc", PROGRAM)
    assert isinstance(answer, Ok) and answer.info == "PUT part.nc"
    data = (tmp_path / "sd" / "part.nc").read_bytes()
    assert data == ("\n".join(PROGRAM) + "\n").encode()
    assert zlib.crc32(data) == crc32_of_lines(PROGRAM)
    acks = [a.seq for a in host.of(Ack)]
    assert acks == list(range(len(PROGRAM)))
    cid = host.command("SD LIST")
    host.answer(cid)
    rows = [f.text for f in host.of(Info) if f.id == cid]
    assert rows == [f"part.nc {len(data)} {len(PROGRAM)}"]
    assert host.ok("SD DEL part.nc").info == "DEL part.nc"
    assert host.refused("SD DEL part.nc").code == "NO_FILE"


def test_sd_put_crc_mismatch_leaves_no_file(sim, host, tmp_path):
    answer = put(host, "bad.nc", PROGRAM, crc=crc32_of_lines(PROGRAM) ^ 1)
    assert isinstance(answer, Error) and answer.code == "CRC_MISMATCH"
    assert list((tmp_path / "sd").iterdir()) == []


def test_sd_put_gap_is_naked_and_resent(sim, host, tmp_path):
    cid = host.command(f"SD PUT g.nc 3 {crc32_of_lines(PROGRAM[:3]):08x}")
    host.send(Data(0, PROGRAM[0]).body())
    host.send(Data(2, PROGRAM[2]).body())
    assert host.wait(lambda f: isinstance(f, Nak)).seq == 1
    host.send(Data(1, PROGRAM[1]).body())
    host.send(Data(2, PROGRAM[2]).body())
    assert isinstance(host.answer(cid), Ok)
    assert (tmp_path / "sd" / "g.nc").exists()


@pytest.mark.parametrize("name", ["../x.nc", "a/b", "..", ".hidden", "x" * 33, "sp ace", "star*"])
def test_bad_sd_names_are_refused(sim, host, name):
    if " " in name:
        cid = host.command(f"SD DEL {name}")
        assert host.answer(cid).code == "BAD_ARGS"
        return
    assert host.refused(f"SD PUT {name} 1 00000000").code == "BAD_NAME"
    assert host.refused(f"SD DEL {name}").code == "BAD_NAME"


def test_sd_run_streams_the_file_and_carries_on_without_host(sim, host):
    assert isinstance(put(host, "job.nc", PROGRAM), Ok)
    host.home()
    ok = host.ok("SD RUN job.nc")
    assert ok.info == "RUN job.nc"
    assert host.wait(lambda f: isinstance(f, Status) and f.state == "RUN").has("S")
    host.heartbeat = False
    host.wait(lambda f: isinstance(f, Alarm) and f.code == "HOST_LOST", timeout=5)
    assert sim.run_until(lambda: sim.main.sd_job is None, 60)
    assert [s for s, _ in sim.exec_log] == list(range(len(PROGRAM)))
    assert sim.run_until(lambda: sim.cnc.mc.state == "IDLE", 10)  # after the job: Z lifted
    host.heartbeat = True
    host.command("PING")
    host.wait(lambda f: isinstance(f, Log) and "done" in f.text, start=0)


def test_sd_run_refused_before_homing_and_for_missing_file(sim, host):
    assert host.refused("SD RUN nothing.nc").code == "NO_FILE"
    put(host, "job.nc", PROGRAM)
    assert host.refused("SD RUN job.nc").code == "NOT_HOMED"
    assert sim.main.sd_job is None


def test_bad_host_frame_is_naked_once_per_stretch(sim, host):
    host.home()
    host.ok("JOB 4")
    host.send("D 0 G00 Z5")
    host.port.write(b"D 1 G00 Z6*0000\n")
    host.port.write(b"D 2 G00 Z7*0000\n")
    sim.run_for(0.3)
    assert [n.seq for n in host.of(Nak)] == [1]


def test_cut_uart_holds_a_running_job_on_the_cnc_side(sim, host):
    host.home()
    host.stream(["G01 X60 F300", "G01 X0"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN")
    sim.faults.cut_uart()
    assert sim.run_until(lambda: sim.cnc.uart_lost, 4.0)
    assert sim.run_until(lambda: sim.cnc.mc.state == "HOLD", 0.1)
    host.wait(lambda f: isinstance(f, Alarm) and f.code == "UART_LOST", timeout=1)
    sim.faults.restore_uart()
    assert sim.run_until(lambda: not sim.main.uart_lost and not sim.cnc.uart_lost, 2.0)
    host.ok("RESUME")
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN")


def test_long_move_keeps_the_uart_alive(sim, host):
    host.home()
    host.stream(["G01 X100 F600"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "IDLE" and f.done == 0, timeout=20)
    assert not sim.cnc.uart_lost and not sim.main.uart_lost
    assert [f for f in host.of(Alarm) if f.code == "UART_LOST"] == []


def test_limit_alarm_then_home_recover(sim, host):
    host.home()
    host.stream(["G01 X60 F600"])
    host.wait(lambda f: isinstance(f, Status) and f.state == "RUN")
    sim.faults.trip_limit("X")
    host.wait(lambda f: isinstance(f, Alarm) and f.code == "LIMIT")
    status = host.wait(lambda f: isinstance(f, Status) and f.state == "ALARM")
    assert not status.has("H") and not sim.cnc.job.open
    assert host.refused("JOB 1").code in ("ALARM", "NOT_HOMED")
    host.ok("HOME RECOVER", timeout=120)
    assert sim.cnc.mc.homed


def test_mreset_during_an_upload_leaves_no_file(sim, host, tmp_path):
    host.command(f"SD PUT half.nc 3 {crc32_of_lines(PROGRAM[:3]):08x}")
    host.send(Data(0, PROGRAM[0]).body())
    sim.run_for(0.05)
    sim.panel.reset_main()
    assert list((tmp_path / "sd").iterdir()) == []
    assert sim.main.upload is None
