"""Programs that leave the fast path (issue 9, part 2): how fast the general
interpreter expands work offsets, cutter compensation and canned cycles.

Builds three programs in memory, each about 100,000 lines, and prints the best of
three load times (text -> Program with Toolpath), the rows made, and the lines per
second; rs274's time on the same text when ``rs274`` is installed. Printed, never
asserted.
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
import time
from pathlib import Path

from app.gcode import load_text
from app.gcode.tools import Tool

LINES = 100_000
TOOLS = {1: Tool(1, 6.0, 0.0)}


def _offsets() -> str:
    body = [f"G1 X{i % 97} Y{(i * 7) % 89} F300\n" for i in range(LINES)]
    return "G10 L2 P1 X5 Y5\nG92 X1\n" + "".join(body) + "M2\n"


def _compensation() -> str:
    """A zig-zag profile under G41: every corner is concave or convex in turn."""
    body = [f"G1 X{(i + 1) * 10} Y{10 if i % 2 else 0}\n" for i in range(LINES - 3)]
    return "G0 X-10 Y-10\nG41 D1 G1 X0 Y0 F300\n" + "".join(body) + "G40 G1 X-10 Y-10\nM2\n"


def _cycles() -> str:
    body = [f"X{i % 100} Y{i // 100 % 100}\n" for i in range(LINES - 2)]
    return "G0 Z5\nG99 G83 X0 Y0 Z-6 R1 Q2 F200\n" + "".join(body) + "G80\nM2\n"


def _best_of_three(text: str) -> tuple[float, int, int]:
    best, rows, errors = float("inf"), 0, 0
    for _ in range(3):
        started = time.perf_counter()
        program = load_text(text, tools=TOOLS)
        best = min(best, time.perf_counter() - started)
        rows, errors = len(program.toolpath), len(program.errors)
    return best, rows, errors


def _rs274(text: str) -> str:
    if shutil.which("rs274") is None:
        return "rs274 not installed"
    with tempfile.TemporaryDirectory() as tmp:
        Path(tmp, "p.ngc").write_text(text)
        Path(tmp, "tool.tbl").write_text(f"T1 P1 D{6 / 25.4!r}\n")
        started = time.perf_counter()
        env = {"HOME": tmp, "PATH": "/usr/bin:/bin"}
        subprocess.run(["rs274", "-g", "-t", "tool.tbl", "p.ngc"], cwd=tmp, env=env, stdin=subprocess.DEVNULL,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        return f"rs274 -g {time.perf_counter() - started:.2f} s"


def main() -> None:
    for name, make in (("work offsets + G92", _offsets), ("cutter compensation", _compensation),
                       ("canned cycles (G83)", _cycles)):
        text = make()
        seconds, rows, errors = _best_of_three(text)
        lines = text.count("\n")
        print(f"{name}: {lines:,} lines -> {rows:,} moves ({errors} errors) in {seconds:.2f} s "
              f"({lines / seconds / 1000:.0f} k lines/s), best of 3; {_rs274(text)}")


if __name__ == "__main__":
    main()
