"""GRBL 1.1 / grblHAL lines from the machine, parsed into small frozen dataclasses.

``parse_line(text)`` takes one line without its line end and returns one of: ``Ok``,
``Error(code)``, ``Alarm(code)``, ``Welcome(flavour, version, text)``,
``Report`` (a ``<...>`` status report, fields whatever ``$10`` asked for),
``SettingLine(number, value)`` (``$n=v``), ``Feedback(kind, text)`` (``[MSG:..]``,
``[GC:..]``, ``[VER:..]``, ``[OPT:..]``, ``[G54:..]``...), ``StartupLine(line, result)``
(``>G54:ok``) or ``Unknown(text, why)``. It never raises: a malformed report is an
``Unknown`` naming what was wrong. Real-time bytes the host sends are here too.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from app.i18n import msg

Vec = tuple[float, ...]

# Real-time commands (interface documentation, "Real-time commands").
STATUS_QUERY = b"?"
CYCLE_START = b"~"
FEED_HOLD = b"!"
SOFT_RESET = b"\x18"
SAFETY_DOOR = b"\x84"
JOG_CANCEL = b"\x85"
FEED_100, FEED_PLUS_10, FEED_MINUS_10, FEED_PLUS_1, FEED_MINUS_1 = (bytes([b]) for b in range(0x90, 0x95))
RAPID_100, RAPID_50, RAPID_25 = b"\x95", b"\x96", b"\x97"
SPINDLE_100, SPINDLE_PLUS_10, SPINDLE_MINUS_10, SPINDLE_PLUS_1, SPINDLE_MINUS_1 = (
    bytes([b]) for b in range(0x99, 0x9E))
SPINDLE_STOP = b"\x9e"
# The console kinds (``FrameEvent.kind``) of GRBL's streaming and polling traffic, hidden
# unless the operator asks for them: job lines, the job's preamble and syncs, the ``ok``
# answering them and the polled status reports (an operator's own ``?`` is answered by a
# "report", shown; a command's ``ok``, messages and errors are "rx", shown).
STREAM_KINDS = frozenset({"job", "preamble", "sync", "<", "ok"})

REALTIME_NAMES = {STATUS_QUERY: "status", CYCLE_START: "cycle start", FEED_HOLD: "feed hold",
                  SOFT_RESET: "soft reset", SAFETY_DOOR: "safety door", JOG_CANCEL: "jog cancel"}


@dataclass(frozen=True)
class Ok:
    pass


@dataclass(frozen=True)
class Error:
    code: int


@dataclass(frozen=True)
class Alarm:
    code: int


@dataclass(frozen=True)
class Welcome:
    """``Grbl 1.1h ['$' for help]`` (flavour "grbl") or ``GrblHAL 1.1f ...`` ("grblhal")."""

    flavour: str
    version: str
    text: str


@dataclass(frozen=True)
class Report:
    """One ``<...>`` status report. Positions are as reported (mm or inches per ``$13``);
    a field the report did not carry is None."""

    state: str
    substate: int | None = None
    mpos: Vec | None = None
    wpos: Vec | None = None
    wco: Vec | None = None
    feed: float | None = None
    rpm: float | None = None
    overrides: tuple[int, int, int] | None = None
    pins: str | None = None
    planner_free: int | None = None
    rx_free: int | None = None
    accessories: str | None = None
    line: int | None = None


@dataclass(frozen=True)
class SettingLine:
    number: int
    value: str


@dataclass(frozen=True)
class Feedback:
    """A ``[KIND:text]`` message (``MSG``, ``GC``, ``VER``, ``OPT``, ``G54``, ``PRB``...)."""

    kind: str
    text: str


@dataclass(frozen=True)
class StartupLine:
    line: str
    result: str


@dataclass(frozen=True)
class Unknown:
    text: str
    why: str = ""


Line = Ok | Error | Alarm | Welcome | Report | SettingLine | Feedback | StartupLine | Unknown

_WELCOME = re.compile(r"^(grbl|grblhal)\s+(\d+\.\d+[a-z]?)\b(.*)$", re.IGNORECASE)
_SETTING = re.compile(r"^\$(\d+)=(.*)$")
_FEEDBACK = re.compile(r"^\[([A-Za-z0-9.]+):(.*)\]$")
_CODE = re.compile(r"^(error|ALARM):(\d+)$")


def parse_line(text: str) -> Line:
    """One line from the machine (no line end) as its dataclass; see the module."""
    text = text.strip()
    if text == "ok":
        return Ok()
    code = _CODE.match(text)
    if code:
        return Error(int(code[2])) if code[1] == "error" else Alarm(int(code[2]))
    if text.startswith("<"):
        return parse_report(text)
    if text.startswith("["):
        match = _FEEDBACK.match(text)
        if match is None:
            return Unknown(text, msg("a [ ] message without its end"))
        return Feedback(match[1].upper(), match[2])
    if text.startswith(">"):
        line, _, result = text[1:].rpartition(":")
        if line.endswith(":error"):
            line, result = line[: -len(":error")], "error:" + result
        return StartupLine(line, result)
    setting = _SETTING.match(text)
    if setting:
        return SettingLine(int(setting[1]), setting[2].strip())
    welcome = _WELCOME.match(text)
    if welcome:
        flavour = "grblhal" if welcome[1].lower() == "grblhal" else "grbl"
        return Welcome(flavour, welcome[2], text)
    return Unknown(text)


def _numbers(value: str, count: int | None = None) -> Vec:
    parts = value.split(",")
    if count is not None and len(parts) < count:
        raise ValueError(f"{count} numbers expected, got {len(parts)}")
    values = tuple(float(p) for p in parts)
    if not all(math.isfinite(v) for v in values):
        raise ValueError(f"not a finite number: {value}")
    return values


def _field_mpos(value):
    return {"mpos": _numbers(value, 3)}


def _field_wpos(value):
    return {"wpos": _numbers(value, 3)}


def _field_wco(value):
    return {"wco": _numbers(value, 3)}


def _field_fs(value):
    feed, rpm = _numbers(value, 2)[:2]
    return {"feed": feed, "rpm": rpm}


def _field_f(value):
    return {"feed": _numbers(value, 1)[0]}


def _field_ov(value):
    ov = _numbers(value, 3)
    return {"overrides": (int(ov[0]), int(ov[1]), int(ov[2]))}


def _field_bf(value):
    blocks, rx = _numbers(value, 2)[:2]
    return {"planner_free": int(blocks), "rx_free": int(rx)}


def _field_ln(value):
    return {"line": int(value)}


_SUBSTATE = lambda v: {"substate": int(v)}  # noqa: E731

_FIELDS = {"MPos": _field_mpos, "WPos": _field_wpos, "WCO": _field_wco, "FS": _field_fs,
           "F": _field_f, "Ov": _field_ov, "Bf": _field_bf, "Ln": _field_ln,
           "Pn": lambda v: {"pins": v}, "A": lambda v: {"accessories": v}}


def parse_report(text: str) -> Report | Unknown:
    """A ``<State[:sub]|Field:values|...>`` report; unknown fields are skipped."""
    if not (text.startswith("<") and text.endswith(">")) or len(text) < 3:
        return Unknown(text, msg("a status report without its < >"))
    fields = text[1:-1].split("|")
    state, _, sub = fields[0].partition(":")
    if not state.isalpha():
        return Unknown(text, msg("a status report without a state"))
    values: dict = {"state": state}
    for field in ([f"state:{sub}"] if sub else []) + fields[1:]:
        name, _, value = field.partition(":")
        handler = _SUBSTATE if name == "state" else _FIELDS.get(name)
        try:
            if handler is not None:
                values.update(handler(value))
        except ValueError:
            return Unknown(text, msg("the status field {field} is not what GRBL sends", field=field[:40]))
    return Report(**values)
