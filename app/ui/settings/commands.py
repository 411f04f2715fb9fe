"""The operator's custom commands (a row of buttons, as Candle and gSender have): each a
name, what it runs (G-code lines typed in, or a G-code file) and whether it asks first.
Kept as JSON (``commands.json``) beside ``settings.json``. No Qt here.

``load_commands(path)`` never raises: a missing file gives no commands; a damaged one is
set aside (``aside_note``) with a message naming the file; an entry that breaks a rule
is left out with a message naming the file, the entry and the rule, and the others are
kept. ``save_commands`` writes atomically.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from app.atomic import aside_note, write_atomic
from app.gcode.reading import SourceError, load_json
from app.i18n import joined, msg

VERSION = 1
FILE_NAME = "commands.json"
NAME_LIMIT = 40
LIMIT = 24  # buttons in the row


@dataclass(frozen=True)
class CustomCommand:
    name: str
    gcode: str = ""  # G-code lines, one per line; or
    file: str = ""  # a G-code file to run (exactly one of the two)
    confirm: bool = False

    def problem(self) -> str:
        """What breaks a rule ("" when fine), in the operator's words."""
        if not self.name.strip() or len(self.name) > NAME_LIMIT:
            return msg("a name of 1 to {limit} characters", limit=NAME_LIMIT)
        if bool(self.gcode.strip()) == bool(self.file.strip()):
            return msg("either G-code lines or a file, not both and not neither")
        return ""


@dataclass(frozen=True)
class LoadedCommands:
    commands: tuple[CustomCommand, ...]
    problem: str = ""


def load_commands(path: Path) -> LoadedCommands:
    """The saved commands; never raises, never writes (see the module docstring)."""
    try:
        data = load_json(path)
    except FileNotFoundError:
        return LoadedCommands(())
    except SourceError as exc:
        return LoadedCommands((), aside_note(path, _damaged(path, exc.args[0])))
    except OSError as exc:
        return LoadedCommands((), msg("{path}: cannot read ({error}); using the defaults", path=str(path),
                                      error=str(exc)))
    valid = isinstance(data, dict) and data.get("version") == VERSION
    if not (valid and isinstance(data.get("commands"), list)):
        return LoadedCommands((), aside_note(path, _damaged(path, "not a version 1 list of commands")))
    commands, problems = [], []
    for number, entry in enumerate(data["commands"][:LIMIT], start=1):
        command, problem = _entry(entry)
        if problem:
            problems.append(msg("{path}: command {number}: {problem}", path=str(path), number=number,
                                problem=problem))
        else:
            commands.append(command)
    return LoadedCommands(tuple(commands), joined(problems))


def save_commands(path: Path, commands) -> None:
    """Write ``commands`` atomically; OSError if the folder cannot be written."""
    rows = [{"name": c.name, "gcode": c.gcode, "file": c.file, "confirm": c.confirm} for c in commands]
    write_atomic(path, json.dumps({"version": VERSION, "commands": rows}, indent=2, ensure_ascii=False))


def _entry(entry) -> tuple[CustomCommand | None, str]:
    if not isinstance(entry, dict):
        return None, msg("not an object with name, gcode, file, confirm")
    values = {key: entry.get(key, default) for key, default in
              (("name", ""), ("gcode", ""), ("file", ""), ("confirm", False))}
    for key in ("name", "gcode", "file"):
        if not isinstance(values[key], str):
            return None, msg("{key} must be text", key=key)
    if not isinstance(values["confirm"], bool):
        return None, msg("{key} must be true or false", key="confirm")
    command = CustomCommand(**values)
    problem = command.problem()
    return (None, problem) if problem else (command, "")


def _damaged(path: Path, error) -> str:
    return msg("The settings file {path} is damaged ({error})", path=str(path), error=error)
