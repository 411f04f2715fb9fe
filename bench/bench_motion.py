"""Benchmark of the CNC MCU's motion core (backend_sim.motion); prints figures, never fails.

1. Real-time factor of the motion core alone (3 axes + spindle, PID at 1 kHz, planner)
   running the largest sample as fast as possible, in wall and in CPU time, with a
   reference figure for this machine's Python speed.
2. For every sample in resources/samples: contour error (max, RMS) and job time of the
   planner and of the original firmware's simple method, and the speed-up, next to the
   feed-limited minimum (path length / programmed feed, no acceleration).

Run: ``.venv/bin/python -m bench bench_motion`` (or ``make bench``).
"""

from __future__ import annotations

import time
from pathlib import Path

from backend_sim.motion.accuracy import home, run_lines
from backend_sim.motion.controller import MotionController
from backend_sim.motion.dialect import DialectParser
from backend_sim.motion.geometry import Segment

SAMPLES = Path(__file__).resolve().parents[1] / "resources" / "samples"


def device_lines(path: Path) -> list[str]:
    from app.gcode import load  # the bench may use the host's normaliser

    return load(path).device_lines


def reference_ns() -> float:
    """ns per iteration of a trivial float loop: how fast Python runs here today."""
    t0, x = time.process_time(), 0.0
    for i in range(1_000_000):
        x += i * 0.5
    return (time.process_time() - t0) * 1000.0


def realtime_factor(lines: list[str], chunk_ms: int = 50) -> tuple[float, float, float, float]:
    """(simulated s, wall s, CPU s, us per tick) of the job, homing excluded."""
    ctl = MotionController(start_mm=(0.0, 0.0, 30.0))
    home(ctl)
    parser = DialectParser(ctl.profile.travel.work_offset(), ctl.commanded_mm)
    moves = [parser.parse(seq, line) for seq, line in enumerate(lines)]
    t0, nxt = ctl.now_ms, 0
    wall, cpu = time.perf_counter(), time.process_time()
    while nxt < len(moves) or not ctl.idle():
        while nxt < len(moves) and ctl.free_slots() > 0:
            ctl.enqueue(moves[nxt])
            nxt += 1
        ctl.advance(chunk_ms)
        ctl.events()
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    sim = (ctl.now_ms - t0) / 1000.0
    return sim, wall, cpu, cpu / (sim * 1000) * 1e6


def feed_limited_s(lines: list[str]) -> float:
    """Sum of length / feed (rapids at the rapid feed): no machine can be faster."""
    ctl = MotionController()
    parser = DialectParser(ctl.profile.travel.work_offset(), (0.0, 0.0, 30.0))
    pos, total = parser.position, 0.0
    rapid = ctl.profile.motion.rapid_mm_min
    for seq, line in enumerate(lines):
        move = parser.parse(seq, line)
        if move.moves_axes:
            feed = rapid if move.kind == "rapid" else min(move.feed, ctl.profile.motion.max_feed_mm_min)
            total += Segment.from_move(pos, move).length / feed * 60.0
            pos = move.target
        elif move.kind == "dwell":
            total += move.seconds
    return total


def main() -> None:
    samples = sorted(SAMPLES.glob("*.ngc"))
    if not samples:
        print("no samples in", SAMPLES)
        return
    programs = {p.name: device_lines(p) for p in samples}
    largest = max(programs, key=lambda n: len(programs[n]))
    print(f"python reference loop: {reference_ns():.0f} ns/iteration (about 30 on an idle desktop)")
    sim, wall, cpu, per_tick = realtime_factor(programs[largest])
    print(f"real-time factor, motion core on {largest} ({len(programs[largest])} lines, {sim:.1f} s):"
          f" {sim / wall:.0f}x wall, {sim / cpu:.0f}x CPU ({per_tick:.2f} us CPU per 1 ms tick)")
    print()
    head = f"{'sample':18} {'lines':>5} {'mode':8} {'job s':>8} {'max mm':>8} {'rms mm':>8} {'final':>7}"
    print(head + f" {'feed-limited s':>15}")
    for name, lines in programs.items():
        ideal = feed_limited_s(lines)
        limit = max(3600.0, 4 * ideal)  # the whole job, however long (traced_drawing runs 88 min)
        results = {mode: run_lines(lines, mode, limit_s=limit) for mode in ("planner", "simple")}
        for mode, r in results.items():
            alarms = f"  ALARMS {r.alarms}" if r.alarms else ""
            print(f"{name:18} {len(lines):5} {mode:8} {r.job_s:8.1f} {r.contour_max_mm:8.4f}"
                  f" {r.contour_rms_mm:8.4f} {r.final_error_counts:5.2f}c {ideal:15.1f}{alarms}")
        ratio = results["simple"].job_s / results["planner"].job_s
        print(f"{'':18} {'':5} planner is {ratio:.2f}x faster than simple", flush=True)


if __name__ == "__main__":
    main()
