"""The window's geometry and dock layout, kept in a JSON file written atomically.

No Qt here: the window passes the bytes of ``saveGeometry()``/``saveState()``.
``load_window_state(path)`` never raises: a missing file gives nothing to restore; a
damaged one is renamed ``<name>.damaged`` (kept for the operator, never overwritten
silently), nothing is restored, and ``problem`` says so.
"""

from __future__ import annotations

import base64
import binascii
import contextlib
import json
from dataclasses import dataclass
from pathlib import Path

from app.atomic import write_atomic

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
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return WindowState()
    except (OSError, UnicodeDecodeError) as exc:
        return _damaged(path, str(exc))
    try:
        data = json.loads(text)
        if not isinstance(data, dict):
            raise ValueError("not a JSON object")
        return WindowState(_field(data, "geometry"), _field(data, "state"))
    except (ValueError, TypeError, RecursionError, binascii.Error) as exc:
        return _damaged(path, str(exc) or type(exc).__name__)


def _field(data: dict, key: str) -> bytes | None:
    value = data.get(key)
    if value is None:
        return None
    if not isinstance(value, str):
        raise ValueError(f"{key} is not text")
    return base64.b64decode(value, validate=True)


def _damaged(path: Path, why: str) -> WindowState:
    aside = path.with_name(path.name + ".damaged")
    with contextlib.suppress(OSError):
        path.replace(aside)
    return WindowState(problem=f"The window layout file {path} is damaged ({why}); the default layout is "
                               f"used and the damaged file kept as {aside.name}.")
