"""The sealing layer of docs/protocol.md's frames: ``BODY*CCCC\n`` with CRC-16/CCITT-FALSE
over printable ASCII, at most ``MAX_FRAME`` bytes. No frame kinds here (``app.comm.frame``
builds on it and re-exports these names)."""

from __future__ import annotations

import binascii
import re

MAX_FRAME = 96
"""Longest frame in bytes, including ``*CCCC\n``."""
MAX_BODY = MAX_FRAME - 6


class FrameError(ValueError):
    """A line that is not a valid frame; the message says why."""


def crc16(body: bytes) -> int:
    """CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF): ``crc16(b"123456789") == 0x29B1``."""
    return binascii.crc_hqx(body, 0xFFFF)


def seal(body: str) -> bytes:
    """``BODY`` -> ``BODY*CCCC\\n``; raises FrameError if the result is too long or not ASCII."""
    raw = body.encode("ascii", "strict") if body.isascii() else _not_ascii(body)
    if not _PRINTABLE.fullmatch(raw):
        raise FrameError(f"body has a non-printable byte: {body!r}")
    if len(raw) > MAX_BODY:
        raise FrameError(f"frame would be {len(raw) + 6} bytes, over {MAX_FRAME}: {body[:40]!r}...")
    return b"%s*%04X\n" % (raw, crc16(raw))


def unseal(line: bytes) -> str:
    """``BODY*CCCC`` (newline and ``\\r`` already removed) -> BODY, checking length and CRC."""
    if len(line) + 1 > MAX_FRAME:
        raise FrameError(f"over-length frame ({len(line) + 1} bytes)")
    body, star, crc = line.rpartition(b"*")
    if not star:
        raise FrameError("no '*' before the CRC")
    if not _PRINTABLE.fullmatch(body) or not body:
        raise FrameError("empty body or a non-printable byte")
    if not _HEX4.fullmatch(crc):
        raise FrameError(f"CRC field {crc!r} is not 4 upper-case hex digits")
    if int(crc, 16) != crc16(body):
        raise FrameError(f"bad CRC {crc.decode()} (expected {crc16(body):04X})")
    return body.decode("ascii")


def _not_ascii(body: str) -> bytes:
    raise FrameError(f"body is not ASCII: {body!r}")


_PRINTABLE = re.compile(rb"[\x20-\x7e]*")
_HEX4 = re.compile(rb"[0-9A-F]{4}")
