"""The window's geometry and dock layout, kept in a JSON file written atomically.

No Qt here: the window passes the bytes of ``saveGeometry()``/``saveState()``.
``load_window_state(path)`` never raises: a missing file gives nothing to restore; a
damaged one (``reading.load_json``: not a regular file, too big, too deep, not JSON)
is renamed ``<name>.damaged`` (kept for the operator, never overwritten silently),
nothing is restored, and ``problem`` says so.
"""

from __future__ import annotations

import base64
import binascii
import json
from dataclasses import dataclass
from pathlib import Path

from app.atomic import set_aside, write_atomic
from app.gcode.reading import SourceError, load_json

FILE_NAME = "window.json"


@dataclass(frozen=True)
class WindowState:
    geometry: bytes | None = None
    state: bytes | None = None
    problem: str = ""


def save_window_state(path: Path, geometry: bytes, state: bytes) -> None:
    data = {"geometry": base64.b64encode(geometry).decode(), "state": base64.b64encode(state).decode()}
    write_atomic(path, json.dumps(data))


def load_window_state(path: Path) -> WindowState:
    try:
        data = load_json(path)
    except FileNotFoundError:
        return WindowState()
    except (OSError, SourceError) as exc:
        return _damaged(path, str(exc))
    try:
        if not isinstance(data, dict):
            raise ValueError("not a JSON object")
        return WindowState(_field(data, "geometry"), _field(data, "state"))
    except (ValueError, TypeError, binascii.Error) as exc:
        return _damaged(path, str(exc) or type(exc).__name__)


def _field(data: dict, key: str) -> bytes | None:
    value = data.get(key)
    if value is None:
        return None
    if not isinstance(value, str):
        raise ValueError(f"{key} is not text")
    return base64.b64decode(value, validate=True)


def _damaged(path: Path, why: str) -> WindowState:
    aside = set_aside(path)
    kept = aside.name if aside is not None else path.name
    return WindowState(problem=f"The window layout file {path} is damaged ({why}); the default layout is "
                               f"used and the damaged file kept as {kept}.")
