"""Atomic file writes: a crash or a full disk mid-write never leaves a half file.

``write_atomic(path, data)`` writes ``data`` (str as UTF-8, or bytes) to a temporary
file in the same folder, flushes it to the disk, then renames it over ``path`` (a
rename within one file system is atomic): readers see the old file or the new one,
never a mix. On any error the temporary file is removed and the error raised; the
old file is untouched. Used for settings, the window state and the tool table.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path


def write_atomic(path: str | Path, data: str | bytes) -> None:
    """Replace ``path`` with ``data`` atomically (see the module docstring)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    raw = data.encode("utf-8") if isinstance(data, str) else data
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as file:
            file.write(raw)
            file.flush()
            os.fsync(file.fileno())
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise
    _sync_folder(path.parent)


def _sync_folder(folder: Path) -> None:
    """Make the rename itself durable (POSIX; a no-op where folders cannot be opened)."""
    with contextlib.suppress(OSError):
        fd = os.open(folder, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def set_aside(path: str | Path) -> Path | None:
    """Rename a damaged ``path`` to ``<name>.damaged`` (a free name: ``.damaged-2``...) so
    that it is kept for the operator and never read or overwritten again; the new path,
    or None if it could not be moved (then it stays where it is)."""
    path = Path(path)
    for n in range(1, 100):
        aside = path.with_name(path.name + (".damaged" if n == 1 else f".damaged-{n}"))
        if os.path.lexists(aside):
            continue
        try:
            os.rename(path, aside)
        except OSError:
            return None
        return aside
    return None


def aside_note(path: str | Path, problem) -> str:
    """``problem`` and what became of the file (set aside now), for the operator."""
    from app.i18n import msg

    aside = set_aside(path)
    if aside is None:
        return msg("{problem}; the defaults are used", problem=problem)
    return msg("{problem}; the defaults are used and the file is kept as {aside}", problem=problem,
               aside=aside.name)
