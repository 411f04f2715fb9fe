"""Custom command buttons in the window (issue 21): read from commands.json, edited in
the dialog and saved, run as a job once allowed and (when asked for) confirmed."""

from __future__ import annotations

from PySide6.QtCore import Qt

from app.ui.settings.commands import CustomCommand, load_commands, save_commands
from tests.ui.conftest import home_when_allowed

SPEED = 20


def _connect_and_home(qtbot, window, tmp_path) -> None:
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    qtbot.waitUntil(lambda: window.binder.status.homed and window.binder.status.state == "IDLE"
                    and window.binder.state == "READY", timeout=60_000)


def test_buttons_run_their_lines_or_file_after_the_operator_s_yes(qtbot, make_window, tmp_path):
    config = tmp_path / "config"
    config.mkdir()
    program = tmp_path / "park.ngc"
    program.write_text("G21 G90\nG00 X5 Y6\n")
    save_commands(config / "commands.json", (
        CustomCommand("Lift", gcode="G00 Z-3", confirm=True),
        CustomCommand("Park", file=str(program)),
        CustomCommand("Missing", file=str(tmp_path / "nowhere.ngc"))))
    window = make_window(config_dir=config)
    bar, custom = window.custom_bar, window.custom_commands
    assert [b.text() for b in bar.buttons] == ["Lift", "Park", "Missing"]
    assert not bar.buttons[0].isEnabled()  # not connected: the state table says no
    _connect_and_home(qtbot, window, tmp_path)
    window.link.call("send_command", "SET AFTERJOB 0")  # no lift after each job: Z stays where sent
    asked = []
    custom.ask = lambda parent, title, text: asked.append(text) or False  # the operator says no
    qtbot.mouseClick(bar.buttons[0], Qt.MouseButton.LeftButton)
    assert asked == ["Run “Lift” now?"] and window.binder.last_job_event is None
    custom.ask = lambda parent, title, text: True
    qtbot.mouseClick(bar.buttons[0], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    qtbot.waitUntil(lambda: window.binder.state == "READY" and window.binder.status.state == "IDLE",
                    timeout=60_000)
    assert abs(window.binder.status.z + 3.0) < 0.01
    window.binder.last_job_event = None
    qtbot.mouseClick(bar.buttons[1], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    qtbot.waitUntil(lambda: window.binder.state == "READY" and window.binder.status.state == "IDLE",
                    timeout=60_000)
    assert abs(window.binder.status.x - 5.0) < 0.01 and abs(window.binder.status.y - 6.0) < 0.01
    window.binder.last_job_event = None
    assert not custom.run(bar.commands[2])
    title, text = window.notifier.messages[-1][1:]
    assert "Missing" in text and "nowhere.ngc" in text and window.binder.last_job_event is None


def test_the_dialog_edits_checks_and_saves(qtbot, window):
    dialog = window.custom_commands.edit()
    qtbot.mouseClick(dialog.add, Qt.MouseButton.LeftButton)
    dialog.name.setText("Spindle off")
    dialog.name.textEdited.emit("Spindle off")
    dialog.accept()  # no lines, no file: refused, the dialog stays open
    assert dialog.isVisible() and "Spindle off" in dialog.problem.text()
    dialog.gcode.setPlainText("M05")
    dialog.confirm.setChecked(True)
    dialog.accept()
    assert not dialog.isVisible()
    assert [b.text() for b in window.custom_bar.buttons] == ["Spindle off"]
    saved = load_commands(window.config_dir / "commands.json").commands
    assert saved == (CustomCommand("Spindle off", gcode="M05", confirm=True),)


def test_a_bad_file_is_told_and_the_good_commands_kept(qtbot, make_window, tmp_path):
    config = tmp_path / "config"
    config.mkdir()
    (config / "commands.json").write_text('{"version": 1, "commands": [{"name": "ok", "gcode": "M05"},'
                                          ' {"name": "bad"}]}')
    window = make_window(config_dir=config)
    assert [b.text() for b in window.custom_bar.buttons] == ["ok"]
    assert any("command 2" in text for _, _, text in window.notifier.messages)
