"""Frustum culling: which parts of the path a camera sees (no Qt).

The path's units (the strip's segments, a level's spans) are cut in chunks of CHUNK
units in program order, each with the box of the vertices it draws (``strip_boxes``,
``span_boxes``: (k, 2, 3) low and high corners). ``visible_runs`` projects each box's
corners and keeps the chunks that reach into the view, merged into runs of units
``(first, last)``: a strip's run draws segments first+1..last, a level's spans
first..last-1, as ``fullframe.FullSource`` counts them. Zoomed in on a corner of a
big program, full detail draws the part on screen only.
"""

from __future__ import annotations

import numpy as np

CHUNK = 1024  # units per chunk (2,000 boxes for 2 M segments: a few ms to test)
_CORNERS = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], bool)


def strip_boxes(points: np.ndarray, chunk: int = CHUNK) -> np.ndarray:
    """Chunk c: the segments ending at vertices c*chunk+1..(c+1)*chunk (so its vertices
    c*chunk..(c+1)*chunk, both ends)."""
    if len(points) < 2:
        return np.zeros((0, 2, 3), np.float32)
    starts = np.arange(0, len(points) - 1, chunk)
    following = np.minimum(starts + chunk, len(points) - 1)
    low = np.minimum(np.minimum.reduceat(points, starts, axis=0), points[following])
    high = np.maximum(np.maximum.reduceat(points, starts, axis=0), points[following])
    return np.stack([low, high], axis=1)


def span_boxes(points: np.ndarray, starts: np.ndarray, ends: np.ndarray, chunk: int = CHUNK) -> np.ndarray:
    """Chunk c: spans c*chunk..(c+1)*chunk-1 (each from vertex ``starts`` to ``ends``)."""
    if not len(ends):
        return np.zeros((0, 2, 3), np.float32)
    first = np.arange(0, len(ends), chunk)
    a, b = np.take(points, starts, axis=0), np.take(points, ends, axis=0)
    low = np.minimum(np.minimum.reduceat(a, first, axis=0), np.minimum.reduceat(b, first, axis=0))
    high = np.maximum(np.maximum.reduceat(a, first, axis=0), np.maximum.reduceat(b, first, axis=0))
    return np.stack([low, high], axis=1)


def visible_runs(boxes: np.ndarray, project, total: int, chunk: int = CHUNK) -> list[tuple[int, int]]:
    """Runs ``(first, last)`` of units whose chunks' boxes reach into the view;
    ``project`` maps (n, 3) world points to normalised device coordinates."""
    if not len(boxes):
        return []
    corners = np.where(_CORNERS[None], boxes[:, 1][:, None], boxes[:, 0][:, None])  # (k, 8, 3)
    ndc = project(corners.reshape(-1, 3)).reshape(len(boxes), 8, 3)
    low, high = ndc[..., :2].min(axis=1), ndc[..., :2].max(axis=1)
    seen = np.all((high >= -1.0) & (low <= 1.0), axis=1)
    edges = np.diff(np.concatenate([[False], seen, [False]]).astype(np.int8))
    begin, end = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    return [(int(b) * chunk, min(int(e) * chunk, total)) for b, e in zip(begin, end, strict=True)]
