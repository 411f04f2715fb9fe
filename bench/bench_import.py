"""Point-list import: a 1,000,000-point file (plain and Fabrication Task) read and turned
into G-code, and a feature program generated; prints times (never asserts them).

Run: ``.venv/bin/python -m bench bench_import``.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

import numpy as np

from app.gcode import load_text
from app.gcode.features import Cutting, PocketCircle, Profile, parse_contour, program_moves, write_plain
from app.gcode.pointlist import ImportOptions, read_points, to_gcode

POINTS = 1_000_000
PATHS = 326  # as many paths as the engraver's sample file


def _plain(points: np.ndarray, paths: int) -> bytes:
    blocks = np.array_split(points, paths)
    return b"\n".join(b"\n".join(b"%.6f %.6f %.6f" % tuple(p) for p in block) + b"\n" for block in blocks)


def _fabrication(points: np.ndarray, paths: int) -> bytes:
    head = (b"===== Fabrication Task =====\nFormat Version : 01\n== General Information ==\n"
            b"Voxel Distance : 0.700000\nFlag of 'Start from Top' : 1\n== Scan Path Information ==\n"
            b"Number of Total Paths : %d\n" % paths)
    parts = [head]
    for k, block in enumerate(np.array_split(points, paths)):
        parts.append(b"Path Number : %d\nNumber of Total Points : %d\n" % (k, len(block)))
        parts.append(b"".join(b"%.6f %.6f %.6f\n" % tuple(p) for p in block))
    return b"".join(parts)


def _time_import(path: Path) -> None:
    started = time.perf_counter()
    points = read_points(path.read_bytes(), path.name)
    read = time.perf_counter() - started
    text, placement = to_gcode(points, ImportOptions(fit=True, cut_z=-0.2))
    total = time.perf_counter() - started
    print(f"{path.name}: {points.point_count:,} points in {len(points.paths)} paths, "
          f"{path.stat().st_size / 1e6:.1f} MB: read {read:.2f} s, read + G-code {total:.2f} s "
          f"({len(text) / 1e6:.1f} MB of G-code, scale {placement.scale:.4g})")
    started = time.perf_counter()
    program = load_text(text, path.name)
    print(f"  loading that G-code: {time.perf_counter() - started:.2f} s, {len(program.toolpath):,} moves, "
          f"{len(program.errors)} errors")


def _time_features() -> None:
    cut = Cutting(tool_diameter=6, depth=5, stepdown=1, finish_xy=0.3)
    paper = "G00 X40 Y40\nG01 X35 Y55\nG02 X45 Y65 R10\nG03 X70 Y65 R30\nG02 X80 Y55 R10\n" \
            "G01 Y50\nG01 X75 Y40\nG01 X60 Y37\nG01 X40 Y40\n"
    for feature in (PocketCircle(75, 75, 100, cut), Profile(parse_contour(paper), "outside", cut, 15)):
        started = time.perf_counter()
        text = write_plain(program_moves([feature]))
        took = time.perf_counter() - started
        print(f"feature {feature.kind}: {text.count(chr(10)):,} lines in {took:.2f} s")


def main() -> None:
    rng = np.random.default_rng(7)
    points = np.cumsum(rng.normal(0, 0.3, (POINTS, 3)), axis=0)
    with tempfile.TemporaryDirectory() as folder:
        plain, fab = Path(folder) / "points.xyz", Path(folder) / "task.txt"
        plain.write_bytes(_plain(points, PATHS))
        fab.write_bytes(_fabrication(points, PATHS))
        for path in (plain, fab):
            _time_import(path)
    _time_features()


if __name__ == "__main__":
    main()
