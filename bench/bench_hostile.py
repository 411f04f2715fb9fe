"""Hostile programs (issue 19) through ``cnc-gcode check``, as an operator would run them.

Each program of ``tests/fuzz/hostile.py`` is laid out in a temporary folder and checked
by a fresh ``cnc-gcode check`` process; its wall time, CPU time (user + system) and
peak resident memory come from ``os.wait4`` (what ``/usr/bin/time -v`` reports), with
its first error. The goal: every one ends within 5 s and 1 GB on the 2-core machine, or
is refused naming a line. Printed, never asserted; the load average is printed beside
(the machine is shared: CPU time is the steadier figure).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tests.fuzz.hostile import PROGRAMS, write  # noqa: E402


def _check(path: Path) -> tuple[float, float, float, int, str]:
    """(wall s, CPU s, peak MB, exit status, first error) of ``cnc-gcode check path``."""
    started = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "app.gcode", "check", str(path)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    wall = time.perf_counter() - started
    first = next((line for line in out.splitlines() if line.startswith(("error:", "Traceback"))), "")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, proc.returncode, first


def main() -> None:
    print(f"machine load average: {' '.join(Path('/proc/loadavg').read_text().split()[:3])} "
          f"on {os.cpu_count()} cores")
    worst_wall = worst_cpu = worst_mb = 0.0
    for name in PROGRAMS:
        with tempfile.TemporaryDirectory(prefix="hostile-") as tmp:
            wall, cpu, mb, code, first = _check(write(Path(tmp), name))
        worst_wall, worst_cpu, worst_mb = max(worst_wall, wall), max(worst_cpu, cpu), max(worst_mb, mb)
        print(f"{name:45s} {wall:6.2f} s wall {cpu:6.2f} s CPU {mb:7.0f} MB  exit {code}  {first[:90]}",
              flush=True)
    print(f"worst: {worst_wall:.2f} s wall, {worst_cpu:.2f} s CPU, {worst_mb:.0f} MB peak resident "
          f"({len(PROGRAMS)} programs)")


if __name__ == "__main__":
    main()
