"""The window's own preferences: the recent files and the dark palette, as JSON
(``prefs.json``) beside ``settings.json``. No Qt here: the caller passes the path.

``load_prefs(path)`` never raises: a missing file gives the defaults; a damaged one
(``reading.load_json``: not a regular file, too big, too deep, not JSON) is set aside
as ``prefs.json.damaged`` and gives the defaults with a message naming the file; a bad
value its default with a message naming the file, the key and the rule. ``save_prefs`` writes atomically
(``app.atomic``): a crash mid-write keeps the old file. ``from_legacy(values)`` reads
what older versions kept in Qt's ``window.ini`` (``recent_files``, ``dark``), for the
one migration when there is no ``prefs.json`` yet.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from app.atomic import aside_note, write_atomic
from app.gcode.reading import SourceError, load_json
from app.i18n import joined, msg

VERSION = 1
FILE_NAME = "prefs.json"
RECENT_LIMIT = 8


@dataclass(frozen=True)
class Prefs:
    recent_files: tuple[str, ...] = ()  # newest first, at most RECENT_LIMIT
    dark: bool = False

    def with_recent(self, path: str) -> Prefs:
        """``path`` first, its older entry dropped, at most ``RECENT_LIMIT`` kept."""
        files = (path, *(f for f in self.recent_files if f != path))
        return Prefs(files[:RECENT_LIMIT], self.dark)


@dataclass(frozen=True)
class LoadedPrefs:
    prefs: Prefs
    problem: str = ""  # what was wrong with the file ("" when fine)


def load_prefs(path: Path) -> LoadedPrefs:
    """The saved preferences; never raises, never writes (see the module docstring)."""
    try:
        data = load_json(path)
    except FileNotFoundError:
        return LoadedPrefs(Prefs())
    except SourceError as exc:
        return LoadedPrefs(Prefs(), aside_note(path, _damaged(path, exc.args[0])))
    except OSError as exc:
        return LoadedPrefs(Prefs(), msg("{path}: cannot read ({error}); using the defaults", path=str(path),
                                        error=str(exc)))
    if not isinstance(data, dict) or data.get("version", VERSION) != VERSION:
        return LoadedPrefs(Prefs(), aside_note(path, _damaged(path, "not a version 1 JSON object")))
    prefs, problems = _read(data, str(path))
    return LoadedPrefs(prefs, joined(problems))


def from_legacy(recent, dark) -> Prefs:
    """Preferences from the values QSettings held (a string for a one-entry list, the
    text ``"true"``/``"false"`` for a boolean in an INI file); anything odd is dropped."""
    if isinstance(recent, str):
        recent = [recent]
    if not isinstance(recent, list | tuple):
        recent = []
    files = tuple(f for f in recent if isinstance(f, str) and f)
    flag = dark if isinstance(dark, bool) else str(dark).lower() == "true"
    return Prefs(files[:RECENT_LIMIT], flag)


def save_prefs(path: Path, prefs: Prefs) -> None:
    """Write ``prefs`` atomically; OSError if the folder cannot be written."""
    data = {"version": VERSION, "recent_files": list(prefs.recent_files), "dark": prefs.dark}
    write_atomic(path, json.dumps(data, indent=2))


def _damaged(path: Path, error) -> str:
    return msg("The settings file {path} is damaged ({error})", path=str(path), error=error)


def _read(data: dict, where: str) -> tuple[Prefs, list[str]]:
    problems = []
    recent = data.get("recent_files", [])
    if not (isinstance(recent, list) and all(isinstance(f, str) and f for f in recent)):
        problems.append(msg("{path}: {key} must be a list of file names", path=where, key="recent_files"))
        recent = []
    dark = data.get("dark", False)
    if not isinstance(dark, bool):
        problems.append(msg("{path}: {key} = {value!r} must be true or false", path=where, key="dark",
                            value=dark))
        dark = False
    return Prefs(tuple(recent[:RECENT_LIMIT]), dark), problems
