"""One run of the noisy-link matrix (issue 14 point 2), shared by the test and the bench.

A simulator and a session on the simulated clock; once connected, every byte on all
four wires (USB and UART, down and up) is dropped, corrupted, duplicated or followed
by noise, each with a quarter of ``rate``. The run homes, switches check mode on and
streams ``lines``; it reports whether all of it completed, whether the CNC MCU's
executed log is exactly the program, the job's lines per simulated second, the
resends, and how often the host called the link lost although valid frames came in
within the last ``lost_s`` (a false loss).
"""

from __future__ import annotations

from dataclasses import dataclass

from app.comm.listener import SessionListener, SessionState
from app.comm.session import Session
from backend_sim import Simulator
from tests.comm.simlink import seeded_ids

STEP_S = 0.005


@dataclass
class Outcome:
    completed: bool
    exact: bool
    lines_per_s: float
    resends: int
    false_losses: int
    reason: str = ""


class _Tally(SessionListener):
    def __init__(self) -> None:
        self.jobs, self.results, self.losses, self.progress = [], [], [], None

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_command_done(self, event):
        self.results.append(event)

    def on_progress(self, event):
        self.progress = event

    def on_link_changed(self, event):
        if event.state == "LOST":
            self.losses.append(event)


def noisy_run(lines: list[str], rate: float, seed: int, sd_dir, home: bool = True) -> Outcome:
    """Home, check mode, then the job, all at per-byte fault ``rate`` (see the docstring)."""
    sim = Simulator(sd_dir=sd_dir, seed=seed)
    port = sim.host_port
    port.timeout = 0
    tally = _Tally()
    session = Session(None, tally, clock=lambda: sim.clock.now, ids=seeded_ids(seed))
    session.attach(port.write)

    def step() -> None:
        sim.run_for(STEP_S)
        waiting = port.in_waiting
        if waiting:
            session.feed(port.read(waiting))
        session.tick()

    def run_until(done, timeout: float) -> bool:
        end = sim.clock.now + timeout
        while not done():
            if sim.clock.now >= end:
                return False
            step()
        return True

    def command(verb: str, *args, timeout: float) -> str:
        cid = session.submit(verb, *args)
        answered = lambda: any(r.id == cid for r in tally.results)  # noqa: E731
        if not run_until(answered, timeout):
            return f"{verb}: no answer"
        result = next(r for r in tally.results if r.id == cid)
        return "" if result.ok else f"{verb}: {result.code} {result.info}"

    run_until(lambda: session.state is SessionState.READY, 2.0)
    share = rate / 4
    if rate:
        sim.faults.set_rates(seed=seed, drop=share, corrupt=share, duplicate=share, noise=share)
    problem = (command("HOME", timeout=240.0) if home else "") or command("SET", "CHECK", 1, timeout=30.0)
    if problem:
        return Outcome(False, False, 0.0, 0, len(tally.losses), problem)
    start = sim.clock.now
    if not session.start_job(lines):
        return Outcome(False, False, 0.0, 0, len(tally.losses), "job refused")
    run_until(lambda: bool(tally.jobs), 10.0 + len(lines))
    elapsed = sim.clock.now - start
    job = tally.jobs[-1] if tally.jobs else None
    executed = list(sim.exec_log)
    exact = [s for s, _ in executed] == list(range(len(lines))) and all(
        line == lines[s] for s, line in executed)
    resends = tally.progress.resends if tally.progress else 0
    completed = bool(job and job.completed)
    reason = "" if completed else (job.reason if job else "job never ended")
    rate_out = len(lines) / elapsed if elapsed else 0.0
    return Outcome(completed, exact, rate_out, resends, len(tally.losses), reason)
