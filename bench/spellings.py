"""The same program in other legal spellings, for the load benchmarks (issue 24).

``variants(path)`` writes beside a compact file (as Gcodetools writes it) the same moves
spelled five ways and returns their paths (made once, then reused):

* ``padded``: numbers right-aligned in wide fields after a space (``X  40.710000``), as
  many post-processors (and this project's importer, once) write;
* ``lower``: every letter in lower case;
* ``numbered``: a block number ``N10``, ``N20``, ... before every line but ``%``;
* ``mixed``: all of those at once, plus ``G1`` for ``G01``, ``+`` on positive numbers,
  no leading zero (``X.5``), spaces inside words (``g 1``, ``x+ 40.7``) and a ``;``
  comment on every tenth line;
* ``marked``: what else hosts and editors write: CRLF line ends, tabs between words,
  a checksum ``*71`` on every fifth line (RepRap hosts send them; the lexer ignores
  them) and block delete ``/`` on every seventh (the switch off: they run).

rs274 reads the first four as the compact file (spaces anywhere, either case, block
numbers, signs, leading zeros; it knows no checksums).
"""

from __future__ import annotations

import re
from pathlib import Path

_NUMBER = re.compile(rb"([XYZIJFxyzijf])(-?\d+\.\d+)")
_LEADING_ZERO = re.compile(rb"(?<=[XYZIJF+-])0\.")
_POSITIVE = re.compile(rb"([XYZIJF])(?=[\d.])")
_TWO_DIGIT_G = re.compile(rb"G0(\d)\b")
_WORD_GAP = re.compile(rb"([GXYZIJF])")
NAMES = ("padded", "lower", "numbered", "mixed", "marked")


def _padded(data: bytes) -> bytes:
    return _NUMBER.sub(lambda m: m.group(1) + b" " + m.group(2).rjust(12), data)


def _numbered(data: bytes) -> bytes:
    out = []
    for k, line in enumerate(data.split(b"\n")[:-1], start=1):
        out.append(line if line.startswith(b"%") else b"N%d %s" % (10 * k, line))
    return b"\n".join(out) + b"\n"


def _mixed(data: bytes) -> bytes:
    text = _TWO_DIGIT_G.sub(rb"G\1", data)
    text = _POSITIVE.sub(rb"\1+", text)
    text = _LEADING_ZERO.sub(b".", text)
    text = _WORD_GAP.sub(rb"\1 ", text)
    lines = text.split(b"\n")[:-1]
    for k in range(9, len(lines), 10):
        if not lines[k].startswith(b"%"):
            lines[k] += b" ; every tenth line"
    return _numbered(b"\n".join(lines) + b"\n").lower()


def _marked(data: bytes) -> bytes:
    lines = data.replace(b" ", b"\t").split(b"\n")[:-1]
    for k in range(4, len(lines), 5):
        if not lines[k].startswith((b"%", b"(")):
            lines[k] += b"*%d" % (sum(lines[k]) & 255)
    for k in range(6, len(lines), 7):
        if not lines[k].startswith(b"%"):
            lines[k] = b"/" + lines[k]
    return b"\r\n".join(lines) + b"\r\n"


SPELL = {"padded": _padded, "lower": bytes.lower, "numbered": _numbered, "mixed": _mixed, "marked": _marked}


def variants(path: Path) -> dict[str, Path]:
    """{name: path} of the four spellings of ``path`` (built once, then reused)."""
    out = {}
    data = None
    for name in NAMES:
        target = path.with_name(f"{path.stem}_{name}{path.suffix}")
        if not target.exists() or target.stat().st_mtime < path.stat().st_mtime:
            data = path.read_bytes() if data is None else data
            target.write_bytes(SPELL[name](data))
        out[name] = target
    return out
