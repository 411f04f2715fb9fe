"""Runs through an honest noisy link (issue 18), shared by the tests and ``bench_noisy``.

A simulator and a session on the simulated clock (``NoisyRig``); every byte on all four
wires (USB and UART, down and up) may be flipped (any bit: a newline, ``!``, 0x18 ...),
dropped or duplicated, each with probability ``rate`` (``backend_sim/faults.py``).

- ``noisy_run``: home, check mode, a job: completed?, executed log exactly the
  program?, lines per simulated second, resends, false link losses (the host calling
  the link lost although nothing was cut), phantoms (a hold, stop or reset the CNC MCU
  carried out, or a HOLD status, that nobody asked for) and the legacy bytes the
  machines ignored (what the old protocol would have obeyed).
- ``hold_latency``: a motion job through the noise; the operator clicks Hold; seconds
  until the CNC MCU holds.
- ``fuzz_run``: bursts of 1-200 random bytes (all 256 values) thrown onto both
  downward wires, at an idle machine or under a running motion job: did anything move
  that should not, did the job leave its path, does a PING get answered afterwards.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field

from app.comm.listener import SessionListener, SessionState
from app.comm.session import Session
from backend_sim import Simulator
from tests.comm.simlink import FAST_HOMING, seeded_ids

STEP_S = 0.005
KINDS = ("drop", "corrupt", "duplicate")
PHANTOM_VERBS = ("PAUSE", "STOP", "RESET", "R HOLD", "R STOP", "R RESET", "R RESUME")
MOTION_VERBS = ("HOME", "JOB", "JOG", "SPINDLE", "RESUME", "R RESUME")
BURST_MAX = 200
BURST_EVERY_S = 0.02


def zigzag(n: int, feed: int = 900) -> list[str]:
    """A motion job of ``n`` lines: 20 mm zig-zags near the middle of the table."""
    lines = ["G00 Z5", "G00 X40 Y40"]
    lines += [f"G01 X{40 + 20 * (i % 2)} Y{40 + i * 0.25:g} F{feed}" for i in range(max(0, n - 2))]
    return lines[:n]


@dataclass
class Outcome:
    completed: bool
    exact: bool
    lines_per_s: float
    resends: int
    false_losses: int
    phantoms: int = 0
    legacy: int = 0
    reason: str = ""


@dataclass
class FuzzOutcome:
    thrown: int
    moved: bool
    left_job: bool
    exact: bool
    pinged: bool
    phantoms: int
    legacy: int
    reason: str = ""


@dataclass
class _Tally(SessionListener):
    jobs: list = field(default_factory=list)
    results: list = field(default_factory=list)
    losses: list = field(default_factory=list)
    holds: list = field(default_factory=list)
    progress: object = None

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_command_done(self, event):
        self.results.append(event)

    def on_progress(self, event):
        self.progress = event

    def on_link_changed(self, event):
        if event.state == "LOST":
            self.losses.append(event)

    def on_status(self, event):
        if event.state == "HOLD" and event.boot != "0":
            self.holds.append(event)


class NoisyRig:
    """One simulator and one session on the simulated clock (no threads, no sleeps)."""

    def __init__(self, seed: int, sd_dir, profile=None) -> None:
        self.seed = seed
        self.sim = Simulator(profile=profile, sd_dir=sd_dir, seed=seed)
        self.port = self.sim.host_port
        self.port.timeout = 0
        self.tally = _Tally()
        self.session = Session(None, self.tally, clock=lambda: self.sim.clock.now, ids=seeded_ids(seed))
        self.session.attach(self.port.write)
        self.run_until(lambda: self.session.state is SessionState.READY, 2.0)

    @property
    def now(self) -> float:
        return self.sim.clock.now

    def step(self, dt: float = STEP_S) -> None:
        self.sim.run_for(dt)
        waiting = self.port.in_waiting
        if waiting:
            self.session.feed(self.port.read(waiting))
        self.session.tick()

    def run_until(self, done, timeout: float, dt: float = STEP_S, every=None) -> bool:
        end = self.now + timeout
        while not done():
            if self.now >= end:
                return False
            self.step(dt)
            if every is not None:
                every()
        return True

    def command(self, verb: str, *args, timeout: float) -> str:
        """Send a command and wait for its answer: "" if done, else what went wrong."""
        cid = self.session.submit(verb, *args)
        answered = lambda: any(r.id == cid for r in self.tally.results)  # noqa: E731
        if not self.run_until(answered, timeout):
            return f"{verb}: no answer"
        result = next(r for r in self.tally.results if r.id == cid)
        return "" if result.ok else f"{verb}: {result.code} {result.info}"

    def noise(self, rate: float) -> None:
        """Flip, drop and duplicate each at ``rate`` per byte on all four wires."""
        if rate:
            self.sim.faults.set_rates(seed=self.seed, **{kind: rate for kind in KINDS})
        else:
            self.sim.faults.clear()

    def phantoms(self) -> int:
        """Holds, stops and resets the CNC MCU carried out, plus HOLD statuses: the runs
        send none of these, so each one is noise taken for a command."""
        return sum(self.sim.cnc.taken[v] for v in PHANTOM_VERBS) + len(self.tally.holds)

    def legacy(self) -> int:
        return self.sim.main.legacy.total + self.sim.cnc.legacy.total

    def exact(self, lines: list[str]) -> bool:
        executed = list(self.sim.exec_log)
        return [s for s, _ in executed] == list(range(len(lines))) and all(
            line == lines[s] for s, line in executed)


def noisy_run(lines: list[str], rate: float, seed: int, sd_dir, home: bool = True) -> Outcome:
    """Home, check mode, then the job, all at per-byte fault ``rate`` (see the docstring)."""
    rig = NoisyRig(seed, sd_dir)
    rig.noise(rate)
    tally = rig.tally
    problem = rig.command("HOME", timeout=240.0) if home else ""
    problem = problem or rig.command("SET", "CHECK", 1, timeout=30.0)
    if problem:
        return Outcome(False, False, 0.0, 0, len(tally.losses), rig.phantoms(), rig.legacy(), problem)
    start = rig.now
    if not rig.session.start_job(lines):
        return Outcome(False, False, 0.0, 0, len(tally.losses), rig.phantoms(), rig.legacy(), "job refused")
    rig.run_until(lambda: bool(tally.jobs), 10.0 + len(lines))
    elapsed = rig.now - start
    job = tally.jobs[-1] if tally.jobs else None
    resends = tally.progress.resends if tally.progress else 0
    completed = bool(job and job.completed)
    reason = "" if completed else (job.reason if job else "job never ended")
    return Outcome(completed, rig.exact(lines), len(lines) / elapsed if elapsed else 0.0, resends,
                   len(tally.losses), rig.phantoms(), rig.legacy(), reason)


def hold_latency(seed: int, rate: float, sd_dir) -> float | None:
    """Seconds from the operator's Hold to the CNC MCU holding, in a motion job through
    ``rate`` noise (None: it never held within a second)."""
    rig = NoisyRig(seed, sd_dir, FAST_HOMING)
    if rig.command("HOME", timeout=120.0):
        return None
    lines = zigzag(60)
    rig.session.start_job(lines)
    rig.noise(rate)
    mc = rig.sim.cnc.mc
    if not rig.run_until(lambda: mc.state == "RUN" and len(rig.sim.exec_log) > 3, 30.0):
        return None
    rig.run_until(lambda: False, random.Random(seed).uniform(0.0, 1.0))
    if mc.state != "RUN":
        return None
    clicked = rig.now
    rig.session.pause()
    if not rig.run_until(lambda: mc.state == "HOLD", 1.0, dt=0.001):
        return None
    return rig.now - clicked


def fuzz_job_lines(total: int) -> int:
    """Lines of a ``zigzag`` job that runs (about 1.4 s a line) while ``total`` bytes come."""
    return int(total / (BURST_MAX / 2) * BURST_EVERY_S / 1.2) + 20


def fuzz_run(total: int, seed: int, sd_dir, job_lines: int = 0) -> FuzzOutcome:
    """Throw ``total`` random bytes in bursts of 1-``BURST_MAX`` onto both downward wires,
    every ``BURST_EVERY_S``, at an idle homed machine (``job_lines`` 0) or while a
    motion job of ``job_lines`` lines runs (see the module docstring)."""
    rig = NoisyRig(seed, sd_dir, FAST_HOMING)
    if rig.command("HOME", timeout=120.0):
        return FuzzOutcome(0, False, False, False, False, 0, 0, "HOME failed")
    lines = zigzag(job_lines) if job_lines else []
    taken = dict(rig.sim.cnc.taken)  # what was carried out before the bytes came
    if lines and not rig.session.start_job(lines):
        return FuzzOutcome(0, False, False, False, False, 0, 0, "job refused")
    rng = random.Random(f"fuzz:{seed}")
    wires = (rig.sim.wires["usb_down"], rig.sim.wires["uart_down"])
    state = {"thrown": 0, "next": rig.now}
    rest = tuple(rig.sim.cnc.mc.measured_mm)

    def throw() -> None:
        while state["thrown"] < total and rig.now >= state["next"]:
            burst = rng.randbytes(min(rng.randint(1, BURST_MAX), total - state["thrown"]))
            rng.choice(wires).write(burst, rig.now)
            state["thrown"] += len(burst)
            state["next"] += BURST_EVERY_S

    thrown_all = lambda: state["thrown"] >= total  # noqa: E731
    job_over = lambda: bool(rig.tally.jobs) or not lines  # noqa: E731
    budget = total / 100 * BURST_EVERY_S * 2 + 5.0 * len(lines) + 60.0
    rig.run_until(lambda: thrown_all() and job_over(), budget, every=throw)
    rig.run_until(lambda: False, 1.0)
    pinged = rig.command("PING", timeout=5.0) == ""
    job = rig.tally.jobs[-1] if rig.tally.jobs else None
    started = any(rig.sim.cnc.taken[v] > taken.get(v, 0) for v in MOTION_VERBS if not (lines and v == "JOB"))
    drift = max(abs(a - b) for a, b in zip(rig.sim.cnc.mc.measured_mm, rest, strict=True))
    moved = started or not lines and (bool(rig.sim.exec_log) or drift > 0.01)
    left = bool(lines) and not (job and job.completed)
    reason = job.reason if job and not job.completed else ""
    return FuzzOutcome(state["thrown"], bool(moved), left, rig.exact(lines), pinged, rig.phantoms(),
                       rig.legacy(), reason)
