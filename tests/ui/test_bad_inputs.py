"""Bad inputs end in a clear message and no crash."""

import json
import os
from pathlib import Path

from app.gcode import load
from app.profile import MachineProfile
from app.ui.settings.dialog import SettingsDialog
from app.ui.settings.store import load_settings, save_settings
from tests.ui.conftest import SAMPLES, open_and_wait


def _failed_open(qtbot, window, path):
    with qtbot.waitSignal(window.loader.failed, timeout=10_000) as blocker:
        window.open_file(path)
    return blocker.args[1]


def test_an_image_is_not_gcode(qtbot, window, notifier):
    text = _failed_open(qtbot, window, SAMPLES / "logo.png")
    assert "not a G-code file" in text
    assert notifier.last()[:2] == ("error", "Cannot open file")
    assert window.loaded is None


def test_prose_is_not_gcode(qtbot, window, notifier, tmp_path):
    path = tmp_path / "letter.txt"
    path.write_text("Dear operator,\nplease cut the star tomorrow.\nThanks!\n")
    text = _failed_open(qtbot, window, path)
    assert "does not look like G-code" in text and "line 1" in text


def test_missing_file(qtbot, window, tmp_path):
    assert "does not exist" in _failed_open(qtbot, window, tmp_path / "gone.ngc")


def test_a_fifo_or_device_is_refused_without_blocking(qtbot, window, tmp_path):
    fifo = tmp_path / "pipe.ngc"
    os.mkfifo(fifo)
    assert "not a regular file" in _failed_open(qtbot, window, fifo)
    assert "not a regular file" in _failed_open(qtbot, window, Path("/dev/zero"))


def test_utf16_file_gets_the_encoding_message(qtbot, window, tmp_path):
    path = tmp_path / "wide.ngc"
    path.write_bytes("G0 X1\nG0 X2\n".encode("utf-16"))
    assert "UTF-16" in _failed_open(qtbot, window, path)


def test_file_with_errors_is_shown_not_run(qtbot, window, notifier, tmp_path):
    path = tmp_path / "tapping.ngc"  # G84 tapping: refused, the spindle cannot reverse
    path.write_text("G21 G90\nG0 X10 Y10\nG84 X20 Y20 Z-1 R1 F100\nG1 X30 Y10 F200\nG1 X30 Y30\n")
    loaded = open_and_wait(qtbot, window, path)
    assert loaded.program.errors and loaded.program.errors[0].line == 3
    assert notifier.last()[1] == "Program has errors"
    problems = window.program_panel.problems
    model = problems.model()
    assert model.rowCount() >= 1
    assert model.index(0, 0).data() == "3" and model.index(0, 2).data() == "error"
    problems.activated.emit(model.index(0, 0))
    assert window.program_panel.source.currentIndex().row() == 2
    window.operator.start()
    assert notifier.last()[1] == "Program has errors"


def test_problem_double_click_highlights_the_move(qtbot, window, tmp_path):
    path = tmp_path / "warn.ngc"
    path.write_text("G21 G90\nG0 X10 Y10\nG1 X500 Y10 F200\nG1 X10 Y20\n")  # X 500 is off the table
    loaded = open_and_wait(qtbot, window, path)
    assert loaded.program.warnings
    problems = window.program_panel.problems
    problems.activated.emit(problems.model().index(0, 0))
    x, _ = window.preview.highlight_item.getData()
    assert max(x) >= 500 - 1e-6


def test_a_port_that_is_not_there(qtbot, window, notifier):
    # (no waitSignal on the worker's signals: its callback would run in the worker thread)
    window.operator.connect_to("/dev/ttyUSB_that_was_unplugged")
    qtbot.waitUntil(lambda: (notifier.last() or ("", ""))[1] == "Cannot connect", timeout=10_000)
    assert window.connection.button.text() == "Connect"
    assert "disconnected" in window.connection.link.text()


def test_port_discovery_failure_still_lists_the_simulator(monkeypatch):
    import app.comm.transport as transport
    from app.ui.ports import available_ports

    def broken():
        raise OSError("udev went away")

    monkeypatch.setattr(transport, "list_ports", broken)
    assert available_ports()[0][0] == "sim://"


def test_settings_value_out_of_range_is_named(qtbot):
    dialog = SettingsDialog(MachineProfile())
    qtbot.addWidget(dialog)
    dialog.show()
    dialog.edits["pid", "kp"].setText("99999")
    dialog.edits["link", "heartbeat_s"].setText("fast")
    dialog.accept()
    assert dialog.isVisible()
    assert "kp = '99999' is out of range 0..10000" in dialog.error.text()
    assert "not a number" in dialog.error.text()
    dialog.edits["pid", "kp"].setText("12.5")
    dialog.edits["link", "heartbeat_s"].setText("0.5")
    with qtbot.waitSignal(dialog.accepted):
        dialog.accept()
    assert dialog.profile.pid.kp == 12.5 and dialog.profile.link.heartbeat_s == 0.5


def test_corrupt_settings_file_falls_back_to_defaults(qtbot, make_window, notifier, tmp_path):
    config = tmp_path / "corrupt"
    config.mkdir()
    (config / "settings.json").write_text('{"version": 1, "profile": {"pid": {"kp": ')
    window = make_window(config_dir=config)
    assert window.profile == MachineProfile()
    level, title, text = notifier.last()
    assert (level, title) == ("warning", "Settings") and "damaged" in text and "defaults" in text


def test_out_of_range_settings_file_falls_back_to_defaults(tmp_path):
    path = tmp_path / "settings.json"
    path.write_text(json.dumps({"version": 1, "profile": {"pid": {"kp": -5}}}))
    loaded = load_settings(path)
    assert loaded.profile == MachineProfile() and "kp" in loaded.problem


def test_settings_round_trip_and_old_version(tmp_path):
    path = tmp_path / "settings.json"
    profile = MachineProfile()
    from dataclasses import replace

    changed = replace(profile, pid=replace(profile.pid, kp=3.0))
    save_settings(path, changed)
    assert load_settings(path).profile == changed
    path.write_text(json.dumps({"motion": {"arc_tolerance_mm": 0.02}}))  # version 0: the bare profile
    assert load_settings(path).profile.motion.arc_tolerance_mm == 0.02


def test_samples_have_no_errors():
    for path in SAMPLES.glob("*.ngc"):
        assert not load(path).errors, path
