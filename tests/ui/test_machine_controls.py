"""Machine controls on the simulator: jog, spindle, work zero, settings pushed with SET,
MDI lines and commands, the SD list; and the keep-awake and no-display fallbacks."""

from dataclasses import replace

import pytest
from PySide6.QtCore import Qt

from app.ui.keep_awake import KeepAwake
from app.ui.state_table import decide
from tests.ui.conftest import home_when_allowed

SPEED = 20


@pytest.fixture
def connected(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    return window


def _at(window, axis_index, value, tol=0.05):
    status = window.binder.status
    return status.state == "IDLE" and abs(status.position[axis_index] - value) < tol


def test_jog_spindle_and_work_zero(qtbot, connected):
    window = connected
    x0 = window.binder.status.x
    window.controls.jog.set_step_index(2)  # 10 mm
    qtbot.mouseClick(window.controls.jog.buttons["X", 1], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: _at(window, 0, x0 + 10), timeout=60_000)
    window.actions_by_name["step_1"].trigger()  # 1 mm, by its shortcut's action
    window.actions_by_name["jog_Y+"].trigger()
    y0 = window.binder.status.y
    qtbot.waitUntil(lambda: _at(window, 1, y0 + 1), timeout=60_000)
    qtbot.mouseClick(window.controls.buttons["spindle_on"], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.status.rpm > 1000, timeout=60_000)
    qtbot.mouseClick(window.controls.buttons["spindle_off"], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: "P" not in window.binder.status.flags, timeout=60_000)
    qtbot.mouseClick(window.controls.buttons["zero_XY"], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: _at(window, 0, 0.0, 0.01) and _at(window, 1, 0.0, 0.01), timeout=60_000)


def test_settings_are_pushed_and_mdi_answers(qtbot, connected):
    window = connected
    profile = window.profile
    window.operator.apply_settings(replace(profile, pid=replace(profile.pid, kp=12.5)))
    assert (window.config_dir / "settings.json").exists()
    window.console.mdi.setText("GET KP_Y")
    window.console.mdi.returnPressed.emit()
    qtbot.waitUntil(lambda: "KP_Y 12.5" in window.console.log.toPlainText(), timeout=60_000)
    window.console.mdi.setText("G0 X5 Y5")  # a G-code line runs as a one-line job
    window.console.mdi.returnPressed.emit()
    qtbot.waitUntil(lambda: _at(window, 0, 5.0, 0.01) and _at(window, 1, 5.0, 0.01), timeout=60_000)
    _typed_lines_end_where_they_end(qtbot, window)
    window.console.mdi.setText("G1 X5 Q3")  # not a valid line: said in the console, nothing sent
    window.console.mdi.returnPressed.emit()
    qtbot.waitUntil(lambda: "MDI:" in window.console.log.toPlainText(), timeout=10_000)


def _typed_lines_end_where_they_end(qtbot, window):
    """An MDI line is a job without the after-job lift (the machine's default lifts Z at
    the end of a job): every status after the job's end shows the tool where the line left it."""
    assert window.profile.job.after_job == 1
    # the last job ended: MDI allowed again
    qtbot.waitUntil(lambda: decide("mdi", window.binder.inputs()).allowed, timeout=60_000)
    ended, after = window.binder.last_job_event, []
    window.console.mdi.setText("G1 Z-2 F600")
    window.console.mdi.returnPressed.emit()
    event = lambda: window.binder.last_job_event  # noqa: E731 (the same figures as the last: not ==)
    qtbot.waitUntil(lambda: event() is not None and event() is not ended, timeout=60_000)
    assert window.binder.last_job_event.completed

    last = window.binder.status  # received before the job's end

    def seen() -> bool:  # each status received after the end, read once
        if window.binder.status is not (after[-1] if after else last):
            after.append(window.binder.status)
        return len(after) >= 5

    qtbot.waitUntil(seen, timeout=60_000)
    assert all(s.state == "IDLE" and abs(s.z + 2) < 0.01 for s in after), [(s.state, s.z) for s in after]


def test_keep_awake_is_best_effort(monkeypatch):
    import app.ui.keep_awake as keep_awake

    monkeypatch.setattr(keep_awake.shutil, "which", lambda name: None)
    awake = KeepAwake()
    assert awake.start() is False
    awake.stop()
    monkeypatch.setattr(keep_awake.shutil, "which", lambda name: "/nonexistent/inhibit")
    awake = KeepAwake()
    assert awake.start() is False  # the tool vanished: no crash
    awake.stop()


def test_make_run_falls_back_to_the_demo_without_a_display(monkeypatch):
    import app.run as run

    monkeypatch.setattr(run.sys, "platform", "linux")
    for name in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"):
        monkeypatch.delenv(name, raising=False)
    assert run.has_display() is False
    monkeypatch.setenv("WAYLAND_DISPLAY", "wayland-0")
    assert run.has_display() is True
    monkeypatch.delenv("WAYLAND_DISPLAY")
    monkeypatch.setenv("QT_QPA_PLATFORM", "offscreen")
    assert run.has_display() is True


def test_uart_loss_is_named_and_panel_mirrors_the_machine(qtbot, connected):
    window = connected
    sim = window.link.sim
    view = window.machine_panel
    assert view.panel is sim.panel
    before = view.oled.pixmap().toImage()
    qtbot.mouseClick(view.buttons["OK"], Qt.MouseButton.LeftButton)  # open the menu
    qtbot.waitUntil(lambda: view.oled.pixmap().toImage() != before, timeout=10_000)
    qtbot.mouseClick(view.buttons["EXIT"], Qt.MouseButton.LeftButton)
    sim.faults.cut_uart()
    qtbot.waitUntil(window.alert.isVisible, timeout=60_000)
    assert "internal link" in window.alert.body.text()
    sim.faults.restore_uart()


def test_heartbeat_period_reaches_the_link(qtbot, window):
    profile = window.profile
    window.operator.apply_settings(replace(profile, link=replace(profile.link, heartbeat_s=0.5)))
    qtbot.waitUntil(lambda: window.link.worker.session.link.heartbeat_s == 0.5, timeout=10_000)
