"""The simulator's speed factor seen by a client that knows nothing of it (issue 11).

For each factor, ``cnc-sim --pty --speed N`` runs as its own process and the project's
console (no time option: its heartbeat is wall-clock) homes and runs a real Inkscape
sample to the end. Prints the wall time, the machine time the job took (from the
program's estimate), the factor achieved, and how often the machine declared the host
lost (must be 0). Figures only; nothing is asserted.
"""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SAMPLE = Path(__file__).resolve().parent.parent / "resources" / "samples" / "arcs_circles.ngc"
SPEEDS = (10, 50, 100)


def _run(speed: int, sd: Path) -> tuple[float, int, int]:
    from app.comm.console import main as console_main

    args = ["--pty", "--speed", str(speed), "--sd", str(sd)]
    proc = subprocess.Popen([sys.executable, "-m", "backend_sim", *args], stdout=subprocess.PIPE, text=True)
    try:
        path = proc.stdout.readline().split()[1]
        out = io.StringIO()
        started = time.perf_counter()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
            code = console_main([path, "-q", "--at-stops", "continue", "run", str(SAMPLE)])
        wall = time.perf_counter() - started
    finally:
        proc.terminate()
        proc.communicate(timeout=10)
    return wall, code, out.getvalue().count("HOST_LOST")


def main() -> None:
    from app.gcode import load

    machine_s = load(SAMPLE).toolpath.estimated_time
    print(f"{SAMPLE.name}: estimated {machine_s:.1f} s of machine time (plus homing)")
    for speed in SPEEDS:
        with tempfile.TemporaryDirectory() as sd:
            wall, code, lost = _run(speed, Path(sd))
        print(f"--speed {speed:>3}: {wall:6.1f} s wall, {machine_s / wall:5.1f}x achieved "
              f"(job only, homing included in wall), exit {code}, HOST_LOST {lost}")


if __name__ == "__main__":
    main()
