"""The CNC MCU's flash: what survives a reset and a restart (the six work offsets).

Kept as a hidden JSON file in the folder of the SD card (``.flash.json``; hidden
names are never listed or accepted as SD names): ``{"systems": [[x, y, z] * 6],
"active": 54..59, "offset": [x, y, z]}`` (``offset``, the active row, is what a copy
before the six systems wrote and read). A missing or damaged file reads as every system
at the profile's default offset, G54 active; a file with only ``offset`` as that offset
in G54.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

Vec3 = tuple[float, float, float]
SYSTEMS = tuple(range(54, 60))  # G54 .. G59


def _vec3(values) -> Vec3:
    vec = tuple(float(v) for v in values)
    if len(vec) != 3 or not all(math.isfinite(v) for v in vec):
        raise ValueError("not three finite numbers")
    return vec  # type: ignore[return-value]


class Flash:
    def __init__(self, folder: str | Path | None, default_offset: Vec3) -> None:
        self.path = Path(folder) / ".flash.json" if folder is not None else None
        self.default_offset = default_offset

    def defaults(self) -> tuple[dict[int, Vec3], int]:
        return {n: self.default_offset for n in SYSTEMS}, 54

    def load_systems(self) -> tuple[dict[int, Vec3], int]:
        """(offset of each system 54..59, the active system)."""
        systems, active = self.defaults()
        if self.path is None:
            return systems, active
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
            if "systems" in data:
                rows = [_vec3(row) for row in data["systems"]]
                if len(rows) != len(SYSTEMS) or data["active"] not in SYSTEMS:
                    raise ValueError("six systems and the active one")
                return dict(zip(SYSTEMS, rows, strict=True)), int(data["active"])
            systems[54] = _vec3(data["offset"])
        except (OSError, ValueError, KeyError, TypeError):
            return self.defaults()
        return systems, active

    def save_systems(self, systems: dict[int, Vec3], active: int) -> None:
        if self.path is not None:
            data = {"systems": [list(systems[n]) for n in SYSTEMS], "active": active,
                    "offset": list(systems[active])}
            self.path.write_text(json.dumps(data), encoding="utf-8")
