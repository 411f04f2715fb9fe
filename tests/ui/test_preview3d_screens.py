"""Screenshots of the 3-D view: a star cut in three depth passes from the isometric
preset, and a finished job on the simulator with its measured path. Used by the test
below (into tmp_path, where OpenGL starts) and to refresh the ones in docs/screenshots:
``xvfb-run -a -s '-screen 0 1600x1000x24' .venv/bin/python -m tests.ui.test_preview3d_screens``
(in Vietnamese: ``... docs/screenshots/vi vi``)."""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import pytest

from tests.ui.screens import _save, shot_window, start_on_simulator
from tests.ui.test_preview3d_model import star_program


def _show_3d(window, wait) -> None:
    window.views.setCurrentWidget(window.preview3d)
    view = window.preview3d
    wait(lambda: view.gl is not None or view.unavailable, 10)
    if view.unavailable:
        raise RuntimeError(f"the 3-D view cannot start: {view.unavailable}")
    wait(lambda: view.mesh is not None and view.gl.drawn[0] != "none", 30)


def star_shot(window, wait, out: Path) -> Path:
    """The star in three passes, isometric."""
    path = out / "star_3_passes.ngc"
    out.mkdir(parents=True, exist_ok=True)
    path.write_text(star_program())
    window.open_file(path)
    wait(lambda: window.loaded is not None and window.loaded.path == path, 30)
    _show_3d(window, wait)
    window.preview3d.preset("isometric")
    return _save(window, wait, out / "preview3d-star.png")


def measured_shot(window, wait, out: Path, speed: float = 20) -> Path:
    """The star run to the end on the simulator: finished path, measured path, largest deviation."""
    if window.loaded is None:
        star_shot(window, wait, out)
    start_on_simulator(window, wait, speed)
    wait(lambda: window.binder.last_job_event is not None, 300)
    _show_3d(window, wait)
    view = window.preview3d
    wait(lambda: len(view.measured) > 10, 5)
    view.jump_to_largest()
    view.preset("isometric")
    window.docks["plot"].raise_()
    window.plots.setCurrentWidget(window.diagnostics)
    return _save(window, wait, out / "preview3d-measured.png")


def test_3d_screenshots(make_window, qtbot, tmp_path):
    from app.ui.preview3d.view import gl_problem

    reason = gl_problem()
    if reason:
        pytest.skip(f"no OpenGL in this process ({reason}); test_preview3d_gl runs it under Xvfb")
    from PySide6.QtGui import QImage

    window = make_window()

    def wait(predicate, timeout):
        qtbot.waitUntil(lambda: bool(predicate()), timeout=int(timeout * 1000))

    shots = [star_shot(window, wait, tmp_path), measured_shot(window, wait, tmp_path, speed=40)]
    assert window.binder.last_job_event.completed
    assert len(window.preview3d.measured) > 20
    assert "largest deviation" in window.preview3d.deviation_label.text()
    for path in shots:
        image = QImage(str(path))
        assert image.width() >= 1000 and image.height() >= 600


def main(out: str = "docs/screenshots", language: str = "en") -> int:
    window, wait = shot_window(language)
    work = Path(tempfile.mkdtemp(prefix="cnc-star-"))
    shots = [star_shot(window, wait, work), measured_shot(window, wait, work)]
    target = Path(out)
    target.mkdir(parents=True, exist_ok=True)
    for shot in shots:
        shot.replace(target / shot.name)
        print(target / shot.name)
    window.close()
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
