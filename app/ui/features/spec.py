"""The fields of each feature kind's form and how their values become a feature.

A field is (name, label, unit, default, minimum, maximum, decimals); ``name`` is the
feature dataclass's field, so a ``FeatureError`` points at its widget. Labels are
marked for translation (context ``FeatureForm``). Defaults that depend on the machine
(feed, spindle speed) come from its profile.
"""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QT_TRANSLATE_NOOP

from app.gcode.features import (
    Cutting,
    Face,
    FeatureError,
    PocketCircle,
    PocketRect,
    Profile,
    Slot,
    holes_circle,
    holes_row,
    read_contour,
)
from app.gcode.features.ranges import RANGES
from app.i18n import msg
from app.profile import MachineProfile


@dataclass(frozen=True)
class Field:
    name: str
    label: str
    unit: str = "mm"
    default: float = 0.0
    low: float = -1000.0
    high: float = 1000.0
    decimals: int = 3


def _f(name, label, default=0.0, unit="mm", low=-1000.0, high=1000.0, decimals=3) -> Field:
    """A field, its limits kept within the core's range of the option (``ranges.RANGES``)."""
    if name in RANGES:
        least, most, _ = RANGES[name]
        low, high = max(low, least), min(high, most)
    return Field(name, label, unit, default, low, high, decimals)


X, Y = QT_TRANSLATE_NOOP("FeatureForm", "X"), QT_TRANSLATE_NOOP("FeatureForm", "Y")
KIND_TITLES = {
    "pocket-rect": QT_TRANSLATE_NOOP("FeatureForm", "Rectangular pocket"),
    "pocket-circle": QT_TRANSLATE_NOOP("FeatureForm", "Round pocket"),
    "slot": QT_TRANSLATE_NOOP("FeatureForm", "Slot"),
    "face": QT_TRANSLATE_NOOP("FeatureForm", "Face"),
    "profile": QT_TRANSLATE_NOOP("FeatureForm", "Profile (island or pocket from a contour)"),
    "holes-circle": QT_TRANSLATE_NOOP("FeatureForm", "Holes on a circle"),
    "holes-row": QT_TRANSLATE_NOOP("FeatureForm", "Holes in a row"),
}
_PECK = [_f("peck", QT_TRANSLATE_NOOP("FeatureForm", "Peck depth (0: none)"), 0.0, low=0),
         _f("dwell", QT_TRANSLATE_NOOP("FeatureForm", "Dwell at the bottom"), 0.0, "s", 0, 60)]
KIND_FIELDS: dict[str, list[Field]] = {
    "pocket-rect": [_f("x", QT_TRANSLATE_NOOP("FeatureForm", "X (lower left)"), 20),
                    _f("y", QT_TRANSLATE_NOOP("FeatureForm", "Y (lower left)"), 20),
                    _f("width", QT_TRANSLATE_NOOP("FeatureForm", "Width"), 40, low=0),
                    _f("height", QT_TRANSLATE_NOOP("FeatureForm", "Height"), 25, low=0),
                    _f("corner_radius", QT_TRANSLATE_NOOP("FeatureForm", "Corner radius"), 0, low=0),
                    _f("angle", QT_TRANSLATE_NOOP("FeatureForm", "Angle about X+"), 0, "°", -360, 360)],
    "pocket-circle": [_f("x", QT_TRANSLATE_NOOP("FeatureForm", "X (centre)"), 50),
                      _f("y", QT_TRANSLATE_NOOP("FeatureForm", "Y (centre)"), 50),
                      _f("diameter", QT_TRANSLATE_NOOP("FeatureForm", "Diameter"), 30, low=0)],
    "slot": [_f("x1", QT_TRANSLATE_NOOP("FeatureForm", "X start"), 20),
             _f("y1", QT_TRANSLATE_NOOP("FeatureForm", "Y start"), 20),
             _f("x2", QT_TRANSLATE_NOOP("FeatureForm", "X end"), 70),
             _f("y2", QT_TRANSLATE_NOOP("FeatureForm", "Y end"), 20),
             _f("width", QT_TRANSLATE_NOOP("FeatureForm", "Width"), 8, low=0)],
    "face": [_f("x", QT_TRANSLATE_NOOP("FeatureForm", "X (lower left)"), 10),
             _f("y", QT_TRANSLATE_NOOP("FeatureForm", "Y (lower left)"), 10),
             _f("width", QT_TRANSLATE_NOOP("FeatureForm", "Width"), 60, low=0),
             _f("height", QT_TRANSLATE_NOOP("FeatureForm", "Height"), 40, low=0)],
    "profile": [_f("stock", QT_TRANSLATE_NOOP("FeatureForm", "Stock around an island (M)"), 10, low=0)],
    "holes-circle": [_f("x", QT_TRANSLATE_NOOP("FeatureForm", "X (centre)"), 75),
                     _f("y", QT_TRANSLATE_NOOP("FeatureForm", "Y (centre)"), 75),
                     _f("diameter", QT_TRANSLATE_NOOP("FeatureForm", "Circle diameter"), 50, low=0),
                     _f("count", QT_TRANSLATE_NOOP("FeatureForm", "Holes"), 6, "", 0, 1000, 0),
                     _f("start_angle", QT_TRANSLATE_NOOP("FeatureForm", "Start angle"), 0, "°", -360, 360),
                     *_PECK],
    "holes-row": [_f("x", QT_TRANSLATE_NOOP("FeatureForm", "X (first hole)"), 20),
                  _f("y", QT_TRANSLATE_NOOP("FeatureForm", "Y (first hole)"), 20),
                  _f("count", QT_TRANSLATE_NOOP("FeatureForm", "Holes"), 5, "", 0, 1000, 0),
                  _f("pitch", QT_TRANSLATE_NOOP("FeatureForm", "Pitch"), 10, low=0),
                  _f("angle", QT_TRANSLATE_NOOP("FeatureForm", "Angle about X+"), 0, "°", -360, 360),
                  *_PECK],
}


def cutting_fields(profile: MachineProfile) -> list[Field]:
    """The technological parameters every kind shares, with the machine's defaults."""
    feed = min(300.0, profile.motion.max_feed_mm_min)
    return [
        _f("tool", QT_TRANSLATE_NOOP("FeatureForm", "Tool number"), 1, "", 0, 99, 0),
        _f("tool_diameter", QT_TRANSLATE_NOOP("FeatureForm", "Tool diameter (D)"), 6, low=0, high=50),
        _f("top", QT_TRANSLATE_NOOP("FeatureForm", "Stock top (Z)"), 0, low=-100, high=100),
        _f("depth", QT_TRANSLATE_NOOP("FeatureForm", "Depth below the top (H)"), 3, low=-100, high=100),
        _f("stepdown", QT_TRANSLATE_NOOP("FeatureForm", "Depth per layer (C)"), 1, low=0, high=50),
        _f("stepover", QT_TRANSLATE_NOOP("FeatureForm", "Stepover (B)"), 40, "%", 0, 200, 1),
        _f("finish_xy", QT_TRANSLATE_NOOP("FeatureForm", "Finishing allowance XY (U)"), 0.2, low=0, high=10),
        _f("finish_z", QT_TRANSLATE_NOOP("FeatureForm", "Finishing allowance Z (W)"), 0, low=0, high=10),
        _f("clearance", QT_TRANSLATE_NOOP("FeatureForm", "Clearance (R)"), 5, low=0, high=50),
        _f("feed", QT_TRANSLATE_NOOP("FeatureForm", "Feed (F)"), feed, "mm/min", 0,
           profile.motion.max_feed_mm_min, 0),
        _f("plunge_feed", QT_TRANSLATE_NOOP("FeatureForm", "Plunge feed"), min(100.0, feed), "mm/min", 0,
           profile.motion.max_feed_mm_min, 0),
        _f("rpm", QT_TRANSLATE_NOOP("FeatureForm", "Spindle speed (S)"), profile.max_spindle_rpm(), "rpm",
           0, profile.max_spindle_rpm(), 0),
    ]


def defaults(kind: str, profile: MachineProfile) -> dict:
    """The values of a new feature of ``kind``."""
    values = {f.name: f.default for f in KIND_FIELDS[kind] + cutting_fields(profile)}
    values["climb"] = True
    if kind == "profile":
        values.update(contour="", side="outside")
    return values


def _cutting(values: dict) -> Cutting:
    names = ("tool_diameter", "depth", "top", "stepdown", "stepover", "finish_xy", "finish_z", "clearance",
             "feed", "plunge_feed", "rpm")
    numbers = {n: float(values[n]) for n in names}
    return Cutting(tool=int(values["tool"]), climb=bool(values["climb"]), **numbers)


def build(kind: str, values: dict):
    """The feature ``values`` describe; raises ``FeatureError`` naming the field."""
    cut = _cutting(values)
    v = values
    if kind == "pocket-rect":
        return PocketRect(v["x"], v["y"], v["width"], v["height"], cut, v["corner_radius"], v["angle"])
    if kind == "pocket-circle":
        return PocketCircle(v["x"], v["y"], v["diameter"], cut)
    if kind == "slot":
        return Slot(v["x1"], v["y1"], v["x2"], v["y2"], v["width"], cut)
    if kind == "face":
        return Face(v["x"], v["y"], v["width"], v["height"], cut)
    if kind == "holes-circle":
        return holes_circle(v["x"], v["y"], v["diameter"], int(v["count"]), cut, v["start_angle"], v["peck"],
                            v["dwell"])
    if kind == "holes-row":
        return holes_row(v["x"], v["y"], int(v["count"]), v["pitch"], cut, v["angle"], v["peck"], v["dwell"])
    if not v["contour"]:
        raise FeatureError("contour", msg("choose a contour file (G00/G01/G02/G03 lines)"))
    return Profile(read_contour(v["contour"]), v["side"], cut, v["stock"])
