"""Hold-to-jog figures of issue 21, on the simulator's clock through the real session.

For each per-byte rate (corrupt, drop and duplicate each at that rate, on every wire)
and ``BENCH_JOG_SEEDS`` seeds (default 5): home, then ``HOLDS`` holds of 1.5 s each,
alternately X+ and X-. Printed: seconds held, early stops (the machine's dead man ended
a jog while the key was still held), release -> at rest (ms, median and worst: the
deceleration from the jog feed included), and the run-on after the host falls silent
mid-jog (the USB cable pulled: ms from the pull to at rest, worst).
Figures are printed, never asserted; the load average is printed beside them.
"""

from __future__ import annotations

import os
import statistics
import tempfile

from tests.comm.simlink import FAST_HOMING, SimLink

RATES = (0.0, 3e-3, 1e-2)
HOLDS = 6
HOLD_S = 1.5
FEED = 600.0


def _load() -> str:
    return "load average " + " ".join(f"{x:.2f}" for x in os.getloadavg())


def _at_rest(link) -> bool:
    mc = link.sim.cnc.mc
    return mc.state == "IDLE" and not mc.stopping


def one_seed(rate: float, seed: int) -> tuple[int, list[float], float]:
    """(early stops, release->rest seconds per hold, silent->rest seconds)."""
    with tempfile.TemporaryDirectory() as sd:
        link = SimLink(seed=seed, sd_dir=sd, check=False, profile=FAST_HOMING)
        link.home()
        link.command_ok("JOG", "X", 60, 900)
        link.sim.faults.set_rates(seed=seed, corrupt=rate, drop=rate, duplicate=rate)
        early, releases = 0, []
        for n in range(HOLDS):
            logs = len(link.rec.of("on_log"))
            link.session.jog_hold(("X+" if n % 2 else "X-",), FEED)
            link.run_for(HOLD_S)
            early += sum("no keep-alive" in e.text for e in link.rec.of("on_log")[logs:])
            link.session.jog_hold((), FEED)
            released = link.now
            link.run_until(lambda: _at_rest(link), 2.0)
            releases.append(link.now - released)
        link.session.jog_hold(("X+",), FEED)
        link.run_for(0.5)
        silent = link.now
        link.sim.faults.unplug()  # the cable is pulled mid-jog
        link.run_until(lambda: _at_rest(link), 3.0)
        return early, releases, link.now - silent


def main() -> None:
    seeds = int(os.environ.get("BENCH_JOG_SEEDS", "5"))
    print(f"hold-to-jog at {FEED:g} mm/min, {HOLDS} holds of {HOLD_S:g} s per seed, {seeds} seeds, "
          f"simulated clock; corrupt, drop and duplicate each at the rate, every wire; {_load()}")
    print(f"{'rate/byte':>10} {'held s':>7} {'early stops':>11} {'release ms med':>14} "
          f"{'release ms max':>14} {'silent->rest ms max':>19}")
    for rate in RATES:
        runs = [one_seed(rate, seed) for seed in range(1, seeds + 1)]
        releases = [r for _, rs, _ in runs for r in rs]
        print(f"{rate:>10g} {seeds * HOLDS * HOLD_S:>7.0f} {sum(e for e, _, _ in runs):>11} "
              f"{statistics.median(releases) * 1000:>14.0f} {max(releases) * 1000:>14.0f} "
              f"{max(s for _, _, s in runs) * 1000:>19.0f}")


if __name__ == "__main__":
    main()
