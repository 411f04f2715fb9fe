"""Fixtures for the window tests: isolated settings, a notifier that records instead
of showing boxes, and a window that is shut down cleanly (worker thread, simulator)."""

from __future__ import annotations

from pathlib import Path

import pytest

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"
SAMPLE_FILES = sorted(SAMPLES.glob("*.ngc"))
# The offscreen platform says so when a widget asks it for native window features.
OFFSCREEN_NOISE = ("propagateSizeHints", "does not support raise", "does not support requestActivate")


def pytest_collection_modifyitems(items):
    for item in items:
        if "tests/ui" in str(item.fspath).replace("\\", "/"):
            item.add_marker(pytest.mark.qt_log_ignore(*OFFSCREEN_NOISE))


@pytest.fixture(autouse=True)
def _isolated_paths(qapp):
    from PySide6.QtCore import QStandardPaths

    QStandardPaths.setTestModeEnabled(True)


@pytest.fixture(autouse=True)
def english(qapp):
    """The window in English, as ``cnc-gui --lang en`` shows it (the plural forms come from
    cnc_en.qm); a test may switch, and the next one starts in English again."""
    from app.ui.language import apply_language

    apply_language("en")
    yield
    apply_language("en")


@pytest.fixture
def notifier():
    from app.ui.notifier import Notifier

    return Notifier(show_boxes=False)


@pytest.fixture
def make_window(qtbot, tmp_path, notifier):
    from app.ui.main_window import MainWindow

    windows = []

    def make(port_lister=None, config_dir=None):
        window = MainWindow(config_dir=config_dir or tmp_path / "config", notifier=notifier,
                            port_lister=port_lister or (lambda: [("sim://", "Simulated machine")]))
        qtbot.addWidget(window)
        window.resize(1500, 950)
        window.show()  # the live plots only redraw while visible
        qtbot.waitExposed(window)
        windows.append(window)
        return window

    yield make
    for window in windows:
        window.shutdown()


@pytest.fixture
def window(make_window):
    return make_window()


def open_and_wait(qtbot, window, path, timeout=20_000):
    with qtbot.waitSignal(window.loader.loaded, timeout=timeout) as blocker:
        window.open_file(path)
    return blocker.args[0]


def when_allowed(qtbot, window, control: str, act, timeout=60_000) -> None:
    """``act()`` once the state table allows ``control`` (right after a job ends the last
    status may still show it running: a click then is refused and never acts), asserting
    the operator's action was not refused."""
    from app.ui.state_table import decide

    qtbot.waitUntil(lambda: decide(control, window.binder.inputs()).allowed, timeout=timeout)
    refused = len(window.operator.refused)
    act()
    assert window.operator.refused[refused:] == []


def home_when_allowed(qtbot, window, timeout=60_000):
    """Home once the state table allows it (a first status alone is not enough on a busy
    machine: the session may not be ready yet, and a refused click would never home), then
    wait until homed and at rest."""
    when_allowed(qtbot, window, "home", lambda: window.operator.home("NORMAL"), timeout)
    binder = window.binder
    at_rest = lambda: binder.status.state == "IDLE" and binder.pending_motion is None  # noqa: E731
    qtbot.waitUntil(lambda: binder.status.homed and at_rest(), timeout=timeout)


def pace(window, speed: float) -> None:
    """Run the simulated machine at ``speed`` times real time from now on: a test's hand on
    the simulated world, as its faults are. A job that a test must catch mid-run (to pause
    it, unplug it) runs slow enough that a busy computer's latency cannot let it end first;
    the test stops it when it has seen what it came for."""
    window.link.sim.set_speed(speed)
