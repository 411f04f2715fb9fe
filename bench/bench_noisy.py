"""Noisy-link figures of issue 18: an honest wire (a flip makes whatever byte it makes).

1. For each per-byte rate (flip, drop and duplicate each at that rate, on all four
   wires: USB and UART, down and up) and each of ``BENCH_NOISY_SEEDS`` seeds (default
   20): home, check mode on, the same 1,000-line job (``tests/comm/noisy.py``). Printed:
   runs completed, runs whose executed log is exactly the program (each line once, in
   order), false link losses, phantom holds/stops (holds, stops, resets the CNC MCU
   carried out or HOLD statuses, none asked for), the legacy ``!``/0x18 the machines
   ignored (each one a phantom hold or stop of the old protocol), the median lines
   per simulated second and its share of the clean run's, the median resends.
2. Hold latency: a motion job through the noise, the operator clicks Hold: simulated
   ms until the CNC MCU holds (median, 95th percentile, worst, how many within 50 ms).
3. Fuzz: ``BENCH_FUZZ_BYTES`` (default 1,000,000) random bytes, all 256 values, in
   bursts of 1-200 onto both downward wires, at an idle machine and under a running
   motion job: anything started, the job left, a PING answered afterwards.

Figures are printed, never asserted; the load average is printed beside them.
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time

from tests.comm.noisy import fuzz_job_lines, fuzz_run, hold_latency, noisy_run
from tests.comm.simlink import dialect_program

RATES = (0.0, 1e-3, 3e-3, 1e-2)
LINES = 1000
HOLD_RATES = (1e-3, 3e-3, 1e-2)


def _load() -> str:
    return "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def job_matrix(seeds: int) -> None:
    lines = dialect_program(LINES, seed=5)
    print(f"{LINES}-line job after HOME and SET CHECK 1, {seeds} seeds per rate, simulated clock; "
          f"flip, drop and duplicate each at the rate, every wire; {_load()}")
    print(f"{'rate/byte':>10} {'completed':>10} {'exact':>6} {'false lost':>10} {'phantoms':>9} "
          f"{'legacy':>7} {'lines/s':>8} {'of clean':>9} {'resends':>8} {'wall s':>7}")
    clean = None
    for rate in RATES:
        wall = time.perf_counter()
        outcomes = []
        for seed in range(1, seeds + 1):
            with tempfile.TemporaryDirectory() as sd:
                outcomes.append(noisy_run(lines, rate, seed, sd))
        done = [o for o in outcomes if o.completed and o.exact]
        speed = statistics.median(o.lines_per_s for o in done) if done else 0.0
        clean = clean or speed
        print(f"{rate:>10g} {sum(o.completed for o in outcomes):>7}/{seeds:<2} {len(done):>6} "
              f"{sum(o.false_losses for o in outcomes):>10} {sum(o.phantoms for o in outcomes):>9} "
              f"{sum(o.legacy for o in outcomes):>7} {speed:>8.1f} {speed / clean if clean else 0:>9.0%} "
              f"{statistics.median(o.resends for o in outcomes):>8.0f} {time.perf_counter() - wall:>7.1f}")
        for o in outcomes:
            if not (o.completed and o.exact):
                print(f"{'':>10}   failed: {o.reason}")


def hold_figures(seeds: int) -> None:
    print(f"\nhold latency: motion job, Hold clicked at a random moment, {seeds} seeds; {_load()}")
    print(f"{'rate/byte':>10} {'held':>6} {'median ms':>10} {'p95 ms':>7} {'worst ms':>9} {'<= 50 ms':>9}")
    for rate in HOLD_RATES:
        with tempfile.TemporaryDirectory() as sd:
            found = [hold_latency(seed, rate, sd) for seed in range(1, seeds + 1)]
        held = sorted(1000 * t for t in found if t is not None)
        if not held:
            print(f"{rate:>10g} {0:>3}/{seeds:<2}")
            continue
        p95 = held[min(len(held) - 1, round(0.95 * (len(held) - 1)))]
        print(f"{rate:>10g} {len(held):>3}/{seeds:<2} {statistics.median(held):>10.1f} {p95:>7.1f} "
              f"{held[-1]:>9.1f} {sum(t <= 50 for t in held):>6}/{len(held):<2}")


def fuzz_figures(total: int) -> None:
    print(f"\nfuzz: {total:,} random bytes (0x00-0xFF) in bursts of 1-200 on USB and UART down; {_load()}")
    lines = fuzz_job_lines(total)
    for label, job_lines in (("idle machine", 0), (f"running a {lines}-line motion job", lines)):
        wall = time.perf_counter()
        with tempfile.TemporaryDirectory() as sd:
            o = fuzz_run(total, 1, sd, job_lines)
        yes = {True: "yes", False: "no"}
        print(f"  {label}: thrown {o.thrown:,}; started anything: {yes[o.moved]}; left the job: "
              f"{yes[o.left_job]}; executed log exact: {yes[o.exact]}; phantom holds/stops: {o.phantoms}; "
              f"legacy bytes ignored: {o.legacy}; PING answered afterwards: {yes[o.pinged]}; "
              f"{time.perf_counter() - wall:.0f} s wall" + (f"; {o.reason}" if o.reason else ""))


def main() -> None:
    seeds = int(os.environ.get("BENCH_NOISY_SEEDS", "20"))
    job_matrix(seeds)
    hold_figures(seeds)
    fuzz_figures(int(os.environ.get("BENCH_FUZZ_BYTES", "1000000")))


if __name__ == "__main__":
    main()
