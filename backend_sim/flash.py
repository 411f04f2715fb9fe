"""The CNC MCU's flash: what survives a reset and a restart (the work offset).

Kept as a hidden JSON file in the folder of the SD card (``.flash.json``; hidden
names are never listed or accepted as SD names). A missing or damaged file reads as
the profile's default offset.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

Vec3 = tuple[float, float, float]


class Flash:
    def __init__(self, folder: str | Path | None, default_offset: Vec3) -> None:
        self.path = Path(folder) / ".flash.json" if folder is not None else None
        self.default_offset = default_offset

    def load_offset(self) -> Vec3:
        if self.path is None:
            return self.default_offset
        try:
            values = json.loads(self.path.read_text(encoding="utf-8"))["offset"]
            offset = tuple(float(v) for v in values)
        except (OSError, ValueError, KeyError, TypeError):
            return self.default_offset
        if len(offset) != 3 or not all(math.isfinite(v) for v in offset):
            return self.default_offset
        return offset  # type: ignore[return-value]

    def save_offset(self, offset: Vec3) -> None:
        if self.path is not None:
            self.path.write_text(json.dumps({"offset": list(offset)}), encoding="utf-8")
