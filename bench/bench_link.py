"""Link benchmark: streaming throughput and heartbeat figures, on the simulator's clock.

Prints (never pass/fail on time):

1. Throughput in check mode through both hops (USB and the 115200 8N1 UART, whose
   byte time the simulator models), in lines per simulated second, for the credit
   window of 8 and for a window of 1 (stop-and-wait), against the ceiling
   ``11520 bytes/s / mean D frame length``. Target: >= 90 % of the ceiling.
2. Heartbeat: simulated time from cutting the USB cable to ``LOST`` on the host and to
   ``HOST_LOST`` on the machine (target <= 3 s each), idle and mid-job.
3. False losses in a 10-minute simulated soak (jobs and idle spells, no faults).
4. A long seeded soak (``BENCH_LINK_SOAK`` lines, default 1,000,000, at 1e-5 per
   byte on both hops; ``0`` skips it): the oracle holds, resend rate, wall time.

Run: ``python -m bench bench_link`` (or ``make bench``).
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time

from app.comm import frame as fr
from app.comm.listener import SessionListener, SessionState
from app.comm.session import Session
from app.gcode import load
from backend_sim import Simulator

SAMPLE = "resources/samples/arcs_circles.ngc"
UART_BYTES_S = 115200 / 10
STEP_S = 0.002


class Tally(SessionListener):
    """Counts what the figures need."""

    def __init__(self) -> None:
        self.jobs, self.links, self.alarms = [], [], []
        self.progress = None

    def on_progress(self, event):
        self.progress = event

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_link_changed(self, event):
        self.links.append(event)

    def on_alarm(self, event):
        self.alarms.append(event)


class Rig:
    """A simulator and a session on the simulator's clock, stepped every ``STEP_S``."""

    def __init__(self, sd: str, seed: int = 1, window: int = 8, check: bool = True) -> None:
        self.sim = Simulator(sd_dir=sd, seed=seed)
        self.port = self.sim.host_port
        self.port.timeout = 0
        self.tally = Tally()
        self.session = Session(None, self.tally, clock=lambda: self.sim.clock.now)
        self.session.max_window = window
        self.session.attach(self.port.write)
        self.run_until(lambda: self.session.state is SessionState.READY, 2.0)
        if check:
            self.session.submit("SET", "CHECK", 1)
            self.run_for(0.2)

    @property
    def now(self) -> float:
        return self.sim.clock.now

    def step(self) -> None:
        self.sim.run_for(STEP_S)
        waiting = self.port.in_waiting
        if waiting:
            self.session.feed(self.port.read(waiting))
        self.session.tick()

    def run_until(self, predicate, timeout: float) -> bool:
        end = self.now + timeout
        while not predicate():
            if self.now >= end:
                return False
            self.step()
        return True

    def run_for(self, seconds: float) -> None:
        self.run_until(lambda: False, seconds)

    def job(self, lines: list[str], timeout: float = 3600.0):
        before = len(self.tally.jobs)
        self.session.start_job(lines)
        self.run_until(lambda: len(self.tally.jobs) > before, timeout)
        return self.tally.jobs[-1] if len(self.tally.jobs) > before else None


def program(repeat: int) -> list[str]:
    return load(SAMPLE).device_lines * repeat


def mean_frame(lines: list[str]) -> float:
    return statistics.fmean(len(fr.Data(i, line).encode()) for i, line in enumerate(lines))


def throughput(sd: str) -> None:
    lines = program(20)
    ceiling = UART_BYTES_S / mean_frame(lines)
    print(f"throughput, check mode, both hops, {len(lines)} lines of {SAMPLE}, host stepped every "
          f"{STEP_S * 1000:g} ms; mean D frame {mean_frame(lines):.1f} bytes, "
          f"ceiling {ceiling:.0f} lines/s")
    for window in (8, 1):
        rig = Rig(sd, window=window)
        start, wall = rig.now, time.perf_counter()
        job = rig.job(lines)
        rate = len(lines) / (rig.now - start)
        print(f"  window {window}: {rate:7.1f} lines/s = {rate / ceiling:5.1%} of the ceiling "
              f"({'completed' if job and job.completed else job}, {time.perf_counter() - wall:.1f} s wall)")


def cut_to_loss(sd: str, mid_job: bool) -> tuple[float, float]:
    rig = Rig(sd, check=not mid_job)
    if mid_job:
        rig.session.submit("HOME")
        rig.run_until(lambda: rig.session.status and rig.session.status.homed, 120.0)
        rig.session.start_job(["G01 X100 F200"])
        rig.run_for(3.0)
    else:
        rig.run_for(1.3)
    for wire in ("usb_down", "usb_up"):
        rig.sim.wires[wire].set_cut(True)
    cut, seen = rig.now, {}

    def both() -> bool:
        if "host" not in seen and rig.tally.links[-1].state == "LOST":
            seen["host"] = rig.now - cut
        if "machine" not in seen and rig.sim.main.host_lost:
            seen["machine"] = rig.now - cut
        return len(seen) == 2

    rig.run_until(both, 10.0)
    return seen.get("host", float("nan")), seen.get("machine", float("nan"))


def heartbeat(sd: str) -> None:
    for mid_job in (False, True):
        host, machine = cut_to_loss(sd, mid_job)
        print(f"heartbeat ({'mid-job' if mid_job else 'idle'}): cable cut -> host LOST {host:.3f} s, "
              f"machine HOST_LOST {machine:.3f} s (target <= 3 s each)")


def false_losses(sd: str, minutes: float = 10.0) -> None:
    rig = Rig(sd)
    lines, wall, jobs = program(2), time.perf_counter(), 0
    end = rig.now + minutes * 60
    while rig.now < end:
        rig.job(lines)
        jobs += 1
        rig.run_for(min(20.0, max(0.0, end - rig.now)))
    lost = [e for e in rig.tally.links if e.state in ("DEGRADED", "LOST")]
    host_lost = [a for a in rig.tally.alarms if a.code == "HOST_LOST"]
    print(f"false losses in a {minutes:g}-minute simulated soak ({jobs} jobs and idle spells): "
          f"{len(lost)} degraded/lost on the host, {len(host_lost)} HOST_LOST on the machine "
          f"({time.perf_counter() - wall:.1f} s wall)")


def long_soak(sd: str, count: int, rate: float = 1e-5, seed: int = 7) -> None:
    rig = Rig(sd, seed=seed)
    share = rate / 4
    rig.sim.faults.set_rates(seed=seed, drop=share, corrupt=share, duplicate=share, noise=share)
    log: list[tuple[int, str]] = []
    queue_line = rig.sim.cnc._queue_line

    def recording(seq: int, line: str):
        before = rig.sim.cnc.job.acc
        queue_line(seq, line)
        if rig.sim.cnc.job.acc == seq != before:
            log.append((seq, line))

    rig.sim.cnc._queue_line = recording
    base = program(1)
    lines = [base[i % len(base)] for i in range(count)]
    start, wall, cpu = rig.now, time.perf_counter(), time.process_time()
    job = rig.job(lines, timeout=count)
    ok = job is not None and job.completed and [s for s, _ in log] == list(range(count)) and all(
        line == lines[s] for s, line in log)
    progress = rig.tally.progress
    ended = f"{job.done + 1} lines done" if job else "no end"
    resends = f"{progress.resends} resends ({progress.resend_rate:.2%})" if progress else ""
    print(f"long soak: {count} lines at {rate:g}/byte on both hops, seed {seed}: "
          f"oracle {'holds' if ok else 'FAILS'} ({ended}, {resends}) in {rig.now - start:.0f} "
          f"simulated s, {time.perf_counter() - wall:.0f} s wall, {time.process_time() - cpu:.0f} s CPU")


def main() -> None:
    with tempfile.TemporaryDirectory() as sd:
        throughput(sd)
        heartbeat(sd)
        false_losses(sd)
        count = int(os.environ.get("BENCH_LINK_SOAK", "1000000"))
        if count > 0:
            long_soak(sd, count)


if __name__ == "__main__":
    main()
