"""Expansion benchmark: parametric programs that expand to about 1,000,000 moves.

A grid of holes written as a Fanuc 21/31 macro B program (WHILE/DO/END, G65 with
arguments) and as its LinuxCNC twin (o-word while loops and a subroutine call): each
hole is a rapid above it, a plunge and a retract, 3 moves, 577 x 578 holes. Prints
for each dialect the wall and CPU time of ``app.gcode.load`` (expansion, interpreter,
checks, plan and Toolpath) and the CPU time of the expansion alone, each the best of
``REPEATS`` runs (the machine is shared: CPU time is the steadier figure), and the peak
resident memory of a fresh process doing one load; then the time LinuxCNC's ``rs274``
takes on the LinuxCNC twin in the same run (skipped with a message when rs274 is not
installed), with the ratio of its CPU time to each dialect's best load, and the 1 M-line
plain file of ``bench_gcode`` through the same ``load`` (the fast path, which the expander
must leave as it was). The goal (issue 24): each dialect's load at least 8 times rs274's
speed by CPU, in at most 400 MB. Figures are printed, never asserted.
"""

from __future__ import annotations

import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "bench" / "data"
ROWS, COLUMNS, PITCH = 577, 578, 0.25  # 333,506 holes, 1,000,518 moves
REPEATS = 3

FANUC = f"""%
O1000 (grid of holes: {ROWS} x {COLUMNS})
G21 G90 G17
#100 = 0
WHILE [#100 LT {ROWS}] DO 1
  #101 = 0
  WHILE [#101 LT {COLUMNS}] DO 2
    G65 P9010 X[#101 * {PITCH}] Y[#100 * {PITCH}] Z-0.5 F300
    #101 = #101 + 1
  END 2
  #100 = #100 + 1
END 1
M30
O9010 (one hole at X Y, depth Z, feed F)
G0 X#24 Y#25
G1 Z#26 F#9
G0 Z1
M99
%
"""

LINUXCNC = f"""(grid of holes: {ROWS} x {COLUMNS})
o<hole> sub
  G0 X#1 Y#2
  G1 Z#3 F#4
  G0 Z1
o<hole> endsub
G21 G90 G17
#100 = 0
o1 while [#100 LT {ROWS}]
  #101 = 0
  o2 while [#101 LT {COLUMNS}]
    o<hole> call [#101 * {PITCH}] [#100 * {PITCH}] [-0.5] [300]
    #101 = [#101 + 1]
  o2 endwhile
  #100 = [#100 + 1]
o1 endwhile
M2
"""

_PEAK = """
import re, sys
def high_water_mb():
    return int(re.search(r"VmHWM:\\s+(\\d+)", open("/proc/self/status").read()).group(1)) // 1024
from app.gcode import load
base = high_water_mb()
program = load(sys.argv[1]); program.toolpath.length.sum()
print(base, high_water_mb())
"""


def _files() -> dict[str, Path]:
    DATA.mkdir(parents=True, exist_ok=True)
    paths = {"Fanuc macro B": DATA / "holes_fanuc.nc", "LinuxCNC o-words": DATA / "holes_linuxcnc.ngc"}
    for (_, path), text in zip(paths.items(), (FANUC, LINUXCNC), strict=True):
        path.write_text(text)
    return paths


def _expansion_cpu(path: Path) -> tuple[float, int]:
    from app.gcode import macro
    from app.gcode.diagnostics import Report
    from app.gcode.ops import OpBuffer
    from app.gcode.state import State

    lines = path.read_text().splitlines()
    buffer = OpBuffer()
    started = time.process_time()
    macro.expand(lines, str(path), path.parent, State(), buffer, Report())
    ops = buffer.finish()
    return time.process_time() - started, len(ops)


def _peak_mb(path: Path) -> tuple[int, int]:
    out = subprocess.run([sys.executable, "-c", _PEAK, str(path)], capture_output=True, text=True,
                         check=True, cwd=ROOT).stdout.split()
    return int(out[0]), int(out[1])


def _rs274(path: Path) -> tuple[str, float]:
    """What rs274 took on ``path`` (said), and its CPU seconds (0 when it did not run it)."""
    if shutil.which("rs274") is None:
        return "rs274 is not installed (Debian: linuxcnc-uspace): skipped", 0.0
    with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
        program = Path(tmp) / "program.ngc"
        program.write_text(path.read_text())
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        wall = time.perf_counter()
        with open(Path(tmp) / "out.txt", "w") as out:
            proc = subprocess.run(["rs274", "-g", "program.ngc"], cwd=tmp, stdout=out, stderr=subprocess.PIPE,
                                  stdin=subprocess.DEVNULL, env={"HOME": tmp, "PATH": "/usr/bin:/bin"},
                                  check=False, text=True, timeout=600)
        wall = time.perf_counter() - wall
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        text = (Path(tmp) / "out.txt").read_text()
    moves = len(re.findall(r"STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED", text))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    status = "" if proc.returncode == 0 else f", exit {proc.returncode}: {proc.stderr.strip()[-200:]}"
    said = f"rs274 -g on the LinuxCNC twin: {wall:.2f} s wall, {cpu:.2f} s CPU, {moves:,} moves{status}"
    return said, cpu if proc.returncode == 0 else 0.0


def _seconds(values: list[float]) -> str:
    return "/".join(f"{v:.2f}" for v in values)


def main() -> None:
    from app.gcode import load

    print(f"machine load average: {Path('/proc/loadavg').read_text().split()[:3]}")
    paths = _files()
    best: dict[str, tuple[float, int]] = {}
    for name, path in paths.items():
        walls, cpus, (moves, device, errors) = _loads(load, path)
        print(f"{name} ({path.name}): load -> Toolpath best of {REPEATS}: {min(walls):.2f} s wall, "
              f"{min(cpus):.2f} s CPU (all: {_seconds(walls)} wall, {_seconds(cpus)} CPU); "
              f"{moves:,} moves, {device:,} device lines, errors {errors}")
        expand = [_expansion_cpu(path) for _ in range(REPEATS)]
        base, peak = _peak_mb(path)
        print(f"  expansion alone (walk + interpreter, {expand[0][1]:,} rows): best {min(expand)[0]:.2f} s "
              f"CPU; peak resident memory of one load {peak} MB (python + numpy + app alone: {base} MB)")
        best[name] = (min(cpus), peak)
    said, rs274_cpu = _rs274(paths["LinuxCNC o-words"])
    print(said)
    if rs274_cpu:
        print("  rs274's CPU time / the load's (goal >= 8x in <= 400 MB): " + "; ".join(
            f"{name} {rs274_cpu / cpu:.1f}x in {peak} MB" for name, (cpu, peak) in best.items()))
    print(_plain(load))


def _loads(load, path: Path) -> tuple[list[float], list[float], tuple]:
    """``REPEATS`` loads of ``path``: wall times, CPU times, (moves, device lines, errors)."""
    walls, cpus = [], []
    for _ in range(REPEATS):
        wall, cpu = time.perf_counter(), time.process_time()
        program = load(path)
        walls.append(time.perf_counter() - wall)
        cpus.append(time.process_time() - cpu)
        found = len(program.toolpath), program.device_count, [str(d) for d in program.errors][:2]
        del program
    return walls, cpus, found


def _plain(load) -> str:
    """The 1 M-line plain file of ``bench_gcode`` (``big.ngc``) through the same ``load``: the
    fast path the expander must leave as it was (issue 9: print both); then the same file
    with one parameter line before it, which needs the expander (issue 19: its plain lines
    are read by the fast path, ``macro/plain.py``)."""
    from bench.bench_gcode import build

    path, _ = build()
    walls, cpus, (moves, _, _) = _loads(load, path)
    said = (f"plain 1 M-line file ({path.name}, fast path): load -> Toolpath best of {REPEATS}: "
            f"{min(walls):.2f} s wall, {min(cpus):.2f} s CPU (all: {_seconds(walls)} wall); {moves:,} moves")
    one = DATA / "big_one_parameter.ngc"
    one.write_text("#1 = 1 (one parameter line: the expander reads the program)\n" + path.read_text())
    walls, cpus, (moves, _, errors) = _loads(load, one)
    _, peak = _peak_mb(one)
    return (f"{said}\nthe same with one parameter line ({one.name}, expander): best of {REPEATS}: "
            f"{min(walls):.2f} s wall, {min(cpus):.2f} s CPU (all: {_seconds(walls)} wall); {moves:,} moves, "
            f"errors {errors}; peak resident memory of one load {peak} MB")
