"""The micro-SD card of the main MCU: a folder on the host.

Contract: file names are 1-32 characters of letters, digits, ``_ - .`` and do not
start with a dot (so ``..``, ``/`` and hidden temporary files are refused with
``BAD_NAME``). ``SdUpload`` receives an ``SD PUT`` stream into a hidden temporary
file and renames it only when the line count and the CRC32 (over the lines joined
with ``\\n`` plus a final ``\\n``) match; otherwise no file is left. ``capacity_bytes``
models a full card (``SD_FULL``); so does an ``OSError`` of the folder standing for
the card (ENOSPC, a quota, an I/O error) at any byte of an upload: the upload is
refused with ``SD_FULL`` (``SD_ERROR`` for an error other than a full medium) and its
temporary file removed. ``SdCard.open_for_write`` is the one seam through which an
upload writes (tests put a failing file there).
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import zlib
from pathlib import Path

from backend_sim.job_stream import JobStream

_NAME = re.compile(r"[A-Za-z0-9_.\-]{1,32}")
_CRC32 = re.compile(r"[0-9A-Fa-f]{1,8}")
UPLOAD_FREE_SLOTS = 16


FULL_ERRNOS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EFBIG})


class SdError(Exception):
    """Refused SD operation: ``code`` (BAD_NAME, NO_FILE, SD_FULL, SD_ERROR, CRC_MISMATCH) and text."""

    def __init__(self, code: str, text: str) -> None:
        super().__init__(code, text)
        self.code, self.text = code, text


def write_error(name: str, exc: OSError) -> SdError:
    """The refusal for an ``OSError`` while ``name`` was being written."""
    code = "SD_FULL" if exc.errno in FULL_ERRNOS else "SD_ERROR"
    return SdError(code, f"{name}: {exc.strerror or exc}")


def check_name(name: str) -> str:
    if not _NAME.fullmatch(name) or name.startswith("."):
        raise SdError("BAD_NAME", f"{name[:40]!r}: 1-32 of A-Z a-z 0-9 _ - . not starting with '.'")
    return name


def crc32_of_lines(lines: list[str]) -> int:
    """CRC32 of the lines joined with ``\\n`` plus a final ``\\n``."""
    return zlib.crc32(("\n".join(lines) + "\n").encode("ascii", "replace"))


class SdCard:
    def __init__(self, folder: str | Path, capacity_bytes: int = 1 << 30) -> None:
        self.folder = Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)
        self.capacity_bytes = capacity_bytes
        self.remove_partials()

    def remove_partials(self) -> None:
        """Delete the temporary files of uploads that never finished (a crash, a reset)."""
        for path in self.folder.glob(".*.part"):
            path.unlink(missing_ok=True)

    def path(self, name: str) -> Path:
        return self.folder / check_name(name)

    def names(self) -> list[str]:
        return sorted(p.name for p in self.folder.iterdir() if p.is_file() and not p.name.startswith("."))

    def list(self) -> list[tuple[str, int, int]]:
        """(name, bytes, lines) of every file, sorted by name."""
        rows = []
        for name in self.names():
            data = (self.folder / name).read_bytes()
            rows.append((name, len(data), data.count(b"\n")))
        return rows

    def used_bytes(self) -> int:
        return sum(p.stat().st_size for p in self.folder.iterdir() if p.is_file())

    def read_lines(self, name: str) -> list[str]:
        path = self.path(name)
        if not path.is_file():
            raise SdError("NO_FILE", name)
        return path.read_text(encoding="ascii", errors="replace").splitlines()

    def delete(self, name: str) -> None:
        path = self.path(name)
        if not path.is_file():
            raise SdError("NO_FILE", name)
        path.unlink()

    def open_for_write(self, path: Path):
        """A binary file to write an upload to (the filesystem seam)."""
        return path.open("wb")

    def begin_put(self, name: str, lines: int, crc_hex: str) -> SdUpload:
        check_name(name)
        if lines < 1:
            raise SdError("BAD_ARGS", f"line count {lines}: at least 1")
        if self.used_bytes() >= self.capacity_bytes:
            raise SdError("SD_FULL", f"{self.used_bytes()} of {self.capacity_bytes} bytes used")
        if not _CRC32.fullmatch(crc_hex):
            raise SdError("BAD_ARGS", f"CRC {crc_hex!r}: 1-8 hex digits")
        return SdUpload(self, name, lines, int(crc_hex, 16))


class SdUpload:
    """One ``SD PUT`` in progress: the D stream, the temporary file, the running CRC."""

    def __init__(self, card: SdCard, name: str, lines: int, crc: int) -> None:
        self.card, self.name, self.lines, self.crc = card, name, lines, crc
        self.stream = JobStream()
        self.stream.start(lines)
        self.tmp = card.folder / f".{name}.part"
        try:
            self._out = card.open_for_write(self.tmp)
        except OSError as exc:
            self.tmp.unlink(missing_ok=True)
            raise write_error(name, exc) from None
        self._crc = 0
        self._bytes = 0

    def write(self, seq: int, line: str) -> None:
        """Store one line; SdError (the upload is over, its file removed) when the card
        cannot take it."""
        data = line.encode("ascii", "replace") + b"\n"
        try:
            self._out.write(data)
        except OSError as exc:
            self.abort()
            raise write_error(self.name, exc) from None
        self._crc = zlib.crc32(data, self._crc)
        self._bytes += len(data)
        self.stream.accepted(seq)

    @property
    def complete(self) -> bool:
        return self.stream.acc >= self.lines - 1

    def finish(self) -> None:
        """Rename into place, or raise SdError (no file is left)."""
        try:
            self._out.close()
        except OSError as exc:
            self.abort()
            raise write_error(self.name, exc) from None
        count = self.stream.acc + 1
        if count != self.lines or self._crc != self.crc:
            self.tmp.unlink(missing_ok=True)
            raise SdError("CRC_MISMATCH", f"got {count} lines CRC {self._crc:08X}, "
                                          f"announced {self.lines} lines CRC {self.crc:08X}")
        if self.card.used_bytes() > self.card.capacity_bytes:
            self.tmp.unlink(missing_ok=True)
            raise SdError("SD_FULL", "card full")
        try:
            os.replace(self.tmp, self.card.path(self.name))
        except OSError as exc:
            self.abort()
            raise write_error(self.name, exc) from None

    def abort(self) -> None:
        """Close and remove the temporary file (a failing close changes nothing)."""
        with contextlib.suppress(OSError):
            self._out.close()
        self.tmp.unlink(missing_ok=True)
