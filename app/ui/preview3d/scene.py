"""The 3-D view's small things, as coloured line vertices (no Qt).

Each function returns (n, 6) float32 rows x, y, z, r, g, b drawn as line pairs: the
machine's travel volume as a box, the work zero as three axes (X red, Y green, Z
blue), the tool as a circle of its diameter at its tip with a stub of shank, and a
cross that marks a place. ``program_tool(lines)`` finds the tool a program asks for
(its first T word), ``tool_diameter`` looks it up in the tool table.
"""

from __future__ import annotations

import itertools
import re

import numpy as np

TRAVEL_RGB = (0.5, 0.5, 0.5)
AXIS_RGB = ((1.0, 0.3, 0.3), (0.3, 0.9, 0.3), (0.35, 0.55, 1.0))
TOOL_RGB = (1.0, 0.25, 0.25)
MARK_RGB = (1.0, 1.0, 1.0)
DEFAULT_DIAMETER = 3.0  # mm, when the tool table does not say
CIRCLE_STEPS = 32
SCAN_LINES = 5_000  # lines of a program looked at for its tool
_T_WORD = re.compile(r"(?<![A-Z#])T\s*(\d+)")
_COMMENT = re.compile(r"\([^)]*\)|;.*")


def _pairs(points: np.ndarray, rgb) -> np.ndarray:
    rows = np.empty((len(points), 6), np.float32)
    rows[:, :3] = points
    rows[:, 3:] = rgb
    return rows


def box_lines(low, high, rgb=TRAVEL_RGB) -> np.ndarray:
    """The 12 edges of the box ``low``..``high``."""
    lo, hi = np.asarray(low, float), np.asarray(high, float)
    corner = [np.where([i & 1, i & 2, i & 4], hi, lo) for i in range(8)]
    edges = [(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1]
    return _pairs(np.array([corner[i] for edge in edges for i in edge]), rgb)


def axes_lines(length: float) -> np.ndarray:
    """X, Y and Z from the work zero, ``length`` mm each."""
    rows = [_pairs(np.array([[0.0, 0.0, 0.0], np.eye(3)[k] * length]), AXIS_RGB[k]) for k in range(3)]
    return np.concatenate(rows)


def tool_lines(tip, diameter: float, shank: float = 10.0) -> np.ndarray:
    """A circle of ``diameter`` around the tool's tip in XY and a shank line upwards."""
    tip = np.asarray(tip, float)
    angle = np.linspace(0.0, 2 * np.pi, CIRCLE_STEPS + 1)
    ring = tip + np.column_stack([np.cos(angle), np.sin(angle), np.zeros_like(angle)]) * diameter / 2
    pairs = np.repeat(ring, 2, axis=0)[1:-1]
    shank_line = np.array([tip, tip + [0.0, 0.0, shank]])
    return _pairs(np.concatenate([pairs, shank_line]), TOOL_RGB)


def mark_lines(point, size: float) -> np.ndarray:
    """A three-axis cross of ``size`` mm centred on ``point``."""
    p = np.asarray(point, float)
    ends = [p + sign * np.eye(3)[k] * size / 2 for k in range(3) for sign in (-1, 1)]
    return _pairs(np.array(ends), MARK_RGB)


def program_tool(lines, limit: int = SCAN_LINES) -> int | None:
    """The number of the first T word in the first ``limit`` lines (comments skipped).
    ``lines``: any sequence; only those lines are read (a program's ``Lines`` then
    decodes those alone rather than split the whole file)."""
    for line in itertools.islice(lines, limit):
        found = _T_WORD.search(_COMMENT.sub("", line).upper())
        if found:
            return int(found.group(1))
    return None


def tool_diameter(tools: dict, number: int | None) -> tuple[float, int | None]:
    """(diameter, tool number) of the program's tool; else of the table's first tool;
    else ``DEFAULT_DIAMETER`` and ``None``."""
    if number in tools:
        return float(tools[number].diameter) or DEFAULT_DIAMETER, number
    if tools:
        first = min(tools)
        return float(tools[first].diameter) or DEFAULT_DIAMETER, first
    return DEFAULT_DIAMETER, None
