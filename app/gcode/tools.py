"""The tool table: number, diameter, length and comment per tool, persisted as JSON.

Qt-free. The file sits next to ``settings.json`` in the per-user config folder
(``default_path()``, from platformdirs; the GUI may pass its own). ``load_tools(path)``
never raises: a missing file is an empty table; a file that cannot be a table (not a
regular file, too big, nested too deep, not JSON: ``reading.load_json``) is set aside
as ``tools.json.damaged`` and the table is empty, with a message; an out-of-range value
gives an empty table and a message naming it. ``save_tools`` writes through
``app.atomic.write_atomic`` (a unique temporary name, fsync, rename), so two windows
saving at once never fail nor leave a reader an empty or half table.

The interpreter reads the table as ``dict[int, Tool]`` (``State.tools``): ``T``/``M6``
and ``M61`` pick a tool, ``G43 H`` applies its length, ``G41 D``/``G42 D`` its radius.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from pathlib import Path

from app.i18n import Message, msg

from .reading import SourceError, load_json

VERSION = 1
FILE_NAME = "tools.json"
MAX_TOOL = 99999
MAX_DIAMETER = 100.0  # mm
MAX_LENGTH = 500.0  # mm, either sign


class ToolError(ValueError):
    """A tool entry out of range; the message names the tool and the field."""


@dataclass(frozen=True)
class Tool:
    """One tool: diameter and length offset in millimetres."""

    number: int
    diameter: float = 0.0
    length: float = 0.0
    comment: str = ""

    def __post_init__(self) -> None:
        check_tool(self.number, self.diameter, self.length)

    @property
    def radius(self) -> float:
        return self.diameter / 2.0


def check_tool(number, diameter, length) -> None:
    """Raise ``ToolError`` naming the field unless every value is in range."""
    if isinstance(number, bool) or not isinstance(number, int) or not 1 <= number <= MAX_TOOL:
        raise ToolError(msg("tool number {number!r} is not a whole number 1..{last}",
                            number=number, last=MAX_TOOL))
    for name, value, lo, hi in ((msg("diameter"), diameter, 0.0, MAX_DIAMETER),
                                (msg("length"), length, -MAX_LENGTH, MAX_LENGTH)):
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            raise ToolError(msg("tool {number}: {name} {value!r} is not a number", number=number, name=name,
                                value=value))
        if not lo <= value <= hi:
            raise ToolError(msg("tool {number}: {name} {value:g} mm is outside {lo:g}..{hi:g} mm",
                                number=number, name=name, value=float(value), lo=lo, hi=hi))


@dataclass(frozen=True)
class LoadedTools:
    tools: dict[int, Tool]
    problem: str = ""  # why the table is empty instead of the file's ("" when fine)


def default_path() -> Path:
    """Where the GUI keeps the table: the per-user config folder of the application."""
    from platformdirs import user_config_dir

    return Path(user_config_dir("cnc-mill-controller", appauthor=False)) / FILE_NAME


def from_data(data) -> dict[int, Tool]:
    """The table from its JSON form; ``ToolError``/``ValueError`` say what is wrong."""
    if not isinstance(data, dict) or data.get("version") != VERSION:
        raise ValueError(msg("not a version {version} tool table", version=VERSION))
    rows = data.get("tools")
    if not isinstance(rows, list):
        raise ValueError(msg("no 'tools' list"))
    table: dict[int, Tool] = {}
    for row in rows:
        if not isinstance(row, dict):
            raise ValueError(msg("tool entry {row!r} is not an object", row=row))
        tool = Tool(row.get("number"), row.get("diameter", 0.0), row.get("length", 0.0),
                    str(row.get("comment", "")))
        if tool.number in table:
            raise ToolError(msg("tool {number} is listed twice", number=tool.number))
        table[tool.number] = tool
    return table


def to_data(tools: dict[int, Tool]) -> dict:
    return {"version": VERSION, "tools": [asdict(tools[n]) for n in sorted(tools)]}


def load_tools(path: Path) -> LoadedTools:
    """Read the table at ``path`` (see the module docstring); never raises."""
    try:
        data = load_json(path)
    except FileNotFoundError:
        return LoadedTools({})
    except SourceError as exc:
        from app.atomic import aside_note  # here: loading a program never needs it (nor tempfile)

        damaged = msg("{path}: the tool table is damaged ({error})", path=str(path), error=_reason(exc))
        return LoadedTools({}, aside_note(path, damaged))
    except OSError as exc:
        return LoadedTools({}, msg("{path}: cannot read the tool table ({error}); the table is empty",
                                   path=str(path), error=str(exc)))
    try:
        return LoadedTools(from_data(data))
    except (ValueError, TypeError) as exc:
        return LoadedTools({}, msg("{path}: the tool table is damaged ({error}); the table is empty",
                                   path=str(path), error=_reason(exc)))


def _reason(exc: Exception):
    """The reason an exception gives: its core message (shown translated) or its text."""
    return exc.args[0] if exc.args and isinstance(exc.args[0], Message) else str(exc)


def save_tools(path: Path, tools: dict[int, Tool]) -> None:
    """Write the table atomically (``app.atomic.write_atomic``); OSError if it cannot."""
    import json  # here: loading a program never writes the table

    from app.atomic import write_atomic  # here: loading a program never needs it (nor tempfile)

    write_atomic(path, json.dumps(to_data(tools), indent=2))
