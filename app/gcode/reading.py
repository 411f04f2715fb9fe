"""Reading a file's bytes safely: only regular files, a size limit, one encoding.

``read_source(path)`` returns the bytes of a regular file of at most
``limits.MAX_FILE_BYTES`` (a FIFO, a device such as ``/dev/zero`` or a folder is
refused before it is opened, so nothing blocks or fills memory); ``read_checked(path,
max_bytes)`` is the same with another limit. The window's and the CLI's own files
(settings, profiles, tools, preferences, layout) are read by ``read_config`` (UTF-8
text, ``CONFIG_MAX_BYTES``) and ``load_json`` (also at most ``MAX_JSON_DEPTH`` levels
of nesting, checked before parsing so a file of 100,000 ``[`` never reaches the parser). ``text_problem``
says why bytes are not a program's text (UTF-16, NUL bytes, not UTF-8 with the
position of the first bad byte), ``clean_bytes``/``clean_text`` drop a UTF-8
byte-order mark and turn CR-only line ends (old Mac files) into LF. Errors are
``SourceError`` with a message for the operator.
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path

from app.i18n import msg

from .limits import MAX_FILE_BYTES

BOM = b"\xef\xbb\xbf"
UTF16_BOMS = (b"\xff\xfe", b"\xfe\xff")
SAVE_AS = msg("save it as UTF-8 (or plain ASCII) text")


class SourceError(ValueError):
    """A file that cannot be read as a program; ``str()`` is the operator's message."""


def _size_text(n: int) -> str:
    return msg("{size:.0f} MiB", size=n / (1 << 20)) if n >= 1 << 20 else msg("{count} bytes", count=n)


LIMIT_TEXT = msg("files up to {size} MiB can be loaded", size=MAX_FILE_BYTES // (1 << 20))


def _not_regular(path) -> str:
    return msg("{path} is not a regular file (a folder, device or pipe)", path=str(path))


def _unreadable(path, exc: OSError) -> str:
    return msg("cannot read {path}: {error}", path=str(path), error=str(exc.strerror or exc))


CONFIG_MAX_BYTES = 4 << 20  # a settings, tools or layout file: far more than any real one
MAX_JSON_DEPTH = 64


def _limit_text(max_bytes: int):
    if max_bytes == MAX_FILE_BYTES:
        return LIMIT_TEXT
    return msg("files up to {size} can be read here", size=_size_text(max_bytes))


def file_problem(path: str | Path, max_bytes: int = MAX_FILE_BYTES) -> str | None:
    """Why ``path`` cannot be opened as a program (without opening it), or None."""
    try:
        info = os.stat(path)
    except OSError as exc:
        return _unreadable(path, exc)
    if not stat.S_ISREG(info.st_mode):
        return _not_regular(path)
    if info.st_size > max_bytes:
        return msg("{path} is {size}: {limit}", path=str(path), size=_size_text(info.st_size),
                   limit=_limit_text(max_bytes))
    return None


def read_source(path: str | Path) -> bytes:
    """The bytes of ``path`` if it is a regular file within the size limit; else SourceError."""
    return read_checked(path, MAX_FILE_BYTES)


def read_checked(path: str | Path, max_bytes: int) -> bytes:
    """The bytes of ``path`` if it is a regular file of at most ``max_bytes``; else SourceError."""
    problem = file_problem(path, max_bytes)
    if problem:
        raise SourceError(problem)
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))  # never waits on a swapped-in FIFO
        with os.fdopen(fd, "rb") as file:
            if not stat.S_ISREG(os.fstat(file.fileno()).st_mode):
                raise SourceError(_not_regular(path))
            data = file.read(max_bytes + 1)
    except OSError as exc:
        raise SourceError(_unreadable(path, exc)) from None
    if len(data) > max_bytes:
        raise SourceError(msg("{path} is more than {size}: {limit}", path=str(path),
                              size=_size_text(max_bytes), limit=_limit_text(max_bytes)))
    return data


def read_config(path: str | Path, max_bytes: int = CONFIG_MAX_BYTES) -> str:
    """The UTF-8 text of a settings-like file (``read_checked``, then ``text_problem``);
    FileNotFoundError when there is none (a file not there yet is no damage)."""
    if not os.path.lexists(path):
        raise FileNotFoundError(path)
    raw = clean_bytes(read_checked(path, max_bytes))
    problem = text_problem(raw)
    if problem:
        raise SourceError(msg("{path}: {problem}", path=str(path), problem=problem))
    return raw.decode("utf-8")


def nesting_problem(text: str, max_depth: int = MAX_JSON_DEPTH) -> str | None:
    """Why ``text`` nests ``[``/``{`` deeper than ``max_depth`` (outside JSON strings), or None."""
    depth = 0
    for match in _BRACKETS.finditer(text):
        token = match.group()
        if token in "[{":
            depth += 1
            if depth > max_depth:
                line = text.count("\n", 0, match.start()) + 1
                return msg("nested more than {depth} levels deep (line {line})", depth=max_depth, line=line)
        elif token in "]}":
            depth -= 1
    return None


_BRACKETS = re.compile(r'"(?:[^"\\]|\\.)*"?|[\[\]{}]')


def load_json(path: str | Path, max_bytes: int = CONFIG_MAX_BYTES, max_depth: int = MAX_JSON_DEPTH):
    """The JSON data of ``path`` read by ``read_config``, at most ``max_depth`` deep;
    SourceError naming the file and what is wrong (FileNotFoundError passes through)."""
    text = read_config(path, max_bytes)
    problem = nesting_problem(text, max_depth)
    if problem is None:
        try:
            import json  # here: a program's load never needs it

            return json.loads(text)
        except (ValueError, RecursionError) as exc:
            problem = str(exc) or type(exc).__name__
    raise SourceError(msg("{path}: not valid JSON: {error}", path=str(path), error=problem))


def looks_utf16(raw: bytes) -> bool:
    """A UTF-16 byte-order mark, or ASCII text with every other byte 0."""
    if raw.startswith(UTF16_BOMS):
        return True
    head = raw[:512]
    zeros_even, zeros_odd = head[0::2].count(0), head[1::2].count(0)
    return len(head) >= 4 and max(zeros_even, zeros_odd) > len(head) // 4 and min(zeros_even, zeros_odd) == 0


def text_problem(raw: bytes) -> str | None:
    """Why ``raw`` (BOM already dropped) is not UTF-8 program text, or None."""
    if looks_utf16(raw):
        return msg("the file is UTF-16 text: {advice}", advice=SAVE_AS)
    if b"\x00" in raw:
        return msg("not a text file (it contains NUL bytes)")
    if raw.isascii():
        return None
    try:
        raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        column = exc.start - (raw.rfind(b"\n", 0, exc.start) + 1) + 1
        return msg("the file is not UTF-8 text (byte 0x{byte:02X} at line {line}, column {column}; "
                   "Latin-1 or Windows-1252?): {advice}", byte=raw[exc.start], line=line, column=column,
                   advice=SAVE_AS)
    return None


def clean_bytes(raw: bytes) -> bytes:
    """``raw`` without a UTF-8 byte-order mark, with CR-only line ends made LF."""
    if raw.startswith(BOM):
        raw = raw[len(BOM):]
    if b"\r" in raw and raw.count(b"\r") != raw.count(b"\r\n"):
        raw = raw.replace(b"\r\n", b"\n").replace(b"\r", b"\n")
    return raw


def clean_text(text: str) -> str:
    """``text`` without a byte-order mark, with CR-only line ends made LF."""
    if text.startswith("\ufeff"):
        text = text[1:]
    if "\r" in text and text.count("\r") != text.count("\r\n"):
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    return text
