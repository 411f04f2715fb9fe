"""Screenshots taken in tests land in tmp_path and are real pictures."""

from PySide6.QtGui import QImage

from tests.ui.screens import job_shot, preview_shot


def _wait(qtbot):
    return lambda predicate, timeout: qtbot.waitUntil(predicate, timeout=int(timeout * 1000))


def _check(path):
    assert path.stat().st_size > 20_000, path
    image = QImage(str(path))
    assert image.width() >= 1000 and image.height() >= 600
    colours = {image.pixel(x, y) for x in range(0, image.width(), 37) for y in range(0, image.height(), 37)}
    assert len(colours) > 20  # not a blank window


def test_screenshots(qtbot, window, tmp_path):
    _check(preview_shot(window, _wait(qtbot), tmp_path))
    for path in job_shot(window, _wait(qtbot), tmp_path, speed=40, fraction=0.1):
        _check(path)
