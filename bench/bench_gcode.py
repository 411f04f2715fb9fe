"""G-code load benchmark: 1,000,000+ lines -> Program with Toolpath arrays.

Builds (or reuses) ``bench/data/big.ngc`` from shifted copies of the Inkscape samples
in ``resources/samples/*.ngc`` (each copy moved a little in X and Y, its ``%`` and
``M2``/``M30`` lines dropped, one ``M2`` at the end), then prints: the best of three
wall-clock times of ``app.gcode.load`` (Toolpath included) on one core (the helper
process of ``app.gcode.workers`` off) and with the helper scanning part of the file
on the second core (started and ready before timing, as the GUI does on start), the
CPU time of each stage of one load, the peak resident memory of a fresh process doing
one load (and of its helper), the time to render the device lines (done on first
use), and the time PyPI ``gcodeparser`` takes to parse the same file, with the
ratios. Figures are printed, never asserted.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import time
from functools import partial
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "bench" / "data"
BIG = DATA / "big.ngc"
TARGET_LINES = 1_000_000
_AXIS = re.compile(r"([XY])(-?\d*\.?\d+)")
_DROP = re.compile(r"^\s*(%|M0?2\b|M30\b)", re.IGNORECASE)


def _shift(text: str, dx: float, dy: float) -> str:
    def repl(m: re.Match) -> str:
        d = dx if m.group(1) == "X" else dy
        return f"{m.group(1)}{float(m.group(2)) + d:.6f}"

    return _AXIS.sub(repl, text)


def _sources() -> tuple[list[str], str]:
    samples = sorted((ROOT / "resources" / "samples").glob("*.ngc"))
    texts = []
    for path in samples:
        lines = [line for line in path.read_text().splitlines() if not _DROP.match(line)]
        texts.append("\n".join(lines) + "\n")
    if texts:
        return texts, f"{len(texts)} samples from resources/samples"
    return [_generated()], "a generated Inkscape-like file (no samples found)"


def _generated() -> str:
    rows = ["G21", "G00 Z5.000000", "G00 X10.000000 Y10.000000", "G01 Z-0.125000 F100.0(Penetrate)"]
    for k in range(200):
        rows.append(f"G01 X{10 + k * 0.1:.6f} Y{10 + (k % 7) * 0.3:.6f} Z-0.125000 F400.000000")
    rows.append("G02 X30.000000 Y10.000000 Z-0.125000 I0.000000 J5.000000 F400.000000")
    rows.append("G00 Z5.000000")
    return "\n".join(rows) + "\n"


def build() -> tuple[Path, str]:
    """The big file (built once, then reused) and a description of its origin."""
    texts, origin = _sources()
    if BIG.exists() and sum(1 for _ in BIG.open()) >= TARGET_LINES:
        return BIG, origin + " (reused)"
    DATA.mkdir(parents=True, exist_ok=True)
    out, count, copy = [], 0, 0
    while count < TARGET_LINES:
        for text in texts:
            inch = re.search(r"\bG20\b", text) is not None
            step = (copy % 10) * (0.5 / 25.4 if inch else 0.5)
            shifted = _shift(text, step, step)
            out.append(shifted)
            out.append("G21\n" if inch else "")
            count += shifted.count("\n") + inch
            copy += 1
    out.append("M5\nM2\n")
    BIG.write_text("".join(out))
    return BIG, origin


def _timed(fn) -> tuple[float, float, object]:
    """(wall s, CPU s of this process, result): CPU time is the fairer figure on a busy machine."""
    wall, cpu = time.perf_counter(), time.process_time()
    result = fn()
    return time.perf_counter() - wall, time.process_time() - cpu, result


def _best_of(n: int, fn) -> tuple[float, float, object]:
    """Best wall and CPU times of ``n`` runs and the last result (each run starts after
    the previous result is dropped, as a fresh load of one program would)."""
    wall, cpu, result = float("inf"), float("inf"), None
    for _ in range(n):
        result = None
        w, c, result = _timed(fn)
        wall, cpu = min(wall, w), min(cpu, c)
    return wall, cpu, result


_PEAK = """
import re, sys
def high_water_mb(pid="self"):  # VmHWM: a process's peak resident set (ru_maxrss survives exec)
    status = open(f"/proc/{pid}/status").read()
    return int(re.search(r"VmHWM:\\s+(\\d+)", status).group(1)) // 1024
if __name__ == "__main__":
    from app.gcode import load, workers
    helper = workers.warm_up(wait=10)
    base = high_water_mb()
    program = load(sys.argv[1]); program.toolpath.length.sum()
    print(base, high_water_mb(), sum(high_water_mb(pid) for pid in workers.helper_pids()), int(helper))
"""


def _peak_mb(path: Path) -> tuple[int, int, int, bool]:
    """(MB before loading, peak MB of the loading process, peak MB of the helper, helper used)."""
    script = DATA / "peak.py"  # a file, so that the helper process can import the main module
    script.write_text(_PEAK)
    out = subprocess.run([sys.executable, str(script), str(path)], capture_output=True, text=True,
                         check=True, cwd=ROOT).stdout.split()
    return int(out[0]), int(out[1]), int(out[2]), out[3] == "1"


def _helper_cpu() -> float:
    """CPU seconds the helper processes have used so far (Linux; 0 elsewhere)."""
    from app.gcode import workers

    total = 0.0
    for pid in workers.helper_pids():
        try:
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime
    return total


def _stages(path: Path) -> str:
    """CPU seconds of each stage of one load, the steps of ``program._interpret``."""
    from app.gcode import bulk, checks, normalize, runner
    from app.gcode.diagnostics import Report
    from app.gcode.ops import OpBuffer
    from app.gcode.source import Lines
    from app.gcode.toolpath import build
    from app.profile import MachineProfile

    profile, report, buffer, spent = MachineProfile(), Report(), OpBuffer(), {}

    def step(name, fn):
        started = time.process_time()
        result = fn()
        spent[name] = time.process_time() - started
        return result

    raw = step("read", path.read_bytes)
    lines = step("lines", lambda: Lines(data=raw))
    scan = step("scan", lambda: bulk.scan(raw, len(lines), lines.chunks))  # with the helper, if on
    step("interpret", partial(runner.run, lines, scan, buffer, report))
    del scan  # as load does: the scan table is freed before the rest
    ops = step("ops", buffer.finish)
    step("checks", lambda: checks.run(ops, profile, lines, report))
    plan = step("plan", lambda: normalize.plan(ops, profile.motion.arc_tolerance_mm))
    step("toolpath", lambda: build(ops, plan.first, profile))
    return ", ".join(f"{name} {cpu:.2f}" for name, cpu in spent.items()) + f" (sum {sum(spent.values()):.2f})"


def _gcodeparser(text: str) -> None:
    from gcodeparser import parse_gcode_lines

    for _ in parse_gcode_lines(text):
        pass


def main() -> None:
    from app.gcode import load, workers

    path, origin = build()
    text = path.read_text()
    lines = text.count("\n")
    print(f"file: {path.relative_to(ROOT)}: {lines:,} lines, {len(text) / 1e6:.1f} MB, from {origin}")
    print(f"machine load average: {_loadavg()}")
    workers.set_enabled(False)
    alone, alone_cpu, _ = _best_of(3, lambda: load(path))
    print(f"load -> Toolpath on one core (helper process off): {alone:.2f} s wall, {alone_cpu:.2f} s CPU, "
          "best of 3")
    workers.set_enabled(True)
    helper = workers.warm_up(wait=10)
    helper_cpu = _helper_cpu()
    wall, cpu, program = _best_of(3, lambda: load(path))
    helper_cpu = (_helper_cpu() - helper_cpu) / 3
    tp = program.toolpath
    print(f"load -> Toolpath{' with the helper process' if helper else ' (no helper process available)'}: "
          f"{wall:.2f} s wall, {cpu:.2f} s CPU here + {helper_cpu:.2f} s in the helper (mean), best of 3 "
          f"({lines / wall / 1e6:.2f} M lines/s wall); "
          f"{len(tp):,} moves, {len(program.errors)} errors, {len(program.warnings)} warnings")
    print(f"stages of one load, CPU s: {_stages(path)}")
    base, peak, helper_peak, used = _peak_mb(path)
    print(f"peak resident memory of one load: {peak} MB (python + numpy + app alone: {base} MB)"
          + (f"; helper process {helper_peak} MB" if used else ""))
    started = time.perf_counter()
    device = program.device_lines
    print(f"device lines (rendered on first use): {len(device):,} in {time.perf_counter() - started:.2f} s")
    their_wall, their_cpu, _ = _timed(lambda: _gcodeparser(text))
    print(f"gcodeparser parse_gcode_lines (parse only, no arcs or toolpath): {their_wall:.2f} s wall, "
          f"{their_cpu:.2f} s CPU; ours is {their_wall / wall:.1f}x faster by wall clock "
          f"({their_wall / alone:.1f}x on one core), {their_cpu / (cpu + helper_cpu):.1f}x by CPU time "
          "(both processes)")


def _loadavg() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"
