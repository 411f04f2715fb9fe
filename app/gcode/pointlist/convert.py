"""A point list -> G-code: each path retracts to the clearance height, rapids over its
first point, feeds down to its Z (or the cut Z), feeds through every point, retracts.

``fit`` scales X and Y uniformly (keeping the aspect) to the machine's travel less a
margin and centres them there; ``scale`` multiplies (after fitting); the ``Placement``
says the scale and offset used (machine = file * scale + offset, X and Y).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.i18n import msg
from app.profile import MachineProfile

from ..features.ranges import COORD, within
from .formats import PointList, PointListError
from .gcode import comment, feed_lines

MARGIN = 5.0  # mm kept free at the travel's edges by fit
DEFAULT_RPM = MachineProfile().max_spindle_rpm()  # what the default machine's spindle reaches


@dataclass(frozen=True)
class ImportOptions:
    """How to place and cut a point list (mm, mm/min; ``cut_z`` None: the file's Z)."""

    fit: bool = False
    scale: float = 1.0
    cut_z: float | None = None
    feed: float = 300.0
    clearance: float = 5.0
    rpm: float = DEFAULT_RPM

    def __post_init__(self) -> None:
        """Every option a number in its range (``features.ranges``): ``FeatureError``."""
        for name in ("scale", "feed", "clearance", "rpm") + (() if self.cut_z is None else ("cut_z",)):
            within(getattr(self, name), name)


@dataclass(frozen=True)
class Placement:
    """Scale and XY offset applied, and the X Y Z bounds of the result."""

    scale: float
    offset: tuple[float, float]
    low: tuple[float, float, float]
    high: tuple[float, float, float]

    def describe(self, points: PointList, options: ImportOptions) -> str:
        z = "the file's Z" if options.cut_z is None else f"cut Z {options.cut_z:g}"
        return (f"{points.name}: {len(points.paths)} paths, {points.point_count} points ({points.format}); "
                f"scale {self.scale:.6g}, offset X {self.offset[0]:+.3f} Y {self.offset[1]:+.3f}; {z}; "
                f"X {self.low[0]:.3f}..{self.high[0]:.3f} Y {self.low[1]:.3f}..{self.high[1]:.3f} "
                f"Z {self.low[2]:.3f}..{self.high[2]:.3f}")


def _work_travel(profile: MachineProfile) -> np.ndarray:
    offset = np.array(profile.travel.work_offset())
    return np.array(profile.travel.limits()) - offset[:, None]


def place(points: PointList, options: ImportOptions, profile: MachineProfile) -> Placement:
    """The scale and offset that ``options`` ask for."""
    if not options.scale > 0:
        raise PointListError(points.name, 0, 0, msg("the scale must be > 0 (got {scale:g})",
                                                    scale=float(options.scale)))
    low = np.min([p.min(axis=0) for p in points.paths], axis=0)
    high = np.max([p.max(axis=0) for p in points.paths], axis=0)
    scale, offset = options.scale, np.zeros(2)
    if options.fit:
        travel = _work_travel(profile)[:2]
        room = travel[:, 1] - travel[:, 0] - 2 * MARGIN
        size = np.maximum(high[:2] - low[:2], 1e-12)
        scale *= float(np.min(room / size))
        centre_file = (low[:2] + high[:2]) / 2
        offset = travel.mean(axis=1) - centre_file * scale
    z = (low[2], high[2]) if options.cut_z is None else (options.cut_z, options.cut_z)
    lo, hi = low[:2] * scale + offset, high[:2] * scale + offset
    for axis, value in zip("XYZXYZ", [*lo, z[0], *hi, z[1]], strict=True):
        if not abs(value) <= COORD:
            raise PointListError(points.name, 0, 0, msg(
                "the points reach {axis} {value:.6g}, beyond {limit:g} mm: a smaller scale, --fit or a cut Z",
                axis=axis, value=float(value), limit=COORD))
    return Placement(scale, (float(offset[0]), float(offset[1])), (lo[0], lo[1], z[0]), (hi[0], hi[1], z[1]))


def _path_gcode(path: np.ndarray, options: ImportOptions, p: Placement, number: int) -> str:
    xy = path[:, :2] * p.scale + np.array(p.offset)
    z = np.full(len(path), options.cut_z) if options.cut_z is not None else path[:, 2]
    clear = f"G00 Z{options.clearance:.3f}\n"
    head = (f"(path {number}: {len(path)} points)\n{clear}G00 X{xy[0, 0]:.3f} Y{xy[0, 1]:.3f}\n"
            f"G01 Z{z[0]:.3f} F{options.feed:g}\n")
    flat = bool((z == z[0]).all())
    body = np.column_stack([xy, z])[1:]
    return head + feed_lines(body[:, :2] if flat else body, "XY" if flat else "XYZ") + clear


def to_gcode(points: PointList, options: ImportOptions, profile: MachineProfile | None = None
             ) -> tuple[str, Placement]:
    """The program text and the placement used; raises ``PointListError`` when a point
    would be cut above the clearance height."""
    placement = place(points, options, profile or MachineProfile())
    if placement.high[2] >= options.clearance:
        said = msg("points reach Z {z:g}, at or above the clearance height {clearance:g}: give a cut Z or a "
                   "higher clearance", z=float(placement.high[2]), clearance=float(options.clearance))
        raise PointListError(points.name, 0, 0, said)


    parts = [comment(placement.describe(points, options)), "G21 G90 G17\n", f"M03 S{options.rpm:g}\n"]
    parts += [_path_gcode(path, options, placement, k) for k, path in enumerate(points.paths)]
    parts.append("M05\nM30\n")
    return "".join(parts), placement
