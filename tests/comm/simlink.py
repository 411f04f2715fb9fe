"""A Session wired to an in-process Simulator on the simulator's own clock (no threads, no sleeps).

``SimLink.step()`` advances the simulated clock by ``dt``, hands the session what
arrived and lets it tick, as the worker's timer does in real time. The oracle helpers
compare the CNC MCU's executed log with the program.
"""

from __future__ import annotations

import itertools
import random

import serial

from app.comm.commands import ID_START_MAX
from app.comm.listener import SessionState
from app.comm.session import Session
from app.profile import MachineProfile, with_overrides
from backend_sim import Simulator
from tests.comm.scripted import Recorder

STEP_S = 0.002
FAST_HOMING = with_overrides(MachineProfile(), {"motion": {"homing_mm_min": 900}})


def dialect_program(n: int, seed: int = 0) -> list[str]:
    """``n`` short dialect lines inside the travel (work coordinates)."""
    lines = ["G00 Z5", "G00 X10 Y10", "G01 Z-0.5 F200"]
    for i in range(max(0, n - 3)):
        x = 10 + (i * 7 + seed) % 120 + (i % 10) / 8
        y = 10 + (i * 13 + seed) % 120 + (i % 7) / 4
        lines.append(f"G01 X{x:g} Y{y:g}" + (" F300" if i % 50 == 0 else ""))
    return lines[:n]


def seeded_ids(seed: int):
    """Command ids as a host makes them (a random start below ``ID_START_MAX``), repeatable:
    the start comes from ``seed``, so the bytes on a noisy link are the same each run."""
    return itertools.count(random.Random(f"ids:{seed}").randrange(1, ID_START_MAX)).__next__


class SimLink:
    """One simulator and one session on the simulated clock."""

    def __init__(self, seed: int = 1, sd_dir=None, check: bool = True, mode: str = "planner",
                 profile=None) -> None:
        self.sim = Simulator(profile=profile, sd_dir=sd_dir, seed=seed, mode=mode)
        self.port = self.sim.host_port
        self.port.timeout = 0
        self.rec = Recorder()
        self.session = Session(None, self.rec, clock=lambda: self.sim.clock.now, ids=seeded_ids(seed))
        self.attach()
        assert self.run_until(lambda: self.session.state is SessionState.READY, 2.0), "no status"
        if check:
            self.command_ok("SET", "CHECK", 1)

    @property
    def now(self) -> float:
        return self.sim.clock.now

    def attach(self) -> None:
        self.session.attach(self.port.write)

    def step(self, dt: float = STEP_S) -> None:
        self.sim.run_for(dt)
        if self.session.attached:
            try:
                waiting = self.port.in_waiting
                if waiting:
                    self.session.feed(self.port.read(waiting))
            except serial.SerialException as exc:
                self.session.detach(f"read failed: {exc}")
        self.session.tick()

    def run_until(self, predicate, timeout: float, dt: float = STEP_S) -> bool:
        end = self.now + timeout
        while not predicate():
            if self.now >= end:
                return False
            self.step(dt)
        return True

    def run_for(self, seconds: float, dt: float = STEP_S) -> None:
        self.run_until(lambda: False, seconds, dt)

    def command(self, verb: str, *args, timeout: float = 10.0):
        cid = self.session.submit(verb, *args)
        found = lambda: [r for r in self.rec.of("on_command_done") if r.id == cid]  # noqa: E731
        assert self.run_until(lambda: bool(found()), timeout), f"{verb} {args} never answered"
        return found()[0]

    def command_ok(self, verb: str, *args, timeout: float = 10.0):
        result = self.command(verb, *args, timeout=timeout)
        assert result.ok, result
        return result

    def home(self) -> None:
        self.command_ok("HOME", timeout=120.0)

    def run_job(self, lines: list[str], timeout: float = 600.0) -> object:
        """Start ``lines`` and run until the job ends; the JobEvent."""
        before = len(self.rec.of("on_job_finished"))
        assert self.session.start_job(lines), self.rec.last("on_error")
        ended = lambda: len(self.rec.of("on_job_finished")) > before  # noqa: E731
        assert self.run_until(ended, timeout), "job never ended"
        return self.rec.last("on_job_finished")

    def executed(self) -> list[tuple[int, str]]:
        """The CNC MCU's executed log (in check mode: every line validated and finished)."""
        return list(self.sim.exec_log)


def assert_oracle(executed: list[tuple[int, str]], lines: list[str]) -> None:
    """Every line 0..N-1 executed exactly once, in order, byte-identical."""
    seqs = [seq for seq, _ in executed]
    assert seqs == list(range(len(lines))), _first_difference(seqs, len(lines))
    for seq, line in executed:
        assert line == lines[seq], f"line {seq}: executed {line!r}, program {lines[seq]!r}"


def _first_difference(seqs: list[int], n: int) -> str:
    for i, seq in enumerate(seqs):
        if seq != i:
            return f"executed log goes wrong at entry {i}: seq {seq} (of {len(seqs)} entries, {n} lines)"
    return f"executed {len(seqs)} of {n} lines"
