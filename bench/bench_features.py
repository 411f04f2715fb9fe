"""Feature programs, plain and parametric (issue 19): for each kind, the moves, the lines
of the plain program and of the Fanuc 31 macro program, the time to generate them and
to load each back (the macro through the expander); prints figures, never asserts them.

Run: ``.venv/bin/python -m bench bench_features``.
"""

from __future__ import annotations

import os
import time

from app.gcode import load_text
from app.gcode.features import (
    Cutting,
    Face,
    PocketCircle,
    PocketRect,
    Slot,
    holes_circle,
    program_moves,
    write_plain,
)
from app.gcode.features.fanuc import write_fanuc


def _timed(fn, *args):
    started = time.perf_counter()
    result = fn(*args)
    return result, time.perf_counter() - started


def main() -> None:
    print(f"load average {' '.join(f'{v:.2f}' for v in os.getloadavg())}")
    cut = Cutting(tool_diameter=3, depth=6, stepdown=0.5, stepover=40, finish_xy=0.2, finish_z=0.1)
    features = [PocketRect(20, 20, 90, 60, cut, corner_radius=6, angle=10), PocketCircle(75, 75, 120, cut),
                Slot(20, 20, 120, 90, 14, cut), Face(10, 10, 120, 100, cut),
                holes_circle(75, 75, 100, 24, Cutting(tool_diameter=3, depth=20), peck=0.5)]
    for feature in features:
        moves, generate = _timed(program_moves, [feature])
        plain, macro = write_plain(moves), write_fanuc(moves, "fanuc31")
        _, plain_load = _timed(load_text, plain)
        loaded, macro_load = _timed(load_text, macro)
        print(f"{feature.kind:14} {len(moves):7,} moves in {generate:.2f} s; plain {plain.count(chr(10)):7,} "
              f"lines, loaded in {plain_load:.2f} s; Fanuc 31 {macro.count(chr(10)):4,} lines, expanded "
              f"in {macro_load:.2f} s to {len(loaded.moves):,} moves")


if __name__ == "__main__":
    main()
