"""The ``cnc-gcode moves`` format: one dict per G-code move, in program order.

``{"line": 17, "kind": "rapid", "end": [x, y, z]}``,
``{"line": 20, "kind": "feed", "end": [x, y, z], "feed": 100.0}``,
``{"line": 22, "kind": "arc", "end": [x, y, z], "center": [c1, c2], "plane": "XY",
"turn": -1, "feed": 400.0}`` (``center`` in the plane's axes: XY (X, Y), XZ (Z, X),
YZ (Y, Z); ``turn`` < 0 clockwise), ``{"line": 30, "kind": "dwell", "seconds": 0.5}``.
Millimetres, absolute; ``line`` is the 1-based physical source line; arcs whole.
A move made by a subprogram file of an expanded program also has ``"file"`` (the
file's name); its ``line`` is the line in that file.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .ops import ARC_CCW, ARC_CW, DWELL, FEED, PLANE_AXES, PLANE_NAMES, RAPID, Ops


def _arc(line, end, center, plane, turn, feed) -> dict:
    a1, a2, _ = PLANE_AXES[plane]
    return {"line": line, "kind": "arc", "end": end, "center": [center[a1], center[a2]],
            "plane": PLANE_NAMES[plane], "turn": turn, "feed": feed}


def moves_of(ops: Ops) -> list[dict]:
    """The moves of interpreted rows as dicts (see the module docstring)."""
    rows = np.flatnonzero(ops.kind <= DWELL)
    lines = ops.line[rows].tolist()
    kinds = ops.kind[rows].tolist()
    ends = ops.end[rows].tolist()
    centers = ops.center[rows].tolist()
    planes = ops.plane[rows].tolist()
    turns = ops.turn[rows].tolist()
    values = ops.value[rows].tolist()
    out = []
    for i, kind in enumerate(kinds):
        if kind == RAPID:
            out.append({"line": lines[i], "kind": "rapid", "end": ends[i]})
        elif kind == FEED:
            out.append({"line": lines[i], "kind": "feed", "end": ends[i], "feed": values[i]})
        elif kind in (ARC_CW, ARC_CCW):
            out.append(_arc(lines[i], ends[i], centers[i], planes[i], turns[i], values[i]))
        else:
            out.append({"line": lines[i], "kind": "dwell", "seconds": values[i]})
    if ops.source is not None:
        _name_files(out, ops.source.file[rows].tolist(), ops.source.files)
    return out


def _name_files(moves: list[dict], file_ids: list[int], files: list[str]) -> None:
    names = [Path(f).name for f in files]
    for move, file_id in zip(moves, file_ids, strict=True):
        if file_id:
            move["file"] = names[file_id]


def to_jsonl(moves: list[dict]) -> str:
    """JSON Lines text of ``moves``, one object per line."""
    import json  # only for this: every load imports this module, and json costs 3-5 ms of a start

    return "".join(json.dumps(m) + "\n" for m in moves)
