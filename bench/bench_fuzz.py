"""Long fuzz run (issue 14 point 10): every target of ``tests/fuzz/targets.py`` with a
large example budget, ``BENCH_FUZZ_EXAMPLES`` in all (default 1,000,000), shared out by
weight (the cheap targets get most). Prints the examples each target ran (counted at
the call, not taken from the budget), the failures (hypothesis reports the shrunk
input), and the total. Printed, never asserted.
"""

from __future__ import annotations

import os
import time
import traceback

from hypothesis import HealthCheck, Phase, given, settings

from tests.fuzz.targets import TARGETS

WEIGHTS = {"gcode text": 2, "gcode bytes": 2, "deframer": 30, "codec": 30, "machine commands": 3,
           "dialect parser": 27, "settings loader": 3, "profile loader": 3}


def _counting(target, calls: list[int]):
    """``target`` that counts its calls in ``calls[0]``."""

    def counted(value) -> None:
        calls[0] += 1
        target(value)

    return counted


def main() -> None:
    total = int(os.environ.get("BENCH_FUZZ_EXAMPLES", "1000000"))
    share = sum(WEIGHTS.values())
    grand, failures = 0, 0
    for name, (strategy, target) in TARGETS.items():
        budget = max(1, total * WEIGHTS[name] // share)
        calls = [0]
        counted = _counting(target, calls)
        run = settings(max_examples=budget, deadline=None, database=None,
                       phases=[Phase.generate, Phase.shrink],
                       suppress_health_check=list(HealthCheck))(given(strategy)(counted))
        started = time.perf_counter()
        try:
            run()
            verdict = "no failure"
        except Exception:  # a fuzz failure: print it and go on with the other targets
            failures += 1
            verdict = "FAILED:\n" + traceback.format_exc(limit=3)
        grand += calls[0]
        print(f"{name:>17}: {calls[0]:>9,} examples in {time.perf_counter() - started:7.1f} s, {verdict}",
              flush=True)
    print(f"{'all targets':>17}: {grand:>9,} examples, {failures} failing target(s)")


if __name__ == "__main__":
    main()
