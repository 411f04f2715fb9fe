"""Peers and whole processes for the load benchmarks: each figure is one fresh process.

``measure(argv)`` runs a command to its end and returns its wall time and peak
resident memory (``os.wait4``: the child's own high-water mark). ``node_peers()``
installs CNCjs's ``gcode-toolpath`` and ``gcode-parser`` from npm into
``bench/data/node`` once, when ``node`` and ``npm`` are on the PATH, and returns the
commands that run them on a file (``None`` with the reason when they cannot be had).
"""

from __future__ import annotations

import os
import shutil
import statistics
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
NODE_DIR = ROOT / "bench" / "data" / "node"
SCRIPTS = Path(__file__).resolve().parent / "node"
PACKAGES = ("gcode-toolpath@3.0.0", "gcode-parser@2.2.0")


@dataclass(frozen=True)
class Run:
    """One finished process: wall seconds, peak resident MB, exit status, its output,
    CPU seconds (user + system; a busy machine stretches wall time, not this)."""

    wall: float
    peak_mb: float
    status: int
    out: str
    cpu: float = 0.0


_LAUNCH = """
import os, sys, time
started = time.perf_counter()
pid = os.fork()
if pid == 0:
    os.dup2(os.open(os.devnull, os.O_WRONLY), 2)
    try:
        os.execvp(sys.argv[1], sys.argv[1:])
    finally:
        os._exit(127)
_, status, usage = os.wait4(pid, 0)
print(time.perf_counter() - started, usage.ru_maxrss, usage.ru_utime + usage.ru_stime,
      os.waitstatus_to_exitcode(status), file=sys.stderr)
"""


def measure(argv: list[str], cwd: Path = ROOT, env: dict | None = None) -> Run:
    """Run ``argv`` to its end; its wall time and its peak resident memory.

    A small launcher process starts it: a child forked from a big process (this one,
    once it has loaded files) would report that process's memory as its own peak
    (Linux keeps ``ru_maxrss`` across fork and exec)."""
    proc = subprocess.Popen([sys.executable, "-S", "-c", _LAUNCH, *argv], cwd=cwd, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out, err = proc.communicate()
    wall, peak_kb, cpu, status = err.decode().split()[-4:]
    return Run(float(wall), int(peak_kb) / 1024, int(status), out.decode(errors="replace"), float(cpu))


def median_of(n: int, argv: list[str], **kwargs) -> tuple[float, float, list[Run]]:
    """(median wall s, median peak MB, the runs) of ``n`` fresh runs of ``argv``."""
    runs = [measure(argv, **kwargs) for _ in range(n)]
    return statistics.median(r.wall for r in runs), statistics.median(r.peak_mb for r in runs), runs


def node_peers() -> tuple[dict[str, list[str]] | None, str]:
    """({name: argv prefix}, "") for the CNCjs peers, or (None, why they are skipped)."""
    node, npm = shutil.which("node"), shutil.which("npm")
    if not node or not npm:
        return None, "node/npm not on the PATH"
    if not (NODE_DIR / "node_modules" / "gcode-toolpath").exists():
        NODE_DIR.mkdir(parents=True, exist_ok=True)
        done = subprocess.run([npm, "install", "--silent", "--no-audit", "--no-fund", "--prefix",
                               str(NODE_DIR), *PACKAGES], capture_output=True, text=True)
        if done.returncode != 0:
            return None, f"npm install failed: {done.stderr.strip()[:200]}"
    env_path = str(NODE_DIR / "node_modules")
    return {
        "gcode-toolpath 3.0.0 (loadFromStringSync, moves and bounds)":
            [node, str(SCRIPTS / "toolpath.js")],
        "gcode-parser 2.2.0 (parseFileSync)": [node, str(SCRIPTS / "parser.js")],
    }, env_path


def node_env(modules: str) -> dict:
    """The environment that lets the peer scripts find the installed packages."""
    return {**os.environ, "NODE_PATH": modules}
