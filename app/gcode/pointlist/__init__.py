"""Point lists (plain ``x y z`` lines, the "Fabrication Task" format) -> G-code. No Qt.

``read_points(raw, name)`` -> ``PointList`` (or ``PointListError`` with the line and
what was expected); ``to_gcode(points, ImportOptions(...), profile)`` -> (text,
``Placement``); ``looks_like_points(raw)`` tells such a file from G-code by content.
The converter's names are imported on first use (PEP 562): the window's Open asks
``looks_like_points`` of every file, and the converter brings the features' modules.
"""

from .formats import PointList, PointListError, looks_like_points, read_points

_CONVERTER = ("ImportOptions", "Placement", "to_gcode")

__all__ = ["ImportOptions", "Placement", "PointList", "PointListError", "looks_like_points", "read_points",
           "to_gcode"]


def __getattr__(name: str):
    if name not in _CONVERTER:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from . import convert

    value = getattr(convert, name)
    globals()[name] = value  # found once
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *_CONVERTER])
