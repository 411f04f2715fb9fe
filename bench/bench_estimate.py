"""The planner's time estimate (``app.gcode.estimate``) against the simulator's run time.

For every sample in resources/samples and a generated 1 M-line file: the estimate (total
and parts, stops apart), the time the simulated machine took (simulated seconds, so exact
and independent of the load; the job streamed from its SD card, program stops released
at once, timed from the first move to the last line's finish), the error in %, and the
seconds the estimate took to compute. The 1 M-line file runs on the simulator as a prefix
(``PREFIX_LINES`` lines and an M02), its estimate over the whole file is timed apart.
"""

from __future__ import annotations

import math
import os
import tempfile
import time
from pathlib import Path

from app.comm.frame import seal
from app.gcode import load, load_text
from app.gcode.estimate import estimate
from backend_sim.simulator import Simulator

SAMPLES = Path(__file__).resolve().parent.parent / "resources" / "samples"
PREFIX_LINES = 20_000
BIG_LINES = 1_000_000


def real_run(lines: list[str], profile=None, timeout_s: float = 36000.0) -> tuple[float, tuple]:
    """Simulated seconds from the job's first move until its last line has finished, and
    where the job started (work mm: the homed position less the work offset)."""
    with tempfile.TemporaryDirectory() as sd:
        (Path(sd) / "job.nc").write_text("\n".join(lines) + "\n", encoding="ascii")
        sim = Simulator(profile=profile, sd_dir=sd, seed=1)
        mc = sim.cnc.mc
        sim.host_port.write(seal("C 1 HOME"))
        if not sim.run_until(lambda: mc.homed and mc.state == "IDLE", 300):
            raise RuntimeError("the simulator did not home")
        offset = sim.cnc.offset
        start = tuple(p - o for p, o in zip(mc.planner.pos, offset, strict=True))
        sim.host_port.write(seal("C 2 SD RUN job.nc"))
        if not sim.run_until(lambda: mc.state == "RUN", 10):
            raise RuntimeError("the job did not start")
        started = sim.clock.now
        done = lambda: len(sim.exec_log) >= len(lines)  # noqa: E731
        while not done():
            if not sim.run_until(lambda: done() or mc.waiting is not None, timeout_s):
                raise RuntimeError(f"not done after {timeout_s} simulated s")
            if mc.waiting is not None:
                mc.resume()  # the operator's wait at a stop is not the machine's time
        return sim.clock.now - started, start


def big_program(n_lines: int) -> str:
    """A traced-looking program: short segments and small arcs around a spiral, passes in Z."""
    out = ["G21 G90 G17", "M03 S4000", "G00 Z5", "G00 X75 Y75", "G01 Z-0.2 F200"]
    angle, k = 0.0, 0
    while len(out) < n_lines - 2:
        k += 1
        radius = 10 + (k % 4000) * 0.015
        angle += 0.03 + 0.02 * math.sin(k * 0.01)
        x, y = 75 + radius * math.cos(angle), 75 + radius * math.sin(angle)
        if k % 97 == 0:
            out.append(f"G03 X{x:.3f} Y{y:.3f} R{radius:.3f} F{300 + k % 5 * 50}")
        else:
            out.append(f"G01 X{x:.3f} Y{y:.3f}")
    return "\n".join(out + ["G00 Z5", "M02"]) + "\n"


def short_segments(step_mm: float, feed: float, n: int = 600) -> str:
    """A circle of radius 10 in chords of ``step_mm``: the look-ahead's hardest case."""
    turn = step_mm / 10.0
    return ("G00 X20 Y20 Z2\nG01 Z0 F200\n" + "".join(
        f"G01 X{20 + 10 * math.cos(k * turn):.4f} Y{20 + 10 * math.sin(k * turn):.4f} F{feed:g}\n"
        for k in range(n)) + "M02\n")


def compare(name: str, program, prefix_note: str = "") -> None:
    real, start = real_run(list(program.device_lines), program.profile)
    t0 = time.perf_counter()
    est = estimate(program.toolpath, program.device_lines, program.profile, start=start)
    took = time.perf_counter() - t0
    figure = est.total + est.stop_seconds
    error = 100.0 * (figure - real) / real if real else 0.0
    old = program.toolpath.estimated_time
    print(f"{name:22s} est {est.total:8.2f} s (motion {est.motion:.2f}, dwell {est.dwell:.2f}, "
          f"spin-up {est.spin_up:.2f}; stops {est.stops}, tool changes {est.tool_changes}, "
          f"{est.stop_seconds:.2f} s apart)  real {real:8.2f} s  error {error:+5.2f} %  "
          f"(length/feed {100.0 * (old - real) / real:+5.1f} %)  computed in {took * 1000:.0f} ms"
          f"{prefix_note}",
          flush=True)


def main() -> None:
    print(f"load average {os.getloadavg()[0]:.2f}; real = simulated seconds of the run")
    for path in sorted(SAMPLES.glob("*.ngc")):
        compare(path.name, load(path))
    for step, feed in ((0.01, 600), (0.025, 600), (0.05, 600), (0.1, 600), (0.025, 300)):
        compare(f"chords {step} mm F{feed}", load_text(short_segments(step, feed)))
    text = big_program(BIG_LINES)
    t0 = time.perf_counter()
    big = load_text(text)
    loaded = time.perf_counter() - t0
    t0 = time.perf_counter()
    device_lines = big.device_lines  # the loader renders them in the background first
    rendered = time.perf_counter() - t0
    took = []
    for _ in range(2):
        t0 = time.perf_counter()
        est = estimate(big.toolpath, device_lines, big.profile)
        took.append(time.perf_counter() - t0)
    print(f"{BIG_LINES} lines: loaded in {loaded:.2f} s, device lines rendered in {rendered:.2f} s; "
          f"estimate {est.total:.1f} s computed in {took[0]:.2f} s, again {took[1]:.2f} s (target <= 2 s), "
          f"load average {os.getloadavg()[0]:.2f}")
    lines = text.splitlines()
    prefix = load_text("\n".join(lines[:PREFIX_LINES] + ["M02"]) + "\n")
    compare(f"first {PREFIX_LINES} lines", prefix, "  (a prefix of the 1 M-line file run on the simulator)")


if __name__ == "__main__":
    main()
