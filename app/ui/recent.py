"""Recent files: the last few opened paths, newest first, kept in the window's
preferences (``app/ui/settings/prefs.py``: ``prefs.json``, written atomically)."""

from __future__ import annotations

from pathlib import Path

from app.ui.settings.prefs import RECENT_LIMIT as LIMIT

__all__ = ["LIMIT", "add_recent", "recent_files"]


def recent_files(window) -> list[str]:
    return list(window.prefs.recent_files)


def add_recent(window, path: str | Path) -> list[str]:
    """Put ``path`` first and save the preferences (a failed write is shown, not raised)."""
    window.update_prefs(window.prefs.with_recent(str(Path(path).resolve())))
    return recent_files(window)
