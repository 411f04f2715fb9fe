"""Noisy-link matrix (issue 14 point 2): rate x completed x lines/s x resends.

For each total per-byte fault rate (drop, corrupt, duplicate and noise in equal shares
on all four wires, USB and UART, down and up) and each of ``BENCH_NOISY_SEEDS``
seeds (default 20): home, check mode on, a 1,000-line job, all on the simulator's
clock (``tests/comm/noisy.py``). Prints how many runs completed with the executed log
exactly the program, the median lines per simulated second (and as a share of the
clean link's), the median resends, and the false link losses (the host calling the
link lost). Targets: 3e-3 20/20 and >= 70 % of clean; 1e-2 >= 18/20. Printed, never
asserted.
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time

from tests.comm.noisy import noisy_run
from tests.comm.simlink import dialect_program

RATES = (0.0, 1e-4, 1e-3, 3e-3, 1e-2)
LINES = 1000


def main() -> None:
    seeds = int(os.environ.get("BENCH_NOISY_SEEDS", "20"))
    lines = dialect_program(LINES, seed=5)
    print(f"{LINES}-line job after HOME and SET CHECK 1, {seeds} seeds per rate, simulated clock")
    print(f"{'rate/byte':>10} {'completed':>10} {'exact':>6} {'lines/s':>8} {'of clean':>9} "
          f"{'resends':>8} {'false losses':>13} {'wall s':>7}")
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
        resends = statistics.median(o.resends for o in outcomes)
        print(f"{rate:>10g} {len([o for o in outcomes if o.completed]):>7}/{seeds:<2} {len(done):>6} "
              f"{speed:>8.1f} {speed / clean:>9.0%} {resends:>8.0f} "
              f"{sum(o.false_losses for o in outcomes):>13} {time.perf_counter() - wall:>7.1f}")
        for o in outcomes:
            if not (o.completed and o.exact):
                print(f"{'':>10}   failed: {o.reason}")


if __name__ == "__main__":
    main()
