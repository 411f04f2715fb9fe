"""The technological parameters every feature shares (the paper's section 4.1).

Lengths in millimetres, feeds in mm/min, ``stepover`` in percent of the tool
diameter. ``top`` is the stock top (work Z), ``depth`` the total depth below it; the
floor is ``top - depth``. ``finish_xy`` (U) and ``finish_z`` (W) are left by roughing
and taken by the finishing passes. ``clearance`` (R) is the safe height above
``top`` and the radius of the finishing lead-in/out arcs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.i18n import msg
from app.profile import MachineProfile

from .errors import require
from .ranges import whole, within

DEFAULT_RPM = MachineProfile().max_spindle_rpm()  # what the default machine's spindle reaches

@dataclass(frozen=True)
class Cutting:
    """Tool, depths and feeds of one feature, validated on construction."""

    tool_diameter: float
    depth: float
    tool: int = 1
    top: float = 0.0
    stepdown: float = 1.0
    stepover: float = 40.0
    finish_xy: float = 0.0
    finish_z: float = 0.0
    clearance: float = 5.0
    feed: float = 300.0
    plunge_feed: float = 100.0
    rpm: float = DEFAULT_RPM
    climb: bool = True

    def __post_init__(self) -> None:
        for name in ("tool_diameter", "depth", "top", "stepdown", "stepover", "finish_xy", "finish_z",
                     "clearance", "feed", "plunge_feed", "rpm"):
            within(getattr(self, name), name)
        whole(self.tool, "tool")
        require(self.finish_z < self.depth, "finish_z",
                msg("must be less than the depth {depth:g} (got {finish_z:g})", depth=float(self.depth),
                    finish_z=float(self.finish_z)))
        require(self.finish_xy <= self.tool_diameter / 2, "finish_xy",
                msg("must be at most the tool's radius {radius:g} (got {finish_xy:g}): the finishing pass "
                    "takes what roughing leaves", radius=float(self.tool_diameter / 2),
                    finish_xy=float(self.finish_xy)))
        require(self.finish_z <= self.stepdown, "finish_z",
                msg("must be at most the stepdown {stepdown:g} (got {finish_z:g}): the floor pass "
                    "takes what roughing leaves", stepdown=float(self.stepdown),
                    finish_z=float(self.finish_z)))

    @property
    def radius(self) -> float:
        return self.tool_diameter / 2.0

    @property
    def step(self) -> float:
        """Stepover in millimetres."""
        return self.tool_diameter * self.stepover / 100.0

    @property
    def floor(self) -> float:
        return self.top - self.depth

    @property
    def safe_z(self) -> float:
        return self.top + self.clearance

    def layers(self, bottom: float) -> list[float]:
        """Depth levels from ``top`` down to ``bottom``: equal steps of at most
        ``stepdown``, the last exactly ``bottom``."""
        span = self.top - bottom
        if span <= 1e-9:
            return []
        count = max(1, math.ceil(span / self.stepdown - 1e-9))
        return [self.top - span * k / count for k in range(1, count)] + [bottom]
