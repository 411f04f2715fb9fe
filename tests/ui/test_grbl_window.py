"""The window on a GRBL machine (issue 23): the connection bar's protocol choice, the
machine's build info shown, homing and a sample job on the simulated GRBL machine."""

from __future__ import annotations

from app.ui.connection_bar import DRIVERS
from tests.ui.conftest import SAMPLES, open_and_wait


def test_window_runs_a_job_on_the_grbl_simulator(qtbot, make_window):
    # 300 times real time: the star sample runs in seconds, and still fills GRBL's buffers
    window = make_window(port_lister=lambda: [("sim://", "mill"), ("sim://grbl?speed=300", "GRBL")])
    bar = window.connection
    bar.ports.setCurrentIndex(1)
    bar.driver.setCurrentIndex([key for key, _ in DRIVERS].index("grbl"))
    assert bar.driver_choice() == "grbl"
    bar.button.click()
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=30_000)
    qtbot.waitUntil(lambda: "Grbl 1.1h" in bar.info.text(), timeout=10_000)
    assert window.binder.status.state == "ALARM"  # GRBL starts locked until homed
    window.operator.home("NORMAL")
    qtbot.waitUntil(lambda: window.binder.status.homed and window.binder.status.state == "IDLE",
                    timeout=120_000)
    open_and_wait(qtbot, window, SAMPLES / "star_passes.ngc")
    qtbot.waitUntil(lambda: window.controls.buttons["start"].isEnabled(), timeout=20_000)
    assert window.preflight.offset == [0.0, 0.0, 20.0]  # from GRBL's live WCO and $130-$132
    assert not [m for m in window.notifier.messages if m[1] == "Machine refused"]
    window.operator.start()
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=300_000)
    assert window.binder.last_job_event.completed, window.binder.last_job_event
