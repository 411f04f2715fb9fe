"""Frame codec of docs/protocol.md, shared by the host and the simulator.

A frame is one line of printable ASCII, ``BODY*CCCC\\n``, at most 96 bytes, where
CCCC is CRC-16/CCITT-FALSE of BODY in upper-case hex. This module only encodes,
decodes and deframes; it knows nothing of sessions, threads or Qt.

``encode(frame) -> bytes`` and ``decode(line) -> Frame`` are exact inverses for
every frame kind. ``app.comm.deframer.Deframer`` turns arbitrary byte chunks into
frames, counted drops and the legacy bytes `!`/0x18 a machine ignores.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import ClassVar

from app.comm.sealing import MAX_BODY, MAX_FRAME, FrameError, crc16, seal, unseal  # noqa: F401 (re-exported)

PARTIAL_TIMEOUT = 0.5
"""Seconds after which a partial frame with no newline is dropped."""
LEGACY_BYTES = b"!\x18"
"""Feed hold and stop of earlier copies of the protocol (and GRBL): no longer commands;
a receiver takes them off the start of a line, counts them and never acts on them."""
STATES = ("IDLE", "HOMING", "RUN", "HOLD", "JOG", "ALARM")
FLAG_LETTERS = "HCLUPSW"
NO_FLAGS = "-"
REALTIME_VERBS = ("HOLD", "RESUME", "STOP", "RESET")
JOG_VERBS = ("JOG", "JOGEND")  # continuous jog: ``R <id> JOG <dirs> <feed>``, ``R <id> JOGEND``
JOG_DIRS = re.compile(r"(?:[XYZ][+-]){1,2}")
OVERRIDE_RANGES = {"FEED": range(10, 201), "SPINDLE": range(50, 151), "RAPID": (25, 50, 100)}
"""Override verbs of the ``R`` frame and the percentages each takes (docs/protocol.md)."""
NO_OVERRIDES = (100, 100, 100)
WHY_CODES = ("HOST", "PANEL", "COVER", "LINK", "UART", "PROG", "SOFT", "LINE", "LIMIT", "FAULT")
"""Why the machine holds, stopped a job short or is in ALARM (``Status.why``); ``-``: none."""


# --------------------------------------------------------------------------- frames


@dataclass(frozen=True)
class Frame:
    """Base of every frame kind; ``KIND`` is the body's first letter."""

    KIND: ClassVar[str] = ""

    def body(self) -> str:
        raise NotImplementedError

    def encode(self) -> bytes:
        return seal(self.body())


@dataclass(frozen=True)
class Data(Frame):
    """``D <seq> <line>``: one G-code line of the current stream."""

    KIND: ClassVar[str] = "D"
    seq: int
    line: str

    def body(self) -> str:
        return f"D {self.seq} {self.line}"


@dataclass(frozen=True)
class Command(Frame):
    """``C <id> <VERB> [args]``: a command, answered by ``O``/``E`` with the same id."""

    KIND: ClassVar[str] = "C"
    id: int
    verb: str
    args: tuple[str, ...] = ()

    def body(self) -> str:
        return " ".join(("C", str(self.id), self.verb, *self.args))


@dataclass(frozen=True)
class RealtimeCommand(Frame):
    """``R <id> <VERB> [why]``: a real-time command (HOLD, RESUME, STOP, RESET) taken in
    the fast lane; ``why`` only in the main MCU's own frames (``LINK``, ``PANEL``).
    ``R <id> JOG <dirs> <feed>`` (``args`` = (dirs, feed)) and ``R <id> JOGEND``: the
    continuous jog (docs/protocol.md, "Continuous jog")."""

    KIND: ClassVar[str] = "R"
    id: int
    verb: str
    why: str = ""
    args: tuple[str, ...] = ()  # the continuous jog's directions and feed
    percent: int | None = None  # the override verbs' value (FEED, SPINDLE, RAPID)

    def body(self) -> str:
        pct = "" if self.percent is None else str(self.percent)
        return _join("R", str(self.id), self.verb, *self.args, self.why, pct)


@dataclass(frozen=True)
class Ack(Frame):
    """``A <seq> <free>``: every D frame up to seq is queued; free slots remain."""

    KIND: ClassVar[str] = "A"
    seq: int
    free: int

    def body(self) -> str:
        return f"A {self.seq} {self.free}"


@dataclass(frozen=True)
class Finished(Frame):
    """``F <seq>``: every line up to seq has finished moving."""

    KIND: ClassVar[str] = "F"
    seq: int

    def body(self) -> str:
        return f"F {self.seq}"


@dataclass(frozen=True)
class Nak(Frame):
    """``N <seq>``: bad frame or gap; resend from seq."""

    KIND: ClassVar[str] = "N"
    seq: int

    def body(self) -> str:
        return f"N {self.seq}"


@dataclass(frozen=True)
class Ok(Frame):
    """``O <id> <VERB> [info]``: command id done."""

    KIND: ClassVar[str] = "O"
    id: int
    verb: str
    info: str = ""

    def body(self) -> str:
        return _join("O", str(self.id), self.verb, self.info)


@dataclass(frozen=True)
class Error(Frame):
    """``E <id> <code> <text>``: command refused; ``id`` None (``-``) for a refused D line."""

    KIND: ClassVar[str] = "E"
    id: int | None
    code: str
    text: str = ""

    def body(self) -> str:
        return _join("E", "-" if self.id is None else str(self.id), self.code, self.text)


@dataclass(frozen=True)
class Status(Frame):
    """``S <boot> <state> <x> <y> <z> <acc> <done> <free> <rpm> <flags> <why>``; ``why``
    (one of ``WHY_CODES``, "" for ``-``) is absent from a machine before issue 18."""

    KIND: ClassVar[str] = "S"
    boot: str
    state: str
    x: float
    y: float
    z: float
    acc: int
    done: int
    free: int
    rpm: int
    flags: str = ""
    why: str = ""
    overrides: tuple[int, int, int] | None = None  # feed, spindle, rapid %; None: not sent

    def body(self) -> str:
        """The eleven fields, and ``ovr`` when the frame still fits in ``MAX_FRAME`` with it
        (docs/protocol.md, "Machine -> host": a status too long for it goes without)."""
        body = (
            f"S {self.boot} {self.state} {self.x:.3f} {self.y:.3f} {self.z:.3f} "
            f"{self.acc} {self.done} {self.free} {self.rpm} {self.flags or NO_FLAGS} {self.why or NO_FLAGS}"
        )
        ovr = "" if self.overrides is None else " " + "/".join(map(str, self.overrides))
        return body + ovr if len(body) + len(ovr) <= MAX_BODY else body

    def has(self, flag: str) -> bool:
        return flag in self.flags


@dataclass(frozen=True)
class Alarm(Frame):
    """``X <code> <text>``: an alarm (LIMIT, SOFT_LIMIT, COVER_OPEN, ...)."""

    KIND: ClassVar[str] = "X"
    code: str
    text: str = ""

    def body(self) -> str:
        return _join("X", self.code, self.text)


@dataclass(frozen=True)
class Info(Frame):
    """``I <id> <text>``: one row of a multi-row answer to command id."""

    KIND: ClassVar[str] = "I"
    id: int
    text: str

    def body(self) -> str:
        return f"I {self.id} {self.text}"


@dataclass(frozen=True)
class Log(Frame):
    """``L <text>``: free text for the log."""

    KIND: ClassVar[str] = "L"
    text: str

    def body(self) -> str:
        return f"L {self.text}"


def _join(*parts: str) -> str:
    return " ".join(p for p in parts if p)


# --------------------------------------------------------------------------- decoding


def _int(text: str, what: str, minimum: int = 0) -> int:
    digits = text[1:] if text[:1] == "-" else text
    if not (0 < len(digits) <= 10 and digits.isascii() and digits.isdigit()) or int(text) < minimum:
        raise FrameError(f"bad {what} {text!r}")
    return int(text)


_NUM = re.compile(r"-?\d{1,6}(?:\.\d{1,3})?")
_WORD = re.compile(r"[A-Z][A-Z0-9_]*")
_BOOT = re.compile(r"[0-9A-F]{1,8}")
_SEQ, _COUNT = r"(-1|\d{1,10})", r"(\d{1,10})"
_STATUS = re.compile(
    " ".join(
        [_BOOT.pattern.join("()"), "|".join(STATES).join("()")]
        + [_NUM.pattern.join("()")] * 3 + [_SEQ] * 2 + [_COUNT] * 2
        + [f"(-|[{FLAG_LETTERS}]+)"]
    ) + "(?: (" + "|".join(("-",) + WHY_CODES) + r")(?: (\d{1,3})/(\d{1,3})/(\d{1,3}))?)?"
)
"""A well-formed status body after ``S ``: the hot path; anything else is parsed field by field."""


DECIMAL = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)")
"""The one number grammar of command arguments (docs/protocol.md): no exponent, no
``_``, no ``inf``/``nan``, ASCII digits only."""


def decimal(text: str, what: str) -> float:
    """``text`` as a number of the strict grammar ``DECIMAL``; FrameError names ``what``."""
    if not DECIMAL.fullmatch(text):
        raise FrameError(f"{what} {text!r} is not a number")
    return float(text)


def _num(text: str, what: str) -> float:
    if not _NUM.fullmatch(text):
        raise FrameError(f"bad {what} {text!r}")
    return float(text)


def _word(text: str, what: str) -> str:
    if not _WORD.fullmatch(text):
        raise FrameError(f"bad {what} {text!r}")
    return text


def _split(rest: str, count: int, kind: str) -> list[str]:
    """The first ``count - 1`` fields and the remainder (possibly empty)."""
    parts = rest.split(" ", count - 1)
    if any(p == "" for p in parts[: count - 1]) or len(parts) < count - 1:
        raise FrameError(f"{kind} frame has too few fields")
    return parts + [""] * (count - len(parts))


def _data(rest: str) -> Data:
    seq, line = _split(rest, 2, "D")
    if not line:
        raise FrameError("D frame has no line")
    return Data(_int(seq, "seq"), line)


def _command(rest: str) -> Command:
    fields = rest.split(" ")
    if len(fields) < 2 or "" in fields:
        raise FrameError("C frame needs an id and a verb, single-spaced")
    return Command(_int(fields[0], "command id"), _word(fields[1], "verb"), tuple(fields[2:]))


def _realtime(rest: str) -> RealtimeCommand:
    """The strict grammar of docs/protocol.md: id, one of the four verbs, an optional why;
    or id, an override verb and its percentage within the verb's range."""
    fields = rest.split(" ")
    if len(fields) >= 2 and fields[1] in JOG_VERBS and "" not in fields:
        return _jog_frame(fields)
    if not 2 <= len(fields) <= 3 or "" in fields:
        raise FrameError("R frame needs an id, a verb and at most a why, single-spaced")
    if fields[1] in OVERRIDE_RANGES:
        return _override(fields)
    if fields[1] not in REALTIME_VERBS:
        raise FrameError(f"bad real-time verb {fields[1]!r}")
    why = fields[2] if len(fields) == 3 else ""
    if why and why not in WHY_CODES:
        raise FrameError(f"bad why {why!r}")
    return RealtimeCommand(_int(fields[0], "command id"), fields[1], why)


def _jog_frame(fields: list[str]) -> RealtimeCommand:
    """``<id> JOG <dirs> <feed>`` or ``<id> JOGEND``, nothing else (no why)."""
    rid = _int(fields[0], "command id")
    if fields[1] == "JOGEND":
        if len(fields) != 2:
            raise FrameError("R JOGEND takes nothing after the verb")
        return RealtimeCommand(rid, "JOGEND")
    if len(fields) != 4:
        raise FrameError("R JOG needs <dirs> <feed>")
    dirs, feed = fields[2], fields[3]
    if not JOG_DIRS.fullmatch(dirs) or len(set(dirs[::2])) != len(dirs) // 2:
        raise FrameError(f"bad jog directions {dirs!r} (e.g. X+, X+Y-)")
    if decimal(feed, "jog feed") <= 0:
        raise FrameError(f"jog feed {feed!r} must be above 0")
    return RealtimeCommand(rid, "JOG", "", args=(dirs, feed))


def _override(fields: list[str]) -> RealtimeCommand:
    verb = fields[1]
    text = fields[2] if len(fields) == 3 else ""
    if not _PERCENT.fullmatch(text) or int(text) not in OVERRIDE_RANGES[verb]:
        raise FrameError(f"bad {verb} override {text!r}")
    return RealtimeCommand(_int(fields[0], "command id"), verb, percent=int(text))


def override_percents(text: str) -> tuple[int, int, int]:
    """A status's ``ovr`` field ``<feed>/<spindle>/<rapid>`` (each within its range)."""
    parts = text.split("/")
    if len(parts) != 3 or not all(_PERCENT.fullmatch(p) for p in parts):
        raise FrameError(f"bad overrides {text!r}")
    values = tuple(int(p) for p in parts)
    for verb, value in zip(OVERRIDE_RANGES, values, strict=True):
        if value not in OVERRIDE_RANGES[verb]:
            raise FrameError(f"bad {verb} override {value} in {text!r}")
    return values


_PERCENT = re.compile(r"[1-9][0-9]{0,2}")


def _ack(rest: str) -> Ack:
    seq, free = _exact(rest, 2, "A")
    return Ack(_int(seq, "seq", -1), _int(free, "free"))


def _finished(rest: str) -> Finished:
    (seq,) = _exact(rest, 1, "F")
    return Finished(_int(seq, "seq", -1))


def _nak(rest: str) -> Nak:
    (seq,) = _exact(rest, 1, "N")
    return Nak(_int(seq, "seq"))


def _ok(rest: str) -> Ok:
    cid, verb, info = _split(rest, 3, "O")
    return Ok(_int(cid, "command id"), _word(verb, "verb"), info)


def _error(rest: str) -> Error:
    cid, code, text = _split(rest, 3, "E")
    return Error(None if cid == "-" else _int(cid, "command id"), _word(code, "code"), text)


def _status(rest: str) -> Status:
    match = _STATUS.fullmatch(rest)
    if match:
        boot, state, x, y, z, acc, done, free, rpm, flags, why, *ovr = match.groups()
        return Status(
            boot, state, float(x), float(y), float(z), int(acc), int(done), int(free), int(rpm),
            "" if flags == NO_FLAGS else flags, "" if why in (None, NO_FLAGS) else why,
            None if ovr[0] is None else override_percents("/".join(ovr)),
        )
    return _status_fields(rest)


def _status_fields(rest: str) -> Status:
    """The slow path of ``_status``: names the first bad field."""
    f = rest.split(" ")
    if len(f) == 10:
        f.append(NO_FLAGS)
    ovr = override_percents(f.pop()) if len(f) == 12 else None
    f = _exact(" ".join(f), 11, "S")
    if f[10] != NO_FLAGS and f[10] not in WHY_CODES:
        raise FrameError(f"bad why {f[10]!r}")
    if not _BOOT.fullmatch(f[0]):
        raise FrameError(f"bad boot id {f[0]!r}")
    if f[1] not in STATES:
        raise FrameError(f"bad state {f[1]!r}")
    flags = "" if f[9] == NO_FLAGS else f[9]
    if f[9] != NO_FLAGS and not set(flags) <= set(FLAG_LETTERS):
        raise FrameError(f"bad flags {f[9]!r}")
    return Status(
        f[0], f[1], _num(f[2], "x"), _num(f[3], "y"), _num(f[4], "z"),
        _int(f[5], "acc", -1), _int(f[6], "done", -1), _int(f[7], "free"),
        _int(f[8], "rpm"), flags, "" if f[10] == NO_FLAGS else f[10], ovr,
    )


def _alarm(rest: str) -> Alarm:
    code, text = _split(rest, 2, "X")
    return Alarm(_word(code, "alarm code"), text)


def _info(rest: str) -> Info:
    cid, text = _split(rest, 2, "I")
    return Info(_int(cid, "command id"), text)


def _log(rest: str) -> Log:
    return Log(rest)


def _exact(rest: str, count: int, kind: str) -> list[str]:
    fields = rest.split(" ")
    if len(fields) != count or "" in fields:
        raise FrameError(f"{kind} frame needs exactly {count} single-spaced fields")
    return fields


_PARSERS = {
    "D": _data, "C": _command, "R": _realtime, "A": _ack, "F": _finished, "N": _nak, "O": _ok,
    "E": _error, "S": _status, "X": _alarm, "I": _info, "L": _log,
}


def parse_body(body: str) -> Frame:
    """Parse a checked BODY into its frame; raises FrameError naming the bad field."""
    if len(body) < 2 or body[1] != " " or body[0] not in _PARSERS:
        raise FrameError(f"unknown frame kind in {body[:20]!r}")
    return _PARSERS[body[0]](body[2:])


def decode(line: bytes) -> Frame:
    """One frame (with or without the trailing newline / ``\\r``) -> Frame; FrameError if bad."""
    return parse_body(unseal(line.rstrip(b"\n").replace(b"\r", b"")))


def encode(frame: Frame) -> bytes:
    """Frame -> wire bytes ``BODY*CCCC\\n``."""
    return frame.encode()
