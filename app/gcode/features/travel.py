"""A feature's moves against the machine's travel, worded as ``checks.py`` words it."""

from __future__ import annotations

import math

import numpy as np

from app.i18n import N_, msg
from app.profile import MachineProfile

from .contour import sweep_angle
from .cutting import Cutting
from .errors import FeatureError
from .moves import ARC, Move

FIELDS = {("X", "+"): "x", ("X", "-"): "x", ("Y", "+"): "y", ("Y", "-"): "y",
          ("Z", "+"): "clearance", ("Z", "-"): "depth"}


_BEYOND = N_("{axis}{sign} beyond travel ({value:.3f} {rel} {limit:g})")

def limits(profile: MachineProfile) -> np.ndarray:
    """(3, 2) travel limits in work coordinates (the default work offset applied)."""
    offset = np.array(profile.travel.work_offset())
    return np.array(profile.travel.limits()) - offset[:, None]


def _arc_reach(start, m: Move) -> list[tuple[float, float]]:
    """The points of an arc's circle at 0, 90, 180 and 270 degrees that the arc passes."""
    cx, cy = m.center
    r = math.hypot(m.end[0] - cx, m.end[1] - cy)
    sweep = sweep_angle(start[:2], m.end[:2], m.center, m.cw)
    a0 = math.atan2(start[1] - cy, start[0] - cx)
    out = []
    for k in range(4):
        quarter = k * math.pi / 2
        along = (quarter - a0) % (2 * math.pi) if sweep > 0 else (a0 - quarter) % (2 * math.pi)
        if along <= abs(sweep):
            out.append((cx + r * math.cos(quarter), cy + r * math.sin(quarter)))
    return out


def extent(moves: list[Move]) -> tuple[np.ndarray, np.ndarray]:
    """(min xyz, max xyz) of the tool centre over ``moves`` (arcs by the extreme points
    they pass; an arc with no known start by its full circle: a safe over-estimate)."""
    ends = np.array([m.end for m in moves], float)
    low, high = ends.min(axis=0), ends.max(axis=0)
    start = None
    for m in moves:
        if m.kind == ARC and m.center is not None:
            r = float(np.hypot(m.end[0] - m.center[0], m.end[1] - m.center[1]))
            reach = _arc_reach(start, m) if start is not None else [
                (m.center[0] - r, m.center[1] - r), (m.center[0] + r, m.center[1] + r)]
            for p in reach:
                low[:2] = np.minimum(low[:2], p)
                high[:2] = np.maximum(high[:2], p)
        start = m.end
    return low, high


def check_travel(moves: list[Move], cut: Cutting, profile: MachineProfile) -> None:
    """Raise ``FeatureError`` for the first axis and direction the tool would pass."""
    if not moves:
        return
    low, high = extent(moves)
    for axis, (lo, hi) in enumerate(limits(profile).tolist()):
        name = "XYZ"[axis]
        if high[axis] > hi + 1e-6:
            raise FeatureError(FIELDS[(name, "+")], msg(_BEYOND, axis=name, sign="+", value=float(high[axis]),
                                                        rel=">", limit=float(hi)))
        if low[axis] < lo - 1e-6:
            raise FeatureError(FIELDS[(name, "-")], msg(_BEYOND, axis=name, sign="-", value=float(low[axis]),
                                                        rel="<", limit=float(lo)))

