"""What the 3-D view draws of a program, apart from how it is drawn (no Qt).

``PathMesh.from_geometry(geometry)`` takes the 2-D preview's ``PathGeometry`` (one
chain of vertices in program order; vertex ``i > 0`` ends a segment of move
``move[i]`` drawn in group ``group[i]``) and keeps what a GPU needs: float32
positions and a uint8 group per vertex, 13 bytes per segment. The chain is drawn as
one line strip whose segment ``i`` takes the attributes of its last vertex, so the
vertex index is the segment index: the finished part of a job is every vertex up to
``vertex_of_move(move)``, compared in the shader with one number.

Levels of detail: ``levels[k]`` is the path as seen with cells of ``cells[k]``
millimetres (extent / 2**k for k in STEPS). The chain of vertices is simplified first:
of a run of consecutive vertices in one 3-D cell only the first stays (and the last
vertex of a run of one group, so a kept span never mixes colours); then, of the spans
that start and end in the same two cells in the same group, only the last in program
order stays (the one a full draw shows on top, done or not, since later lines win at
equal depth). Every vertex of the path is within a cell's diagonal of what a level
draws, so a level whose cell is a small fraction of a pixel looks like the full path
(``pick_full``), and a coarser one is drawn while the camera moves (``pick_level``).
A level is kept spans (start vertex, end vertex), ends ascending, drawn as line pairs
whose colour and progress are the end vertex's. Each level is built from the finer
one's spans (cells nest; a path of a million repeated segments costs one full pass);
a level that keeps more than USEFUL of the path is not made.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from app.ui.preview3d.chunks import span_boxes, strip_boxes

POSITION_BYTES = 12  # float32 x, y, z
GROUP_BYTES = 1  # uint8
INDEX_BYTES = 8  # two uint32 per span of a level
STEPS = range(15, 5, -1)  # cells of extent / 2**k, finest first
USEFUL = 0.6  # a level keeping more than this share of the segments is not made (not worth its memory)
_MIX = np.int64(0x2545F4914F6CDD1D >> 1)  # an odd multiplier that spreads the start cell


@dataclass(frozen=True)
class MeshLevel:
    cell: float  # mm
    starts: np.ndarray  # (k,) uint32 first vertex of each kept span
    ends: np.ndarray  # (k,) uint32 its last vertex, ascending
    boxes: np.ndarray  # (chunks, 2, 3) of its spans (chunks.span_boxes)

    def pairs(self) -> np.ndarray:
        """(2k,) uint32 vertex indices drawn as lines: (start, end) per span."""
        out = np.empty((len(self.ends), 2), np.uint32)
        out[:, 0] = self.starts
        out[:, 1] = self.ends
        return out.ravel()

    def spans_done(self, vertex: int) -> int:
        """How many spans end at or before ``vertex`` (the finished ones: a prefix)."""
        return int(np.searchsorted(self.ends, vertex, "right")) if vertex >= 0 else 0


@dataclass
class PathMesh:
    points: np.ndarray  # (m, 3) float32
    group: np.ndarray  # (m,) uint8
    move: np.ndarray  # (m,) int64 (kept on the CPU: move -> vertex)
    levels: list[MeshLevel] = field(default_factory=list)  # finest first
    boxes: np.ndarray | None = None  # (chunks, 2, 3) of the strip (chunks.strip_boxes), with the levels

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
        """The strip's chunk boxes and every useful level, finest first, each from the
        finer one's spans."""
        self.boxes = strip_boxes(self.points)
        if self.segments == 0:
            self.levels = []
            return
        low, _ = self.bounds()
        origin = low.astype(np.float32)
        chain = np.arange(len(self.points), dtype=np.uint32)
        begins = np.zeros(len(chain), bool)  # where a run of the chain begins (none joins the one before)
        begins[0] = True
        levels = []
        for cell in self.cells():
            cells = _cell_keys(self.points, origin, chain, cell)
            chain, cells, begins = _simplified(chain, cells, self.group, begins)
            starts, ends = _last_of_each_span(chain, cells, self.group, begins)
            if len(ends) <= USEFUL * self.segments:
                levels.append(MeshLevel(cell, starts, ends, span_boxes(self.points, starts, ends)))
            chain, begins = _chain_of(starts, ends)  # the next level from this one's spans
        self.levels = levels

    def pick_level(self, pixel: float, budget: int) -> MeshLevel | None:
        """The coarsest level whose cell is no larger than ``pixel`` (the finest when none
        is), or a coarser one until its spans fit ``budget`` (at last the coarsest);
        ``None`` when the levels are not built."""
        if not self.levels:
            return None
        fine = [i for i, level in enumerate(self.levels) if level.cell <= pixel]
        for level in self.levels[fine[-1] if fine else 0:]:
            if len(level.ends) <= budget:
                return level
        return self.levels[-1]

    def pick_full(self, pixel: float, fraction: float) -> MeshLevel | None:
        """The coarsest level whose cell is at most ``fraction`` of ``pixel`` (its picture is
        the full path's, to the pixel); ``None``: none is, draw every segment."""
        fine = [level for level in self.levels if level.cell <= pixel * fraction]
        return fine[-1] if fine else None


def _cell_keys(points, origin, chain, cell) -> np.ndarray:
    """One int64 per vertex of ``chain``: the 3-D cell it lies in."""
    q = ((np.take(points, chain, axis=0) - origin) / np.float32(cell)).astype(np.int64)  # (a take lets
    side = np.int64(q.max() + 2)  # the GIL go, indexing does not)
    return (q[:, 0] * side + q[:, 1]) * side + q[:, 2]


def _simplified(chain, cells, group, begins) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Of each run of ``chain`` in one cell its first vertex, of each run of one group
    its last, and the ends of the chain's runs: (vertices, their cells, run begins)."""
    g = np.take(group, chain)
    keep = np.ones(len(chain), bool)
    keep[1:-1] = (cells[1:-1] != cells[:-2]) | (g[1:-1] != g[2:]) | begins[1:-1] | begins[2:]
    return chain[keep], cells[keep], begins[keep]


def _last_of_each_span(chain, cells, group, begins) -> tuple[np.ndarray, np.ndarray]:
    """The spans (chain[i - 1], chain[i]) within runs, of those with the same start cell,
    end cell and group only the last; in program order. The three are hashed to one
    int64 (wrapping; two spans of a level collide with odds of about n**2 / 2**64)."""
    inner = np.flatnonzero(~begins[1:]) + 1  # the vertices that end a span
    ends = np.take(chain, inner)
    key = np.take(cells, inner - 1) * _MIX + np.take(cells, inner)
    key = key * _MIX + np.take(group, ends).astype(np.int64)
    order = np.argsort(key, kind="stable")  # (its GIL holds are the shortest; np.unique's are long)
    ordered = np.take(key, order)
    runs = np.flatnonzero(np.concatenate([[True], ordered[1:] != ordered[:-1]]))
    kept = np.take(inner, np.sort(np.maximum.reduceat(order, runs)))
    return np.take(chain, kept - 1), np.take(chain, kept)


def _chain_of(starts, ends) -> tuple[np.ndarray, np.ndarray]:
    """Spans in program order as one vertex list: a span that does not start where the
    one before ended begins a new run. (vertices, run begins)."""
    joined = np.zeros(len(ends), bool)
    joined[1:] = starts[1:] == ends[:-1]
    counts = 2 - joined.astype(np.int64)
    at = np.cumsum(counts) - counts
    chain = np.empty(int(counts.sum()), np.uint32)
    begins = np.zeros(len(chain), bool)
    fresh = np.flatnonzero(~joined)
    chain[at[fresh]] = starts[fresh]
    begins[at[fresh]] = True
    chain[at + counts - 1] = ends
    return chain, begins
