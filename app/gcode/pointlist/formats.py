"""Point lists as drawing programs export them, recognised by content:

- plain: one point ``x y z`` a line (space, tab or comma separated), ``#`` comments,
  a blank line ends a path;
- the laser engraver's "Fabrication Task" file: ``===== Fabrication Task =====``,
  ``key : value`` header lines, ``== Scan Path Information ==``, ``Number of Total
  Paths : N``, then per path ``Path Number : k``, ``Number of Total Points : n`` and
  n lines ``x y z``.

``read_points(raw, name)`` returns a ``PointList`` or raises ``PointListError``
(file, line, column and what was expected); nothing is returned half-read.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from app.i18n import localize, msg

from ..limits import MAX_NUMBER
from .lines import LineTable, table

FABRICATION_MARK = b"Fabrication Task"
SCAN_SECTION = "== Scan Path Information =="


class PointListError(ValueError):
    """A malformed point list: ``name``, 1-based ``line`` and ``column``, ``message``
    (a core message); ``localized()`` says it in the operator's language. Line 0: the
    whole list (its points reach too far, say), named by the file alone."""

    def __init__(self, name: str, line: int, column: int, message: str) -> None:
        if not line:
            said = msg("{name}: {what}", name=name, what=message)
        elif column:
            said = msg("{name}, line {line}, column {column}: {what}", name=name, line=line, column=column,
                       what=message)
        else:
            said = msg("{name}, line {line}: {what}", name=name, line=line, what=message)
        super().__init__(said)
        self.name, self.line, self.column, self.message = name, line, column, message

    def localized(self) -> str:
        return localize(self.args[0])


@dataclass
class PointList:
    """Paths of points (each an (n, 3) float array), the format and its header."""

    name: str
    format: str  # "plain" or "fabrication"
    paths: list[np.ndarray]
    header: dict[str, str] = field(default_factory=dict)

    @property
    def point_count(self) -> int:
        return sum(len(p) for p in self.paths)


def is_fabrication(raw: bytes) -> bool:
    return FABRICATION_MARK in raw[:4096]


def looks_like_points(raw: bytes) -> bool:
    """Whether ``raw`` reads as a point list (either format) rather than G-code: every line
    of its head is ``x y z``, or (a point list with a bad word, which the reader then names
    with its line) most are and every line starts with a number, as no G-code line does."""
    if is_fabrication(raw):
        return True
    head = table(raw[:4096].rsplit(b"\n", 1)[0] if b"\n" in raw[:4096] else raw[:4096])
    used = head.tokens > 0
    if not used.any():
        return False
    points = head.numeric[used] & (head.tokens[used] == 3)
    if points.all():
        return True
    rows = np.flatnonzero(used)
    return bool(points.mean() >= 0.5 and all(_starts_with_number(head.text(k)) for k in rows))


def _starts_with_number(text: str) -> bool:
    first = text.replace(",", " ").split()[0]
    try:
        float(first)
    except ValueError:
        return False
    return True


def _bad_point(t: LineTable, k: int, name: str) -> PointListError:
    """The error of line ``k`` that should hold a point."""
    tokens = t.text(k).split()
    column = 1
    for n, token in enumerate(tokens[:3]):
        column = t.text(k).find(token, column - 1) + 1
        try:
            value = float(token)
        except ValueError:
            return PointListError(name, k + 1, column, msg("expected a number ({axis}), got {token!r}",
                                                           axis="xyz"[n], token=token))
        if not np.isfinite(value):
            return PointListError(name, k + 1, column, msg("expected a finite number ({axis}), got {token!r}",
                                                           axis="xyz"[n], token=token))
        if not abs(value) < MAX_NUMBER:
            return PointListError(name, k + 1, column, msg("{axis} {token} is too large: a point list's "
                                                           "numbers are below {limit:,.0f} in size",
                                                           axis="xyz"[n], token=token, limit=MAX_NUMBER))
    if len(tokens) != 3:
        return PointListError(name, k + 1, 0, msg("expected three numbers 'x y z', got {count} ({text!r})",
                                                  count=len(tokens), text=t.text(k).strip()))
    return PointListError(name, k + 1, 0, msg("expected three numbers 'x y z', got {text!r}",
                                              text=t.text(k).strip()))


def _block(t: LineTable, first: int, stop: int, name: str) -> np.ndarray:
    values = t.numbers(first, stop)
    if values is None or not (t.tokens[first:stop] == 3).all():
        for k in range(first, stop):
            if t.tokens[k] != 3 or t.numbers(k, k + 1) is None:
                raise _bad_point(t, k, name)
    return values.reshape(-1, 3)


def read_plain(raw: bytes, name: str) -> PointList:
    """Paths of a plain ``x y z`` list (see the module docstring)."""
    t = table(raw)
    used = t.tokens > 0
    if not used.any():
        raise PointListError(name, 1, 0, msg("expected points 'x y z', found none"))
    edges = np.diff(np.concatenate(([0], used.astype(np.int8), [0])))
    starts, stops = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    paths = [_block(t, a, b, name) for a, b in zip(starts.tolist(), stops.tolist(), strict=True)]
    return PointList(name, "plain", paths)


def _field(t: LineTable, k: int, key: str, name: str) -> str:
    text = t.text(k)
    left, sep, right = text.partition(":")
    if not sep or left.strip().lower() != key.lower():
        raise PointListError(name, k + 1, 1, msg("expected '{key} : ...', got {text!r}", key=key,
                                                 text=text.strip()))
    return right.strip()


def _count(t: LineTable, k: int, key: str, name: str) -> int:
    value = _field(t, k, key, name)
    if not value.isdigit():
        raise PointListError(name, k + 1, t.text(k).find(":") + 3,
                             msg("expected a whole number after '{key} :', got {value!r}", key=key,
                                 value=value))
    return int(value)


def read_fabrication(raw: bytes, name: str) -> PointList:
    """Paths and header of a "Fabrication Task" file (see the module docstring)."""
    t = table(raw)
    lines = np.flatnonzero(t.tokens > 0).tolist()
    header, i = {}, 0
    while i < len(lines) and t.text(lines[i]).strip() != SCAN_SECTION:
        key, sep, value = t.text(lines[i]).partition(":")
        if sep:
            header[key.strip()] = value.strip()
        i += 1
    if i == len(lines):
        raise PointListError(name, len(t.start), 0, msg("expected the line '{line}', not found",
                                                        line=SCAN_SECTION))
    if i + 1 >= len(lines):
        raise PointListError(name, lines[i] + 1, 0, msg("expected 'Number of Total Paths : N' after it"))
    total = _count(t, lines[i + 1], "Number of Total Paths", name)
    k = lines[i + 1] + 1
    paths = []
    for p in range(total):
        k = _next_used(t, k, name, msg("'Path Number : {p}' (path {n} of {total})", p=p, n=p + 1,
                                       total=total))
        _field(t, k, "Path Number", name)
        k = _next_used(t, k + 1, name, msg("'Number of Total Points : n'"))
        n = _count(t, k, "Number of Total Points", name)
        first = k + 1
        short = np.flatnonzero(~(t.numeric[first:first + n] & (t.tokens[first:first + n] == 3)))
        if first + n > len(t.start) or len(short):
            _short_path(t, first, n, int(short[0]) if len(short) else len(t.start) - first,
                        _field(t, k - 1, "Path Number", name), name)
        paths.append(_block(t, first, first + n, name))
        k = first + n
    rest = np.flatnonzero(t.tokens[k:] > 0)
    if len(rest):
        at = k + int(rest[0])
        raise PointListError(name, at + 1, 0,
                             msg("expected the end of the file after {total} paths, got {text!r}",
                                                  total=total, text=t.text(at).strip()))
    return PointList(name, "fabrication", paths, header)


def _short_path(t: LineTable, first: int, n: int, found: int, number: str, name: str) -> None:
    """Raise the error of a path that does not hold the ``n`` points it announced."""
    at = first + found
    if at < len(t.start) and ":" not in t.text(at):
        raise _bad_point(t, at, name)
    where = msg("the end of the file") if at >= len(t.start) else repr(t.text(at).strip())
    raise PointListError(name, min(at, len(t.start) - 1) + 1, 0,
                         msg("path {number} announced {n} points, found {found} before {where} "
                             "(expected 'x y z')", number=number, n=n, found=found, where=where))


def _next_used(t: LineTable, k: int, name: str, expected: str) -> int:
    rest = np.flatnonzero(t.tokens[k:] > 0)
    if not len(rest):
        raise PointListError(name, len(t.start), 0, msg("expected {expected}, found the end of the file",
                                                        expected=expected))

    return k + int(rest[0])


def read_points(raw: bytes, name: str = "<points>") -> PointList:
    """The point list in ``raw``, either format, recognised by content."""
    return read_fabrication(raw, name) if is_fabrication(raw) else read_plain(raw, name)
