"""The kit's own frame codec, written from docs/protocol.md alone ("Frames").

Nothing here comes from the rest of ``app.comm`` or from the simulator: a bug shared
with the code under test would hide. ``seal(body)`` makes ``BODY*CCCC\\n``;
``Reply.parse(line)`` reads one line the machine sent and says what is wrong with it
(``problem``: bad CRC, no ``*``, over-length, a field the document does not allow).
``GOLDEN`` holds the document's check values; ``self_test()`` proves the codec
against them before any check runs.
"""

from __future__ import annotations

import binascii
import re
from dataclasses import dataclass, field

MAX_FRAME = 96
GOLDEN = {b"123456789": "29B1", b"D 0 G00 X10 Y10": "904C"}
STATES = ("IDLE", "HOMING", "RUN", "HOLD", "JOG", "ALARM")
FLAGS = "HCLUPSW"
WHY = ("HOST", "PANEL", "COVER", "LINK", "UART", "PROG", "SOFT", "LINE", "LIMIT", "FAULT")
ALARMS = (
    "LIMIT",
    "SOFT_LIMIT",
    "COVER_OPEN",
    "FOLLOWING_ERROR",
    "HOMING_FAILED",
    "HOST_LOST",
    "UART_LOST",
    "BOOT",
    "EXEC_LOG",
)

_INT = r"-?[0-9]+"
_SEQ = r"[0-9]+"
_NUM = r"-?[0-9]{1,6}(?:\.[0-9]+)?"
_WORD = r"[A-Z][A-Z0-9_]*"
_PCT = r"[1-9][0-9]{0,2}"  # an override's percentage ("Overrides")
# Machine -> host, one pattern per kind: the fields after the kind letter.
_GRAMMAR = {
    "A": re.compile(rf"({_SEQ}) ({_SEQ})"),
    "F": re.compile(rf"({_INT})"),
    "N": re.compile(rf"({_SEQ})"),
    "O": re.compile(rf"({_SEQ}) ({_WORD})(?: (.+))?"),
    "E": re.compile(rf"({_SEQ}|-) ({_WORD})(?: (.*))?"),
    "S": re.compile(
        rf"([0-9A-F]{{1,8}}) ({'|'.join(STATES)}) ({_NUM}) ({_NUM}) ({_NUM}) ({_INT}) ({_INT}) "
        rf"({_SEQ}) ({_SEQ}) ([{FLAGS}]+|-)(?: ({'|'.join(WHY)}|-)(?: ({_PCT}/{_PCT}/{_PCT}))?)?"
    ),
    "X": re.compile(rf"({_WORD})(?: (.*))?"),
    "I": re.compile(rf"({_SEQ}) (.+)"),
    "L": re.compile(r"(.*)"),
    "R": re.compile(rf"({_SEQ}) ({_WORD})(?: (.*))?"),
}


def crc(body: bytes) -> str:
    """CRC-16/CCITT-FALSE of ``body`` as 4 upper-case hex digits."""
    return f"{binascii.crc_hqx(body, 0xFFFF):04X}"


def seal(body: str) -> bytes:
    raw = body.encode("ascii")
    return raw + b"*" + crc(raw).encode() + b"\n"


def self_test() -> list[str]:
    """Where the codec disagrees with the document's check values (empty: none)."""
    return [f"CRC of {k!r} is {crc(k)}, the document says {v}" for k, v in GOLDEN.items() if crc(k) != v]


@dataclass
class Reply:
    """One line from the machine: ``kind`` and ``fields`` (regex groups), ``t`` wall
    seconds when it arrived; ``problem`` is None for a valid frame."""

    raw: bytes
    t: float
    kind: str = ""
    body: str = ""
    fields: tuple = field(default_factory=tuple)
    problem: str | None = None

    @classmethod
    def parse(cls, line: bytes, t: float) -> Reply:
        """``line`` is a whole line including its ``\\n``."""
        reply = cls(line, t)
        reply.problem = reply._read(line.rstrip(b"\n").replace(b"\r", b""))
        return reply

    def _read(self, line: bytes) -> str | None:
        if len(line) + 1 > MAX_FRAME:
            return f"{len(line) + 1} bytes, over {MAX_FRAME}"
        body, star, check = line.rpartition(b"*")
        if not star:
            return "no '*' before the CRC"
        if check != crc(body).encode():
            return f"CRC {check.decode('ascii', 'replace')!r}, the body's is {crc(body)}"
        try:
            self.body = body.decode("ascii")
        except UnicodeDecodeError:
            return "a byte that is not ASCII"
        if not self.body.isprintable():
            return "a byte that is not printable"
        self.kind, _, rest = self.body.partition(" ")
        pattern = _GRAMMAR.get(self.kind)
        if pattern is None:
            return f"unknown kind {self.kind!r}"
        match = pattern.fullmatch(rest)
        if match is None:
            return f"fields {rest!r} do not follow the grammar of {self.kind}"
        self.fields = match.groups()
        return None

    # -- conveniences for the checks ----------------------------------------------
    def int(self, index: int) -> int:
        return int(self.fields[index])

    @property
    def id(self) -> int | None:
        """The command id of an O/E/I/R frame (None for ``E -`` and other kinds)."""
        if self.kind in "OEIR" and self.fields and self.fields[0] not in (None, "-"):
            return int(self.fields[0])
        return None

    @property
    def text(self) -> str:
        """The free text: of an E after its code, of an O after its verb, of X, L."""
        last = {"O": 2, "E": 2, "X": 1, "L": 0, "I": 1, "R": 2}.get(self.kind)
        return (self.fields[last] or "") if last is not None and len(self.fields) > last else ""

    def status(self) -> Status | None:
        return Status(*self.fields) if self.kind == "S" and self.problem is None else None

    def __str__(self) -> str:
        return self.raw.decode("ascii", "backslashreplace").rstrip("\n")


@dataclass(frozen=True)
class Status:
    boot: str
    state: str
    x: str
    y: str
    z: str
    acc: str
    done: str
    free: str
    rpm: str
    flags: str
    why: str | None = None  # None: a status of ten fields (a machine from before `why`)
    ovr: str | None = None  # `<feed>/<spindle>/<rapid>`; None: a status without it (optional)

    def has(self, flag: str) -> bool:
        return flag in self.flags
