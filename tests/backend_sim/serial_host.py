"""A host on real pyserial for the ``cnc-sim --pty`` tests: frames, heartbeat, waiting."""

from __future__ import annotations

import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import serial

from app.comm.deframer import Deframer, Dropped
from app.comm.frame import Data, Error, Frame, Ok, seal

FAST_PROFILE = "[motion]\nhoming_mm_min = 900\n"


def start_sim(tmp: Path, *args: str) -> tuple[subprocess.Popen, str]:
    """Start ``python -m backend_sim --pty`` and return it with the first stdout line."""
    profile = tmp / "fast.toml"
    profile.write_text(FAST_PROFILE)
    cmd = [sys.executable, "-m", "backend_sim", "--pty", "--sd", str(tmp / "sd"),
           "--profile", str(profile), "--seed", "1", *args]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True)
    return proc, proc.stdout.readline()


def stop_sim(proc: subprocess.Popen) -> tuple[int, str]:
    proc.terminate()
    rest, _ = proc.communicate(timeout=10)
    return proc.returncode, rest


class SerialHost:
    """Sends frames, collects and checks every frame that comes back (CRC included)."""

    def __init__(self, port: serial.Serial, speed: float) -> None:
        self.port = port
        self.speed = speed
        self.deframer = Deframer()
        self.frames: list[Frame] = []
        self.dropped: list[Dropped] = []
        self.raw = bytearray()
        self.next_id = 1
        self.heartbeat = True
        self.last_sent = time.monotonic()

    def send(self, body: str) -> None:
        self.port.write(seal(body))
        self.last_sent = time.monotonic()

    def command(self, text: str) -> int:
        cid = self.next_id
        self.next_id += 1
        self.send(f"C {cid} {text}")
        return cid

    def pump(self) -> None:
        if self.heartbeat and time.monotonic() - self.last_sent > 0.5 / self.speed:
            self.command("PING")
        data = self.port.read(max(1, self.port.in_waiting))
        self.raw += data
        for item in self.deframer.feed(data, time.monotonic()):
            (self.dropped if isinstance(item, Dropped) else self.frames).append(item)

    def wait(self, match: Callable[[Frame], bool], timeout: float = 20.0, start: int | None = None) -> Frame:
        """The first matching frame among those not yet read when called (or from ``start``)."""
        start = len(self.frames) if start is None else start
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            self.pump()
            for frame in self.frames[start:]:
                if match(frame):
                    return frame
        raise AssertionError(f"no matching frame within {timeout} s: {self.frames[-6:]}")

    def answer(self, cid: int, timeout: float = 20.0) -> Frame:
        return self.wait(lambda f: isinstance(f, Ok | Error) and f.id == cid, timeout)

    def ok(self, text: str, timeout: float = 20.0) -> Ok:
        frame = self.answer(self.command(text), timeout)
        assert isinstance(frame, Ok), frame
        return frame

    def refused(self, text: str) -> Error:
        frame = self.answer(self.command(text))
        assert isinstance(frame, Error), frame
        return frame

    def data(self, seq: int, line: str) -> None:
        self.send(Data(seq, line).body())

    def of(self, kind: type) -> list:
        return [f for f in self.frames if isinstance(f, kind)]
