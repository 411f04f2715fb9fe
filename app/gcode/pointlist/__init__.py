"""Point lists (plain ``x y z`` lines, the "Fabrication Task" format) -> G-code. No Qt.

``read_points(raw, name)`` -> ``PointList`` (or ``PointListError`` with the line and
what was expected); ``to_gcode(points, ImportOptions(...), profile)`` -> (text,
``Placement``); ``looks_like_points(raw)`` tells such a file from G-code by content.
"""

from .convert import ImportOptions, Placement, to_gcode
from .formats import PointList, PointListError, looks_like_points, read_points

__all__ = ["ImportOptions", "Placement", "PointList", "PointListError", "looks_like_points", "read_points",
           "to_gcode"]
