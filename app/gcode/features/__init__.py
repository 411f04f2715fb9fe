"""Machining features (the CAPP paper's pockets, slots, islands, faces, hole patterns)
-> moves -> G-code text. Qt-free; everything made here goes through the one loader.

A feature is a frozen dataclass validated on construction (``FeatureError`` names
the field and the rule); ``toolpath(feature)`` gives its moves (``moves.Move``),
``program_moves(features, profile)`` several in order with tool changes, checked
against the travel; ``write_plain(moves)`` the plain G-code.
"""

from .contour import Contour, Segment, parse_contour, read_contour
from .cutting import Cutting
from .errors import FeatureError
from .generate import program_moves, toolpath
from .kinds import Face, Holes, PocketCircle, PocketRect, Profile, Slot, holes_circle, holes_row
from .moves import Move
from .plain import write_plain

__all__ = [
    "Contour", "Cutting", "Face", "FeatureError", "Holes", "Move", "PocketCircle", "PocketRect",
    "Profile", "Segment", "Slot", "holes_circle", "holes_row", "parse_contour", "program_moves",
    "read_contour", "toolpath", "write_plain",
]
