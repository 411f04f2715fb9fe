"""Protocol conformance (docs/protocol.md) through real pyserial on ``cnc-sim --pty``."""

from __future__ import annotations

import re

import pytest
import serial

from app.comm.frame import Ack, Alarm, Error, Finished, Info, Nak, Ok, Status, seal
from backend_sim.sd_card import crc32_of_lines
from tests.backend_sim.serial_host import SerialHost, start_sim, stop_sim

SPEED = 20.0
PROGRAM = ["G00 Z5", "G00 X5 Y5", "G01 Z4 F600", "G01 X8", "G00 Z5"]


@pytest.fixture(scope="module")
def machine(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("pty")
    proc, first = start_sim(tmp, "--speed", str(SPEED))
    match = re.fullmatch(r"PTY (/dev/pts/\d+)\n", first)
    assert match, first
    port = serial.Serial(match.group(1), baudrate=115200, timeout=0.01)
    host = SerialHost(port, SPEED)
    host.ok("HOME", timeout=60)
    host.ok("SET AFTERJOB 0")  # jobs back to back: no Z lift between them
    yield host, tmp / "sd"
    port.close()
    code, rest = stop_sim(proc)
    assert code == 0 and rest == ""


def test_every_frame_checks_and_status_fields(machine):
    host, _ = machine
    host.command("STATUS")
    status = host.wait(lambda f: isinstance(f, Status))
    assert status.state == "IDLE" and status.has("H") and re.fullmatch(r"[0-9A-F]{8}", status.boot)
    assert host.dropped == []
    assert all(re.fullmatch(rb"[A-Z] .*\*[0-9A-F]{4}", line) for line in bytes(host.raw).split(b"\n")[:-1])


def test_job_acks_and_finishes_cumulatively(machine):
    host, _ = machine
    start = len(host.frames)
    host.ok(f"JOB {len(PROGRAM)}")
    for seq, line in enumerate(PROGRAM):
        host.data(seq, line)
    host.wait(lambda f: isinstance(f, Finished) and f.seq == len(PROGRAM) - 1, 60)
    acks = [f.seq for f in host.frames[start:] if isinstance(f, Ack)]
    fins = [f.seq for f in host.frames[start:] if isinstance(f, Finished)]
    assert acks == sorted(acks) and acks[-1] == len(PROGRAM) - 1
    assert fins == sorted(fins) and fins[-1] == len(PROGRAM) - 1
    assert host.dropped == []


def test_duplicate_reacked_gap_and_bad_crc_naked(machine):
    host, _ = machine
    start = len(host.frames)
    host.ok("JOB 3")
    host.data(0, "G00 Z6")
    host.data(0, "G00 Z6")
    acks = lambda: [a for a in host.frames[start:] if isinstance(a, Ack)]  # noqa: E731
    host.wait(lambda f: isinstance(f, Ack) and len(acks()) == 2)
    bad = bytearray(seal("D 1 G00 Z7"))
    bad[6] ^= 0x04
    host.port.write(bytes(bad))
    assert host.wait(lambda f: isinstance(f, Nak)).seq == 1
    host.data(1, "G00 Z7")
    host.data(2, "G00 Z5")
    host.wait(lambda f: isinstance(f, Finished) and f.seq == 2, 30)
    assert [a.seq for a in acks()] == [0, 0, 1, 2]


def test_error_codes(machine):
    host, _ = machine
    assert host.refused("WIBBLE").code == "UNKNOWN_VERB"
    assert host.refused("SET NOPE 1").code == "BAD_PARAM"
    host.ok("JOB 1")
    host.data(0, "G00 Y-5")
    err = host.wait(lambda f: isinstance(f, Error) and f.id is None)
    assert err.code == "SOFT_LIMIT" and err.text.startswith("0 Y- -5.000 < 0")
    host.ok("JOB 1")
    host.data(0, "G05 X1")
    assert host.wait(lambda f: isinstance(f, Error) and f.id is None).code == "BAD_LINE"


def test_sd_round_trip_with_crc(machine):
    host, sd = machine
    cid = host.command(f"SD PUT part.nc {len(PROGRAM)} {crc32_of_lines(PROGRAM):08x}")
    for seq, line in enumerate(PROGRAM):
        host.data(seq, line)
    assert isinstance(host.answer(cid), Ok)
    assert (sd / "part.nc").read_text() == "\n".join(PROGRAM) + "\n"
    cid = host.command("SD LIST")
    host.answer(cid)
    rows = [f.text for f in host.of(Info) if f.id == cid]
    assert f"part.nc {(sd / 'part.nc').stat().st_size} {len(PROGRAM)}" in rows
    cid = host.command(f"SD PUT bad.nc {len(PROGRAM)} {crc32_of_lines(PROGRAM) ^ 0xFF:08x}")
    for seq, line in enumerate(PROGRAM):
        host.data(seq, line)
    assert host.answer(cid).code == "CRC_MISMATCH"
    assert not (sd / "bad.nc").exists() and not list(sd.glob(".*"))
    for name in ("../evil.nc", "a/b", "..", "x" * 40):
        assert host.refused(f"SD PUT {name} 1 0").code == "BAD_NAME"
    host.ok("SD DEL part.nc")
    assert not (sd / "part.nc").exists()


def test_repeated_id_gets_the_first_answer(machine):
    host, _ = machine
    host.send("C 9000 GET KP_X")
    first = host.answer(9000)
    host.send("C 9000 SET KP_X 3")
    answers = lambda: [o for o in host.of(Ok) if o.id == 9000]  # noqa: E731
    host.wait(lambda f: isinstance(f, Ok) and len(answers()) == 2)
    assert answers() == [first, first]


def test_heartbeat_loss_after_3_s(tmp_path):
    proc, first = start_sim(tmp_path, "--speed", "20")
    try:
        port = serial.Serial(first.split()[1], timeout=0.01)
        host = SerialHost(port, 20.0)
        host.command("PING")
        host.wait(lambda f: isinstance(f, Status))
        host.heartbeat = False
        alarm = host.wait(lambda f: isinstance(f, Alarm), timeout=10)
        assert alarm.code == "HOST_LOST"
        after = host.frames.index(alarm)
        assert host.wait(lambda f: isinstance(f, Status), start=after).has("L")
        host.heartbeat = True
        host.command("PING")
        host.wait(lambda f: isinstance(f, Status) and not f.has("L"))
        port.close()
    finally:
        code, rest = stop_sim(proc)
    assert code == 0 and rest == ""


def test_tcp_serves_the_same(tmp_path):
    import subprocess
    import sys

    proc = subprocess.Popen([sys.executable, "-m", "backend_sim", "--tcp", "0", "--sd", str(tmp_path)],
                            stdout=subprocess.PIPE, text=True)
    try:
        first = proc.stdout.readline()
        assert re.fullmatch(r"TCP 127\.0\.0\.1:\d+\n", first), first
        port = serial.serial_for_url(f"socket://{first.split()[1]}", timeout=0.01)
        host = SerialHost(port, 1.0)
        host.command("PING")
        status = host.wait(lambda f: isinstance(f, Status) and f.boot != "0", timeout=10)
        assert status.state == "IDLE"
        port.close()
    finally:
        code, _ = stop_sim(proc)
    assert code == 0
