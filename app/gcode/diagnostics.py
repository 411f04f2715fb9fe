"""Diagnostics: what the G-code core reports instead of raising.

A ``Diagnostic`` names the 1-based physical source line, the 1-based column (0 when
the whole line is meant), its severity (``"error"`` or ``"warning"``), a message and
the file ("" for the program itself, else a subprogram file's path). ``str(d)``
reads ``line 12, column 5: message`` (``O1000.nc line 3: ...`` for a file). ``Report`` collects them; it keeps
at most ``limit`` of each kind of message key and counts the rest, so a million-line
file with one repeated problem stays small.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

from app.i18n import Message, localize, msg

ERROR = "error"
WARNING = "warning"


@dataclass(frozen=True, order=True)
class Diagnostic:
    """One problem found in a source line."""

    line: int
    column: int
    severity: str
    message: str
    file: str = ""  # "" for the program itself; a subprogram file's path otherwise

    def __str__(self) -> str:
        where = f"line {self.line}" + (f", column {self.column}" if self.column else "")
        return f"{self.file + ' ' if self.file else ''}{where}: {self.message}"

    def localized(self) -> str:
        """``str(self)`` in the operator's language (``app.i18n``)."""
        if self.column:
            where = msg("line {line}, column {column}", line=self.line, column=self.column)
        else:
            where = msg("line {line}", line=self.line)
        return f"{localize(where)}: {localize(self.message)}"


@dataclass
class Report:
    """Collects diagnostics; at most ``limit`` per ``key`` are kept, the rest counted."""

    limit: int = 200
    items: list[Diagnostic] = field(default_factory=list)
    dropped: Counter = field(default_factory=Counter)
    _seen: Counter = field(default_factory=Counter)

    def add(self, line: int, column: int, severity: str, message: str, key: str = "", file: str = "") -> None:
        """Record one diagnostic (or count it once ``limit`` of its key are kept); ``file``
        names a subprogram file ("" for the program itself)."""
        key = key or message
        self._seen[severity, key] += 1
        if self._seen[severity, key] > self.limit:
            self.dropped[severity, key] += 1
            return
        self.items.append(Diagnostic(line, column, severity, message, file))

    def add_many(self, lines: range, column: int, severity: str, message: str, key: str = "") -> None:
        """``add`` for every line of ``lines``, at the cost of the ones kept only."""
        key = key or message
        kept = lines[: max(self.limit - self._seen[severity, key], 0)]
        for line in kept:
            self.add(line, column, severity, message, key)
        self.overflow(severity, key, len(lines) - len(kept))

    def overflow(self, severity: str, key: str, count: int) -> None:
        """Count ``count`` more diagnostics of ``key`` that were not listed one by one."""
        if count > 0:
            self._seen[severity, key] += count
            self.dropped[severity, key] += count

    def has_errors(self) -> bool:
        return any(severity == ERROR for severity, _ in self._seen)

    def error(self, line: int, column: int, message: str, key: str = "") -> None:
        self.add(line, column, ERROR, message, key)

    def warning(self, line: int, column: int, message: str, key: str = "") -> None:
        self.add(line, column, WARNING, message, key)

    def finish(self) -> list[Diagnostic]:
        """All diagnostics sorted by line, plus one summary per key that overflowed."""
        out = sorted(self.items)
        for (severity, key), count in sorted(self.dropped.items()):
            last = max((d.line for d in self.items if d.severity == severity), default=0)
            like = key if isinstance(key, Message) else msg(key)
            more = msg("... and {count} more like: {key}", count=count, key=like)
            out.append(Diagnostic(last, 0, severity, more))
        return out
