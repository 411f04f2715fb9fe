"""A relative-start program read again from the machine's position (issue 19): the time
``Program.from_start`` and its device lines take for a 1,000,000-line G91 program, work
that the window does on the loader's thread (``app/ui/machine_start.py``), never on the
GUI thread. Prints figures, never asserts them.

Run: ``.venv/bin/python -m bench bench_start``.
"""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

from app.gcode import load

LINES = 1_000_000


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    text = "G21 G91 F600\n" + "".join(f"G01 X{0.01 if k % 2 else -0.01} Y0.001\n" for k in range(LINES))
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "relative.ngc"
        path.write_text(text)
        started = time.perf_counter()
        program = load(path)
        loaded = time.perf_counter() - started
        started = time.perf_counter()
        job = program.from_start((10.0, 20.0, 5.0))
        job.device_lines  # noqa: B018 (rendered as the loader's thread renders them)
        again = time.perf_counter() - started
    print(f"{LINES:,} relative lines: loaded in {loaded:.2f} s; read again from the machine's position "
          f"with its device lines in {again:.2f} s (off the GUI thread)")


if __name__ == "__main__":
    main()
