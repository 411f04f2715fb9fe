"""Issue 20's defects driven on the simulator, each with its regression test: a jog
clicked during homing never runs; after Start here the machine is free and the next
Start runs; Run from SD shows its own progress and can be paused, resumed and stopped;
MDI ``M3 S3000`` before homing follows the Spindle button's rule, a motion line is
refused in the operator's words."""

from __future__ import annotations

import pytest

from tests.ui.conftest import open_and_wait, when_allowed

SPEED = 20


def _status(window):
    return window.binder.status


@pytest.fixture
def connected(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path / 'card'}")
    qtbot.waitUntil(lambda: window.binder.connected and _status(window) is not None, timeout=60_000)
    qtbot.waitUntil(lambda: window.controls.buttons["home"].isEnabled(), timeout=10_000)
    return window


def _home(qtbot, window):
    window.operator.home("NORMAL")
    qtbot.waitUntil(lambda: _status(window).homed and _status(window).state == "IDLE"
                    and window.binder.pending_motion is None, timeout=60_000)


def test_a_jog_clicked_while_homing_is_refused_and_never_runs(qtbot, connected):
    window = connected
    window.operator.home("NORMAL")
    assert not window.controls.jog.buttons["X", 1].isEnabled()  # at once, before the machine answers
    window.operator.jog("X", 1.0, 300.0)  # a stale click (or its shortcut)
    assert window.operator.refused[-1] == ("jog", "the machine is homing")
    for name in ("start", "home", "spindle_on", "zero_XY"):
        assert not window.controls.buttons[name].isEnabled(), name
    assert window.controls.buttons["stop"].isEnabled()
    qtbot.waitUntil(lambda: _status(window).homed and _status(window).state == "IDLE", timeout=60_000)
    window.console.flush()
    assert "JOG" not in window.console.log.toPlainText()  # never sent, so never queued
    assert abs(_status(window).x) < 0.01


SOURCE = ("G21 G90\nT1 M6\nM3 S2000\nG0 Z5\nG0 X10 Y10\nG1 Z-1 F300\nG1 X20\nM0\nG0 Z5\nT2 M6\nM3 S2000\n"
          "G0 X30 Y10\nG1 Z-1 F300\nG1 X40\nG0 Z5\nM5\nM2\n")


def test_after_start_here_the_machine_is_free_and_the_next_start_runs(qtbot, connected, tmp_path):
    window = connected
    _home(qtbot, window)
    path = tmp_path / "tools.ngc"
    path.write_text(SOURCE)
    loaded = open_and_wait(qtbot, window, path)
    qtbot.waitUntil(lambda: window.controls.buttons["start"].isEnabled(), timeout=10_000)
    window.program_panel.start_here_requested.emit(12)  # "G0 X30 Y10", after T2 M6
    box = window.start_here.dialog
    said = box.text() + "\n" + box.informativeText()
    assert "line 12 of 17" in said and "Tool T2 must be in the spindle" in said
    assert not window.controls.buttons["home"].isEnabled()  # a dialog waits
    box.buttonClicked.emit(window.start_here.start_button)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=120_000)
    assert window.binder.last_job_event.completed
    qtbot.waitUntil(lambda: _status(window).state == "IDLE" and _status(window).z > 9.9, timeout=60_000)
    with window.link.sim.lock:
        assert not window.link.sim.cnc.job.open  # the machine is not left "IDLE with a job open"
    window.binder.last_job_event = None
    qtbot.waitUntil(lambda: window.controls.buttons["start"].isEnabled(), timeout=10_000)
    window.operator.start()
    qtbot.waitUntil(lambda: window.binder.state in ("STREAMING", "PAUSED") or window.binder.last_job_event,
                    timeout=60_000)
    assert window.binder.last_job_event is None or "BUSY" not in window.binder.last_job_event.reason
    assert loaded.program.device_lines  # the whole program runs this time
    window.operator.stop()
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)


def test_run_from_sd_shows_its_progress_and_can_be_paused_resumed_and_stopped(qtbot, connected, tmp_path):
    window = connected
    _home(qtbot, window)
    lines = ["G01 X10 F120", *[f"G01 X{10 + (i % 2) * 20} Y{i % 7}" for i in range(60)]]
    (tmp_path / "card" / "long.nc").write_text("\n".join(lines) + "\n")
    window.sd_panel.list_requested.emit()
    qtbot.waitUntil(lambda: window.sd_panel.lines_of("long.nc") == len(lines), timeout=20_000)
    when_allowed(qtbot, window, "sd_run", lambda: window.operator.run_from_sd("long.nc"))
    qtbot.waitUntil(lambda: "S" in _status(window).flags and _status(window).done >= 2, timeout=60_000)
    qtbot.waitUntil(lambda: "SD long.nc" in window.status.progress_text.text(), timeout=60_000)
    assert f"/{len(lines)}" in window.status.progress_text.text()  # lines of the card's file
    controls = window.controls.buttons  # (the state table follows the status that says it runs)
    qtbot.waitUntil(lambda: controls["pause"].isEnabled() and controls["stop"].isEnabled(), timeout=60_000)
    assert not any(controls[name].isEnabled() for name in ("start", "home", "zero_XY"))
    assert not window.controls.jog.buttons["X", 1].isEnabled()
    window.operator.pause()
    qtbot.waitUntil(lambda: _status(window).state == "HOLD", timeout=30_000)
    qtbot.waitUntil(lambda: controls["resume"].isEnabled(), timeout=10_000)
    held = _status(window).done
    window.operator.resume()
    qtbot.waitUntil(lambda: _status(window).state == "RUN" and _status(window).done > held, timeout=60_000)
    window.operator.stop()
    qtbot.waitUntil(lambda: _status(window).state == "IDLE" and "S" not in _status(window).flags,
                    timeout=60_000)
    qtbot.waitUntil(lambda: window.binder.sd_job is None, timeout=10_000)
    text = window.status.progress_text.text
    qtbot.waitUntil(lambda: text().startswith("SD long.nc") and text().endswith("remaining —"),
                    timeout=10_000)


def test_mdi_spindle_before_homing_follows_the_spindle_button(qtbot, connected):
    window = connected
    assert not _status(window).homed
    window.console.mdi.setText("M3 S3000")
    window.console.mdi.returnPressed.emit()
    window.console.mdi.setText("G0 X5")  # at once, before the machine answers: nothing queued behind it
    window.console.mdi.returnPressed.emit()
    assert window.operator.refused[-1] == ("mdi", "the spindle is changing speed")
    qtbot.waitUntil(lambda: _status(window).rpm > 1000, timeout=60_000)  # as the Spindle On button
    # The answer and the first status at rest may come in either order: wait for both.
    qtbot.waitUntil(lambda: window.binder.pending_motion is None and _status(window).state == "IDLE",
                    timeout=60_000)
    window.console.mdi.setText("G0 X5")
    window.console.mdi.returnPressed.emit()
    assert window.operator.refused[-1] == ("mdi", "home the machine first")
    assert window.status.currentMessage() == "MDI line refused: home the machine first"
    window.console.mdi.setText("M5")
    window.console.mdi.returnPressed.emit()
    qtbot.waitUntil(lambda: "P" not in _status(window).flags, timeout=60_000)


def test_a_card_run_started_on_the_machine_shows_no_stale_figures(qtbot, connected, tmp_path):
    from app.ui.progress import ProgressView

    window = connected
    _home(qtbot, window)
    window.binder.begin_job(None)
    window.status.set_progress(ProgressView(4, 10, 3.0, 12.0), "", (4, 10))  # an earlier job's figures
    lines = "".join(f"G01 X{10 + 20 * (i % 2)} F150\n" for i in range(40))
    (tmp_path / "card" / "panel.nc").write_text(lines)
    window.link.call("run_from_sd", "panel.nc")  # as the machine's panel starts it: not through the window
    qtbot.waitUntil(lambda: "S" in _status(window).flags, timeout=60_000)
    qtbot.waitUntil(lambda: window.status.progress_text.text() == "no job", timeout=10_000)
    qtbot.waitUntil(lambda: window.controls.buttons["pause"].isEnabled(), timeout=10_000)
    buttons = window.controls.buttons
    assert not buttons["start"].isEnabled() and not buttons["home"].isEnabled()
    window.operator.stop()
    qtbot.waitUntil(lambda: "S" not in _status(window).flags and _status(window).state == "IDLE",
                    timeout=60_000)
