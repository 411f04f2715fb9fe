"""The speed factor leaves the link's timing alone (issue 11).

``cnc-sim --pty --speed 50`` runs the machine 50 times faster; its link timers stay in
wall-clock time, so a client that knows nothing of the factor keeps the link alive.
Two clients prove it: an independent raw client written from docs/protocol.md alone
(pyserial, ``binascii.crc_hqx``, its own parsing: nothing of ``app.comm``), pinging
once a second, and the project's console with no time option. Both run a job that
lasts longer than the 3 s host-lost timeout in wall-clock time to its end.
"""

from __future__ import annotations

import binascii
import time

import serial

from app.comm.console import main as console_main
from tests.backend_sim.serial_host import start_sim, stop_sim

SPEED = "50"
SQUARE = ["G01 X110 Y10", "G01 X110 Y110", "G01 X10 Y110", "G01 X10 Y10"]
JOB = ["G00 Z5", "G00 X10 Y10", "G01 Z-0.5 F900", *SQUARE * 4, "G00 Z5"]


def frame(body: str) -> bytes:
    """``BODY*CCCC\\n`` with CRC-16/CCITT-FALSE (docs/protocol.md, Frames)."""
    return f"{body}*{binascii.crc_hqx(body.encode(), 0xFFFF):04X}\n".encode()


class RawClient:
    """Frames out, checked frames in; a PING every wall second; nothing more."""

    def __init__(self, port: serial.Serial) -> None:
        self.port, self.buffer, self.bodies = port, b"", []
        self.next_id, self.last_ping = 1, 0.0

    def command(self, text: str) -> int:
        cid, self.next_id = self.next_id, self.next_id + 1
        self.port.write(frame(f"C {cid} {text}"))
        return cid

    def pump(self) -> None:
        if time.monotonic() - self.last_ping >= 1.0:
            self.last_ping = time.monotonic()
            self.command("PING")
        self.buffer += self.port.read(max(1, self.port.in_waiting))
        *lines, self.buffer = self.buffer.split(b"\n")
        for line in lines:
            body, _, crc = line.rstrip(b"\r").rpartition(b"*")
            assert f"{binascii.crc_hqx(body, 0xFFFF):04X}".encode() == crc, line
            self.bodies.append(body.decode())

    def wait(self, prefix: str, timeout: float = 60.0) -> str:
        start, deadline = len(self.bodies), time.monotonic() + timeout
        while time.monotonic() < deadline:
            self.pump()
            for body in self.bodies[start:]:
                if body.startswith(prefix):
                    return body
            start = len(self.bodies)
        raise AssertionError(f"no {prefix!r} within {timeout} s: {self.bodies[-5:]}")

    def stream(self, lines: list[str], timeout: float = 120.0) -> float:
        """``JOB`` then every line within the credit window; returns the wall seconds to
        the last ``F``."""
        started = time.monotonic()
        cid = self.command(f"JOB {len(lines)}")
        self.wait(f"O {cid} JOB")
        sent, acked, free = 0, -1, 8
        deadline = started + timeout
        while time.monotonic() < deadline:
            while sent < len(lines) and sent - acked - 1 < min(free, 8):
                self.port.write(frame(f"D {sent} {lines[sent]}"))
                sent += 1
            start = len(self.bodies)
            self.pump()
            for body in self.bodies[start:]:
                kind, *fields = body.split()
                if kind == "A":
                    acked, free = max(acked, int(fields[0])), int(fields[1])
                elif kind == "S":
                    free = int(fields[7])
                elif kind == "F" and int(fields[0]) == len(lines) - 1:
                    return time.monotonic() - started
                elif kind in ("E", "N") or body.startswith("X HOST_LOST"):
                    raise AssertionError(f"job broken off: {body}")
        raise AssertionError(f"job not finished within {timeout} s: {self.bodies[-5:]}")


def test_raw_client_runs_a_job_at_speed_50_with_no_host_lost(tmp_path):
    proc, first = start_sim(tmp_path, "--speed", SPEED)
    try:
        port = serial.Serial(first.split()[1], baudrate=115200, timeout=0.01)
        client = RawClient(port)
        client.wait("S ")
        home = client.command("HOME")
        client.wait(f"O {home} HOME")
        wall = client.stream(JOB)
        port.close()
    finally:
        code, rest = stop_sim(proc)
    assert wall > 3.0, f"the job took {wall:.1f} s: too short to prove the timers"
    lost = [b for b in client.bodies if b.startswith("X HOST_LOST") or (b[0] == "S" and "L" in b.split()[-1])]
    assert lost == []
    assert code == 0 and rest == ""


def test_console_runs_a_job_at_speed_50_without_a_time_option(tmp_path, capsys):
    job = tmp_path / "square.ngc"
    job.write_text("G21 G90\n" + "\n".join(JOB) + "\nM02\n")
    proc, first = start_sim(tmp_path, "--speed", SPEED)
    try:
        rc = console_main([first.split()[1], "run", str(job)])
    finally:
        stop_sim(proc)
    out = capsys.readouterr().out
    assert rc == 0, out
    assert f"job completed: {len(JOB) + 1} lines" in out
    assert "HOST_LOST" not in out
