"""What the 3-D view draws of a program, apart from how it is drawn (no Qt).

``PathMesh.from_geometry(geometry)`` takes the 2-D preview's ``PathGeometry`` (one
chain of vertices in program order; vertex ``i > 0`` ends a segment of move
``move[i]`` drawn in group ``group[i]``) and keeps what a GPU needs: float32
positions and a uint8 group per vertex, 13 bytes per segment. The chain is drawn as
one line strip whose segment ``i`` takes the attributes of its last vertex, so the
vertex index is the segment index: the finished part of a job is every vertex up to
``vertex_of_move(move)``, compared in the shader with one number.

Level of detail: ``levels[k]`` keeps, for cells of ``cells[k]`` millimetres (the 2-D
view's ``LEVEL_STEPS`` from extent / 2048 on), the first segment of each (start cell,
end cell) pair in 3-D, as the 2-D view does in XY; depth passes over the same XY stay
apart since their cells differ in Z. A level is an index array of segment ends drawn
as pairs (``i - 1``, ``i``); each is built from the next finer one.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from app.ui.preview.lod import LEVEL_STEPS

POSITION_BYTES = 12  # float32 x, y, z
GROUP_BYTES = 1  # uint8
INDEX_BYTES = 8  # two uint32 per segment of a level
STEPS = [k for k in LEVEL_STEPS if k <= 11]  # finer cells than extent / 2048 keep almost every segment
_MIX = np.int64(0x2545F4914F6CDD1D >> 1)  # an odd multiplier that spreads the start cell


@dataclass(frozen=True)
class MeshLevel:
    cell: float  # mm
    ends: np.ndarray  # (k,) uint32 end vertex of each kept segment, ascending

    def pairs(self) -> np.ndarray:
        """(2k,) uint32 vertex indices drawn as lines: (end - 1, end) per segment."""
        out = np.empty((len(self.ends), 2), np.uint32)
        out[:, 0] = self.ends - 1
        out[:, 1] = self.ends
        return out.ravel()


@dataclass
class PathMesh:
    points: np.ndarray  # (m, 3) float32
    group: np.ndarray  # (m,) uint8
    move: np.ndarray  # (m,) int64 (kept on the CPU: move -> vertex)
    levels: list[MeshLevel] = field(default_factory=list)  # finest first

    @classmethod
    def from_geometry(cls, geometry) -> PathMesh:
        points = np.ascontiguousarray(geometry.points, dtype=np.float32).reshape(-1, 3)
        group = np.ascontiguousarray(geometry.group, dtype=np.uint8)
        return cls(points, group, np.asarray(geometry.move))

    @property
    def segments(self) -> int:
        return max(len(self.points) - 1, 0)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(min xyz, max xyz) of every vertex; zeros when empty."""
        if not len(self.points):
            return np.zeros(3), np.zeros(3)
        cols = [self.points[:, k] for k in range(3)]  # a column at a time (see preview.model)
        return np.array([c.min() for c in cols], float), np.array([c.max() for c in cols], float)

    def vertex_of_move(self, move: int) -> int:
        """The last vertex of moves up to ``move`` (-1: nothing done)."""
        if move < 0 or not len(self.points):
            return -1
        return min(int(np.searchsorted(self.move[1:], move, "right")), len(self.points) - 1)

    def bytes_per_segment(self) -> float:
        """GPU bytes of the full model per segment (positions and groups)."""
        return len(self.points) * (POSITION_BYTES + GROUP_BYTES) / max(self.segments, 1)

    def level_bytes_per_segment(self) -> float:
        """GPU bytes of every level's index buffer per segment of the model."""
        return sum(len(level.ends) for level in self.levels) * INDEX_BYTES / max(self.segments, 1)

    def cells(self) -> list[float]:
        low, high = self.bounds()
        extent = max(float(np.max(high - low)), 1e-6)
        return [extent / 2**k for k in STEPS]

    def build_levels(self) -> None:
        """Every level, finest first, each from the one before (cells nest)."""
        if self.segments == 0:
            self.levels = []
            return
        low, high = self.bounds()
        origin, span = low.astype(np.float32), float(np.max(high - low))
        ends = np.arange(1, len(self.points), dtype=np.uint32)
        levels = []
        for cell in self.cells():
            ends = _representatives(self.points, origin, span, ends, cell)
            levels.append(MeshLevel(cell, ends))
        self.levels = levels

    def pick_level(self, pixel: float, budget: int) -> MeshLevel | None:
        """The coarsest level whose cell is no larger than ``pixel`` (the finest when none
        is), or a coarser one until its segments fit ``budget`` (at last the coarsest);
        ``None`` when the levels are not built."""
        if not self.levels:
            return None
        fine = [i for i, level in enumerate(self.levels) if level.cell <= pixel]
        for level in self.levels[fine[-1] if fine else 0:]:
            if len(level.ends) <= budget:
                return level
        return self.levels[-1]

def _representatives(points, origin, span, ends, cell) -> np.ndarray:
    """The ends (ascending: program order) of the first segment of every 3-D (start
    cell, end cell) pair among the segments ending at ``ends``. The pair is hashed to
    one int64 (wrapping; two pairs of a level collide with odds of about n**2 / 2**64)."""
    side = int(span / cell) + 2  # cells along the longest axis, and one to spare
    key = np.zeros(len(ends), np.int64)
    for vertex in (ends - 1, ends):
        q = ((np.take(points, vertex, axis=0) - origin) / np.float32(cell)).astype(np.int64)  # (a take
        key = key * _MIX + (q[:, 0] * side + q[:, 1]) * side + q[:, 2]  # lets the GIL go, indexing not)
    order = np.argsort(key, kind="stable")  # (its GIL holds are the shortest; np.unique's are long)
    ordered = np.take(key, order)
    runs = np.flatnonzero(np.concatenate([[True], ordered[1:] != ordered[:-1]]))
    return np.take(ends, np.sort(np.minimum.reduceat(order, runs)))
