"""What the load benchmarks' big files share: how a copy of a drawing is placed and
how the lines of a file are counted (``bench_gcode``, ``arcfile``, ``tracedfile``)."""

from __future__ import annotations

import re
from pathlib import Path

AXIS = re.compile(r"([XY])(-?\d*\.?\d+)")  # the X/Y words a shifted copy moves
ENDS = re.compile(r"^\s*(%|M0?2\b|M30\b)", re.IGNORECASE)  # lines a copy drops (one end for all)


def far_offset(copy: int) -> float:
    """How far copy number ``copy`` moves in X and in Y (mm): one in ten stays where it
    is, the rest 200-680 mm away, far outside the 150 mm travel."""
    return 200.0 + 20.0 * (copy % 25) if copy % 10 else 0.0


def count_lines(path: Path) -> int:
    """The newlines of ``path``, read a megabyte at a time."""
    with path.open("rb") as f:
        return sum(block.count(b"\n") for block in iter(lambda: f.read(1 << 20), b""))
