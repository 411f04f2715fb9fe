"""G-code load benchmark: 1,000,000+ lines -> Program with Toolpath arrays (issue 13).

Builds (or reuses) two files in ``bench/data/`` from shifted copies of the Inkscape
samples in ``resources/samples/*.ngc`` (their ``%`` and ``M2``/``M30`` lines dropped,
one ``M2`` at the end): ``far.ngc``, nine copies in ten moved 200-680 mm, far outside
the 150 mm travel, and ``big.ngc``, copies moved by up to 4.5 mm, inside it; and
``arcs.ngc`` (``bench/arcfile.py``), arc-heavy, as Gcodetools writes a traced drawing,
9 copies in 10 outside the travel; and ``traced.ngc`` (``bench/tracedfile.py``), copies of
a real one (``resources/samples/traced_drawing.ngc``, left out of the other two). For each:
``cnc-gcode check`` as a whole fresh process (median of 5: wall, CPU and peak RSS by
``wait4``), paired with CNCjs's ``gcode-toolpath`` (npm, when ``node`` is there) on the
same file, then ``gcode-parser`` and PyPI ``gcodeparser`` once, the ratios, the CPU
time of each stage of one load, and the window's figures from ``bench_ui`` (first
picture after Open, pan/zoom, timer lateness while the rest loads; then the first picture
again in more fresh processes, and its median: one open is one sample). Then ``arcs.ngc``
in four other spellings (``bench/spellings.py``: padded, lower case, numbered, mixed),
each paired with the compact file (time and peak memory). Then a 10,000-line
file and a bare ``import app.gcode.cli`` as whole processes, and in one process: load
with and without the helper process, peak memory, device lines. The machine may be
shared: compare CPU times and medians. Figures are printed, never asserted.
"""

from __future__ import annotations

import compileall
import os
import re
import statistics
import subprocess
import sys
import time
from functools import partial
from pathlib import Path

from bench import arcfile, machine, peers, spellings, tracedfile
from bench.copies import AXIS, ENDS, count_lines, far_offset

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "bench" / "data"
BIG = DATA / "big.ngc"
FAR = DATA / "far.ngc"
TARGET_LINES = 1_000_000
ARCS_ORIGIN = ("bench/arcfile.py: a traced drawing as Gcodetools writes it (biarcs, G02/G03 with I J, "
               "six decimals, comments): one drawing of 80 paths, 203 copies at 26 places, 9 in 10 outside "
               "the travel")


def _shift(text: str, dx: float, dy: float) -> str:
    def repl(m: re.Match) -> str:
        d = dx if m.group(1) == "X" else dy
        return f"{m.group(1)}{float(m.group(2)) + d:.6f}"

    return AXIS.sub(repl, text)


def _sources() -> tuple[list[str], str]:
    samples = sorted(p for p in (ROOT / "resources" / "samples").glob("*.ngc") if p != tracedfile.SAMPLE)
    texts = []
    for path in samples:
        lines = [line for line in path.read_text().splitlines() if not ENDS.match(line)]
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


def build(far: bool = False) -> tuple[Path, str]:
    """The big file (built once, then reused) and a description of its origin.

    ``far=False`` (``big.ngc``): copies moved by up to 4.5 mm, inside the travel.
    ``far=True`` (``far.ngc``): nine copies in ten moved 200-680 mm in X and Y, far
    outside the 150 mm travel (so the checks' out-of-travel branch works on most rows)."""
    texts, origin = _sources()
    path = FAR if far else BIG
    if path.exists() and sum(1 for _ in path.open()) >= TARGET_LINES:
        return path, origin + " (reused)"
    DATA.mkdir(parents=True, exist_ok=True)
    out, count, copy = [], 0, 0
    while count < TARGET_LINES:
        for text in texts:
            inch = re.search(r"\bG20\b", text) is not None
            mm = far_offset(copy) if far else (copy % 10) * 0.5
            step = mm / 25.4 if inch else mm
            shifted = _shift(text, step, step)
            out.append(shifted)
            out.append("G21\n" if inch else "")
            count += shifted.count("\n") + inch
            copy += 1
    out.append("M5\nM2\n")
    path.write_text("".join(out))
    return path, origin + (", 9 copies in 10 far outside the travel" if far else ", inside the travel")


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


def _stages(path: Path) -> tuple[str, str]:
    """CPU seconds of each stage of one load, the steps of ``program._interpret``, the
    planner's estimate and the ``check`` summary (arcs: the scan reads them with the
    lines; interpret checks their radii; plan rounds them as sent and counts chords;
    toolpath their lengths; estimate their tangents and speed limits; summary their
    quadrant points for the bounds); and where the time goes, largest share first.
    One process on one core: ``cnc-gcode check`` runs the plan beside the toolpath, the
    checks (and the summary's bounds) beside the estimate, and shares a big scan with a
    forked child on a quiet machine."""
    from app.gcode import bulk, checks, normalize, runner
    from app.gcode.cli import _summary
    from app.gcode.diagnostics import Report
    from app.gcode.ops import OpBuffer
    from app.gcode.program import Program, _estimate
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
    plan = step("plan", lambda: normalize.plan(ops, profile.motion.arc_tolerance_mm))
    toolpath = step("toolpath", lambda: build(ops, plan.first, profile))
    ops.hand_over(toolpath)  # as load does: the checks read the moves from the toolpath
    step("checks", lambda: checks.run(ops, profile, lines, report))
    program = Program(str(path), lines, report.finish(), ops, toolpath, profile, plan)
    step("estimate", lambda: program.planned)  # the machine planner's time (estimate.py)
    step("summary", lambda: _summary(program))  # bounds (arcs' quadrants), lengths, time
    total = sum(spent.values())
    shares = sorted(spent.items(), key=lambda item: -item[1])
    where = ", ".join(f"{name} {cpu / total:.0%}" for name, cpu in shares if cpu >= 0.02 * total)
    traced = _traced_mb(partial(_estimate, toolpath, ops, plan, profile))
    where += f"; the estimate alone allocates at most {traced:.0f} MB"
    return ", ".join(f"{name} {cpu:.2f}" for name, cpu in spent.items()) + f" (sum {total:.2f})", where


def _traced_mb(fn) -> float:
    """Peak MB that ``fn()`` allocates (numpy arrays and Python objects, ``tracemalloc``)
    on top of what is there: a figure the machine's load and the allocator do not move."""
    import tracemalloc

    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1] / 2**20
    finally:
        tracemalloc.stop()


_GCODEPARSER = ("import sys\nfrom gcodeparser import parse_gcode_lines\n"
                "for _ in parse_gcode_lines(open(sys.argv[1]).read()): pass\n")
RUNS = 5  # whole-process runs of ours and of gcode-toolpath, paired, per file
PICTURE_RUNS = 5  # fresh processes that open each file in the window (the first one with every figure)


def _small(path: Path, lines: int = 10_000) -> Path:
    """The first ``lines`` lines of ``path`` and an M2: a file of everyday size."""
    small = DATA / f"head_{lines // 1000}k.ngc"
    if not small.exists():
        with path.open() as src:
            small.write_text("".join(next(src) for _ in range(lines)) + "M2\n")
    return small


def _whole(runs: list, what: str) -> str:
    wall = statistics.median(r.wall for r in runs)
    cpu = statistics.median(r.cpu for r in runs)
    peak = statistics.median(r.peak_mb for r in runs)
    spread = f"{min(r.wall for r in runs):.2f}-{max(r.wall for r in runs):.2f}"
    peaks = f"{min(r.peak_mb for r in runs):.0f}-{max(r.peak_mb for r in runs):.0f}"
    return (f"{what}: {wall:.2f} s wall (median of {len(runs)}, {spread}), {cpu:.2f} s CPU, "
            f"peak {peak:.0f} MB ({peaks}) [load {_loadavg()}]")


def _versus(path: Path) -> None:
    """``cnc-gcode check`` and the peers on ``path``, each a whole fresh process, paired
    runs (ours, then gcode-toolpath) so that both see the same load on the machine."""
    ours = [sys.executable, "-m", "app.gcode", "check", str(path)]
    node, modules = peers.node_peers()
    peer = [*node[next(iter(node))], str(path)] if node else []
    env = peers.node_env(modules) if node else None
    toolpath_name = next(iter(node)) if node else ""
    mine, theirs, stolen = [], [], {"ours": 0.0, "theirs": 0.0}
    for _ in range(RUNS):
        mine.append(_stolen_from(stolen, "ours", peers.measure, ours))
        if node:
            theirs.append(_stolen_from(stolen, "theirs", peers.measure, peer, env=env))
    print("  " + _whole(mine, "cnc-gcode check (whole process)") + f"; exit status {mine[0].status}")
    print(f"    the host took {stolen['ours']:.1f} s of CPU from this machine during our runs, "
          f"{stolen['theirs']:.1f} s during the peer's (steal time: a share of the wall times above)")
    summary = [row for row in mine[0].out.splitlines() if row.startswith(("lines:", "warnings:"))]
    print("    " + " / ".join(summary))
    wall, cpu = statistics.median(r.wall for r in mine), statistics.median(r.cpu for r in mine)
    if not node:
        print(f"  CNCjs peers skipped: {modules}")
    else:
        print("  " + _whole(theirs, toolpath_name))
        their_wall, their_cpu = (statistics.median(r.wall for r in theirs),
                                 statistics.median(r.cpu for r in theirs))
        best = min(r.wall for r in theirs) / min(r.wall for r in mine)
        print(f"    ours is {their_wall / wall:.1f}x faster by wall clock (medians), {best:.1f}x (best of "
              f"{RUNS}; target >= 5x), {their_cpu / cpu:.1f}x by CPU time")
        for name, argv in list(node.items())[1:]:
            run = peers.measure([*argv, str(path)], env=env)
            print(f"  {name}: {run.wall:.2f} s wall, {run.cpu:.2f} s CPU, peak {run.peak_mb:.0f} MB "
                  f"(one run); ours {run.wall / wall:.1f}x faster by wall, {run.cpu / cpu:.1f}x by CPU")
    run = peers.measure([sys.executable, "-c", _GCODEPARSER, str(path)])
    print(f"  PyPI gcodeparser (parse only): {run.wall:.2f} s wall, {run.cpu:.2f} s CPU, peak "
          f"{run.peak_mb:.0f} MB (one run); ours {run.wall / wall:.1f}x faster by wall, "
          f"{run.cpu / cpu:.1f}x by CPU")


def _stolen_from(stolen: dict, key: str, fn, *args, **kwargs):
    """``fn(*args, **kwargs)``, adding to ``stolen[key]`` the CPU seconds the host took
    from this machine meanwhile (``machine.stolen``; nothing where that is not known)."""
    before = machine.stolen()
    result = fn(*args, **kwargs)
    after = machine.stolen()
    if before is not None and after is not None:
        stolen[key] += after - before
    return result


def _window(path: Path) -> None:
    """bench_ui's figures for opening ``path`` in the window, in a fresh process; then the
    first picture again in ``PICTURE_RUNS - 1`` more fresh processes, and its median."""
    stolen = {"window": 0.0}
    rows = _stolen_from(stolen, "window", _in_fresh_window, "open_file", path).splitlines()
    print("\n".join(f"  window: {row.strip()}" for row in rows))
    seconds = re.findall(r"first picture on screen ([0-9.]+) s", rows[0]) if rows else []
    seconds += [_stolen_from(stolen, "window", _in_fresh_window, "first_picture_only", path).strip()
                for _ in range(PICTURE_RUNS - 1)]
    try:
        times = sorted(float(t) for t in seconds)
    except ValueError:
        print(f"  window: a first-picture run failed ({seconds})")
        return
    print(f"  window: first picture over {len(times)} opens, each in a fresh process: median "
          f"{statistics.median(times):.2f} s ({times[0]:.2f}-{times[-1]:.2f}; target <= 1.2 s) "
          f"[load {_loadavg()}]; the host took {stolen['window']:.1f} s of CPU from this machine during them")


def _in_fresh_window(function: str, path: Path) -> str:
    """What ``bench.bench_ui.<function>(path)`` prints, run in a fresh process."""
    code = f"from bench.bench_ui import {function}; {function}({str(path)!r})"
    env = {**os.environ, "QT_QPA_PLATFORM": os.environ.get("QT_QPA_PLATFORM", "offscreen")}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, env=env)
    return done.stdout or f"the window benchmark failed: {done.stderr.strip()[-300:]}"


def main() -> None:
    from app.gcode import load, workers

    print(f"machine load average: {_loadavg()} on {os.cpu_count()} cores (cnc-gcode shares a big "
          f"file's scan with a forked child when half a core stood idle while it started and read "
          f"the file, by /proc/stat; where that cannot be told, at a load average of cores - 1 or less)")
    compiled = compileall.compile_dir(ROOT / "app", quiet=1)  # as pip compiles an installed package
    note = " (this environment writes none itself)" if sys.flags.dont_write_bytecode else ""
    print(f"python bytecode: app/ compiled{note}{'' if compiled else ', with errors'}")
    files = [build(far=True), build(far=False), (arcfile.build(), ARCS_ORIGIN)]
    files.append((tracedfile.build(), tracedfile.describe()))
    for path, origin in files:
        size = path.stat().st_size
        print(f"file: {path.relative_to(ROOT)}: {count_lines(path):,} lines, {size / 1e6:.1f} MB, "
              f"from {origin}")
        _versus(path)
        stages, where = _stages(path)
        print(f"  stages of one load, CPU s: {stages} [load {_loadavg()}]")
        print(f"    where the time goes: {where}; start-up (python, numpy, app) in the "
              f"'import app.gcode.cli' line below")
        _window(path)
    _spellings(files[2][0])
    small = _small(files[1][0])
    runs = [peers.measure([sys.executable, "-m", "app.gcode", "check", str(small)]) for _ in range(RUNS)]
    print(_whole(runs, f"{small.name} ({count_lines(small):,} lines), cnc-gcode check")
          + " (target <= 0.25 s)")
    runs = [peers.measure([sys.executable, "-c", "import app.gcode.cli"]) for _ in range(RUNS)]
    print(_whole(runs, "python -c 'import app.gcode.cli'"))
    path = files[1][0]
    workers.set_enabled(False)
    alone, alone_cpu, _ = _best_of(3, lambda: load(path))
    print(f"in one process, {path.name}: load -> Toolpath on one core: {alone:.2f} s wall, "
          f"{alone_cpu:.2f} s CPU, best of 3")
    workers.set_enabled(True)
    helper = workers.warm_up(wait=10)
    helper_cpu = _helper_cpu()
    wall, cpu, program = _best_of(3, lambda: load(path))
    helper_cpu = (_helper_cpu() - helper_cpu) / 3
    print(f"  load -> Toolpath{' with the helper process (the GUI)' if helper else ' (no helper process)'}: "
          f"{wall:.2f} s wall, {cpu:.2f} s CPU here + {helper_cpu:.2f} s in the helper (mean), best of 3")
    base, peak, helper_peak, used = _peak_mb(path)
    print(f"  peak resident memory of one load: {peak} MB (python + numpy + app alone: {base} MB)"
          + (f"; helper process {helper_peak} MB" if used else ""))
    started = time.perf_counter()
    device = program.device_lines
    print(f"  device lines (rendered on first use): {len(device):,} in {time.perf_counter() - started:.2f} s")



def _loadavg() -> str:
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"


def _spellings(compact: Path) -> None:
    """``compact`` and each spelling of it (``bench/spellings.py``), paired runs of
    ``cnc-gcode check`` as whole processes: time and peak memory (target: within 1.3x)."""
    print(f"spellings of {compact.name} ({count_lines(compact):,} lines), cnc-gcode check, "
          f"{RUNS} paired runs:")
    ours = [sys.executable, "-m", "app.gcode", "check"]
    for name, path in spellings.variants(compact).items():
        base, spelled = [], []
        for _ in range(RUNS):
            base.append(peers.measure([*ours, str(compact)]))
            spelled.append(peers.measure([*ours, str(path)]))

        def ratio(key: str, spelled=spelled, base=base) -> float:
            return statistics.median(getattr(r, key) for r in spelled) / statistics.median(getattr(r, key)
                                                                                        for r in base)

        print("  " + _whole(spelled, f"{name} ({path.stat().st_size / 1e6:.0f} MB)"))
        print("  " + _whole(base, f"compact ({compact.stat().st_size / 1e6:.0f} MB)"))
        print(f"    {name} to compact: wall {ratio('wall'):.2f}x, CPU {ratio('cpu'):.2f}x, peak "
              f"{ratio('peak_mb'):.2f}x (target <= 1.3x)")
