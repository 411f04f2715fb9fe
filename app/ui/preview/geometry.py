"""Drawable geometry of a toolpath: vertices in program order, arcs as chords (no Qt).

``PathGeometry.from_toolpath(toolpath, tolerance)`` turns the numpy arrays of
``app.gcode``'s ``Toolpath`` into one chain of XY(Z) vertices. Vertex ``i > 0`` ends a
segment that belongs to move ``move[i]`` and is drawn in ``group[i]``: group 0 is the
rapids, group 1 cuts at or above the stock top (Z >= 0), groups 2.. bands of cut
depth from the top of the stock down to the deepest cut.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.gcode.ops import RAPID

RAPID_GROUP = 0
AIR_GROUP = 1
DEPTH_BANDS = 5


@dataclass(frozen=True)
class PathGeometry:
    points: np.ndarray  # (m, 3) float64 vertices
    move: np.ndarray  # (m,) int64 move index of the segment ending at each vertex
    group: np.ndarray  # (m,) int8 drawing group of that segment
    depth_edges: np.ndarray  # band edges, top (0) to bottom (deepest cut)

    @classmethod
    def from_toolpath(cls, toolpath, tolerance: float = 0.01, threads: int = 2) -> PathGeometry:
        """Vertices from ``toolpath.polyline(tolerance)`` (arcs as chords, any plane)."""
        points, move = toolpath.polyline(tolerance, threads)
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        move = np.asarray(move, dtype=np.int64)
        if not len(points):
            return cls(points, move, np.zeros(0, np.int8), np.zeros(DEPTH_BANDS + 1))
        rapid = np.asarray(toolpath.kind)[move] == RAPID
        group, edges = depth_groups(points[:, 2], rapid)
        return cls(points, move, group, edges)

    @property
    def group_count(self) -> int:
        return 2 + DEPTH_BANDS

    def move_vertices(self, index: int) -> np.ndarray:
        """The vertices of one move (its start and chord points), for highlighting."""
        lo = int(np.searchsorted(self.move[1:], index, "left"))
        hi = int(np.searchsorted(self.move[1:], index, "right")) + 1
        return self.points[lo:hi]

    def vertex_of_move(self, index: int) -> int:
        """Index of the last vertex of move ``index`` (the tool position when it is done)."""
        at = int(np.searchsorted(self.move[1:], index, "right"))
        return min(at, len(self.points) - 1)


def depth_groups(z, rapid):
    """Group of each segment (by the Z of its end vertex) and the depth band edges."""
    cut_z = z[~rapid]
    deepest = float(cut_z.min()) if len(cut_z) else 0.0
    deepest = min(deepest, -1e-6)
    edges = np.linspace(0.0, deepest, DEPTH_BANDS + 1)
    band = np.clip(((z / deepest) * DEPTH_BANDS).astype(np.int64), 0, DEPTH_BANDS - 1)
    group = np.where(z >= -1e-9, 1, 2 + band).astype(np.int8)
    group[rapid] = RAPID_GROUP
    return group, edges
