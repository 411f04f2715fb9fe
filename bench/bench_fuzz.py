"""Long fuzz run (issue 14 point 10): every target of ``tests/fuzz/targets.py`` with its
own example budget (``EXAMPLES``, 1,010,000 in all), so the total does not depend on
the machine's speed; ``BENCH_FUZZ_SCALE`` scales every budget (0.001 for a quick look).

Each target runs hypothesis in chunks of at most ``CHUNK`` examples (a fresh random
seed each, which keeps hypothesis's record of tried inputs small) until it has run its
budget. Examples are counted at the call of the target (one call = one example
hypothesis generated and ran), never taken from the budget; a chunk that ends early
(hypothesis found nothing new to try) is simply followed by another. A failure is
printed (hypothesis's shrunk input) and the target goes on with a new chunk, so one
bug does not cut the count short; after ``MAX_FAILURES`` failures it stops. Prints the
examples, seconds and milliseconds per example of each target, and the total.
Printed, never asserted.
"""

from __future__ import annotations

import os
import time
import traceback

from hypothesis import HealthCheck, Phase, given, settings

from tests.fuzz.targets import TARGETS

# Cheap targets get the most; the slow ones (the G-code loader, the simulator, the settings
# and profile loaders) a fixed share each that no time limit can take from them.
EXAMPLES = {"gcode text": 25_000, "gcode bytes": 25_000, "deframer": 220_000, "codec": 400_000,
            "machine commands": 30_000, "dialect parser": 220_000, "settings loader": 45_000,
            "profile loader": 45_000}
CHUNK = 20_000
MAX_FAILURES = 3


def _counting(target, calls: list[int]):
    """``target`` that counts its calls in ``calls[0]``."""

    def counted(value) -> None:
        calls[0] += 1
        target(value)

    return counted


def run_target(strategy, target, budget: int) -> tuple[int, list[str]]:
    """Run ``target`` on ``budget`` hypothesis examples; (examples run, failures)."""
    calls, failures = [0], []
    counted = _counting(target, calls)
    while calls[0] < budget and len(failures) < MAX_FAILURES:
        before = calls[0]
        run = settings(max_examples=min(CHUNK, budget - calls[0]), deadline=None, database=None,
                       phases=[Phase.generate, Phase.shrink],
                       suppress_health_check=list(HealthCheck))(given(strategy)(counted))
        try:
            run()
        except Exception:  # a fuzz failure: keep it and go on with a new chunk
            failures.append(traceback.format_exc(limit=3))
        if calls[0] == before:
            failures.append("hypothesis ran no example")
            break
    return calls[0], failures


def main() -> None:
    scale = float(os.environ.get("BENCH_FUZZ_SCALE", "1"))
    print(f"budget {sum(max(1, round(n * scale)) for n in EXAMPLES.values()):,} examples, "
          f"in chunks of at most {CHUNK:,}", flush=True)
    grand, failures, started_all = 0, 0, time.perf_counter()
    for name, (strategy, target) in TARGETS.items():
        budget = max(1, round(EXAMPLES[name] * scale))
        started = time.perf_counter()
        count, failed = run_target(strategy, target, budget)
        seconds = time.perf_counter() - started
        failures += bool(failed)
        grand += count
        verdict = f"{len(failed)} FAILURE(S):\n" + "\n".join(failed) if failed else "no failure"
        print(f"{name:>17}: {count:>9,} of {budget:>9,} examples in {seconds:7.1f} s "
              f"({seconds / max(count, 1) * 1000:.2f} ms each), {verdict}", flush=True)
    print(f"{'all targets':>17}: {grand:>9,} examples in {time.perf_counter() - started_all:.0f} s, "
          f"{failures} failing target(s)")


if __name__ == "__main__":
    main()
