"""Where the window meets the feature and point-list dialogs: File > New from
features, and File > Open of a point list (recognised by content)."""

from __future__ import annotations

from pathlib import Path

from app.gcode.pointlist import looks_like_points
from app.gcode.reading import file_problem

SNIFF_BYTES = 4096


def generated_dir(window) -> Path:
    """Where generated programs are written before they are opened."""
    return Path(window.config_dir) / "generated"


def feature_dialog(window):
    from .dialog import FeatureDialog

    dialog = FeatureDialog(window.profile, window.open_file, generated_dir(window), window)
    window.feature_dialog = dialog
    return dialog


def is_point_list(path: str | Path) -> bool:
    """True when ``path`` is a regular file whose head reads as a point list (a FIFO or a
    device is never opened here: the loader refuses it with its message)."""
    if file_problem(path) is not None:
        return False
    try:
        with Path(path).open("rb") as file:
            head = file.read(SNIFF_BYTES)
    except OSError:
        return False  # the loader reports it
    return looks_like_points(head)


def offer_point_import(window, path: str | Path) -> bool:
    """Show the import step when ``path`` is a point list; True when it was shown."""
    if not is_point_list(path):
        return False
    from .import_dialog import PointImportDialog

    dialog = PointImportDialog(Path(path), window.profile, window.open_file, generated_dir(window), window)
    window.import_dialog = dialog
    dialog.show()
    return True
