"""Persisted settings: the machine profile (with PID gains, feeds, heartbeat period,
arc tolerance), as JSON in the per-user config folder. No Qt here: the caller passes
the path (``QStandardPaths.AppConfigLocation`` in the GUI, ``tmp_path`` in tests).

``load_settings(path)`` never raises: a missing file gives the defaults; a corrupt
file gives the defaults, a bad value its default, with a message saying what was
wrong (file, key, rule); ``save_settings`` writes atomically (``app.atomic``).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from app.atomic import aside_note, write_atomic
from app.gcode.reading import SourceError, read_config
from app.i18n import joined, msg
from app.profile import MachineProfile, ProfileError, parse_file, read_overrides

VERSION = 1
FILE_NAME = "settings.json"


@dataclass(frozen=True)
class Loaded:
    profile: MachineProfile
    problem: str = ""  # why the defaults were used instead of the file ("" when fine)


def load_settings(path: Path) -> Loaded:
    """The saved profile; never raises. Each bad value is named (file, key, rule) and
    its default used; a file that is no settings at all (not a regular file, too big,
    nested too deep, not JSON) is set aside as ``<name>.damaged`` and gives the defaults.
    The file is never written here: it stays as it is until the operator saves."""
    try:
        data = _migrate(parse_file(path, read_config(path)))
    except FileNotFoundError:
        return Loaded(MachineProfile())
    except (SourceError, ProfileError, ValueError) as exc:
        damaged = msg("The settings file {path} is damaged ({error})", path=str(path),
                      error=exc.args[0] if exc.args else str(exc))
        return Loaded(MachineProfile(), aside_note(path, damaged))
    except OSError as exc:
        problem = msg("{path}: cannot read ({error}); using the defaults", path=str(path), error=str(exc))
        return Loaded(MachineProfile(), problem)
    read = read_overrides(MachineProfile(), data["profile"], str(path))
    return Loaded(read.profile, joined(read.problems))


def _migrate(data) -> dict:
    """Bring an older file to the current layout (version 0 was the bare profile)."""
    if not isinstance(data, dict):
        raise ValueError("not a JSON object")
    version = data.get("version", 0)
    if version == 0:
        return {"version": VERSION, "profile": data}
    if version != VERSION:
        raise ValueError(msg("unknown settings version {version!r}", version=version))
    if not isinstance(data.get("profile"), dict):
        raise ValueError("no 'profile' table")
    return data


def save_settings(path: Path, profile: MachineProfile) -> None:
    """Write the profile atomically (a crash mid-write keeps the old file)."""
    write_atomic(path, json.dumps({"version": VERSION, "profile": profile.to_dict()}, indent=2))


# Profile fields the machine takes with ``SET <name> <value>`` (per axis for the PID).
MACHINE_SETTINGS = {
    ("pid", "kp"): "KP_{axis}",
    ("pid", "ki"): "KI_{axis}",
    ("pid", "kd"): "KD_{axis}",
    ("pid", "following_error_mm"): "FERR",
    ("job", "optional_stop"): "OPTSTOP",
    ("job", "stop_spindle"): "STOPSPINDLE",
    ("job", "after_job"): "AFTERJOB",
}


def machine_settings(profile: MachineProfile) -> list[tuple[str, str]]:
    """The ``SET`` commands (name, value) that push ``profile`` to the machine."""
    out = []
    for (section, key), pattern in MACHINE_SETTINGS.items():
        value = getattr(getattr(profile, section), key)
        names = [pattern.format(axis=a) for a in "XYZ"] if "{axis}" in pattern else [pattern]
        out += [(name, f"{value:g}") for name in names]
    return out
