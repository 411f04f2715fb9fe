"""The window connected to the simulated GRBL machine (``sim://grbl``) and homed, for the
GRBL window tests; what the machine ran, without the lines every job adds."""

from __future__ import annotations

from app.ui.connection_bar import DRIVERS
from tests.ui.conftest import open_and_wait


def homed_window(qtbot, make_window, path, speed: int = 30):
    """A window on ``sim://grbl?speed=..`` (protocol GRBL), homed, ``path`` open."""
    window = make_window(port_lister=lambda: [(f"sim://grbl?speed={speed}", "GRBL")])
    bar, binder = window.connection, window.binder
    bar.driver.setCurrentIndex([key for key, _ in DRIVERS].index("grbl"))
    bar.button.click()
    qtbot.waitUntil(lambda: binder.connected and binder.status is not None, timeout=30_000)
    window.operator.home("NORMAL")
    qtbot.waitUntil(lambda: binder.status.homed and binder.status.state == "IDLE", timeout=120_000)
    open_and_wait(qtbot, window, path)
    qtbot.waitUntil(lambda: window.controls.buttons["start"].isEnabled(), timeout=20_000)
    return window


def homed_window_with(qtbot, make_window, tmp_path, source: str):
    """``homed_window`` with ``source`` written to a file and open."""
    path = tmp_path / "program.ngc"
    path.write_text(source)
    return homed_window(qtbot, make_window, path)


def lines_run(window) -> list[str]:
    """The lines the simulated machine executed, without each job's preamble and syncs."""
    return [line for line in window.link.sim.machine.executed if line not in ("G21 G90 G94 G17", "G4 P0")]
