"""The window's GRBL features end to end on the simulated GRBL machine (issue 23): the $$
settings dialog (send-and-wait, refusals in words, backup and restore with the diff
first), the alarm banner and unlock, door and hold states in words, $# and $G into the
DRO and the live modal panel, the overrides sliders on 0x90-0x9D."""

from __future__ import annotations

import pytest

from app.comm.driver import FRAME_CAPABILITIES, GRBL_CAPABILITIES
from app.ui.connection_bar import DRIVERS
from app.ui.state_table import Inputs, Link, Machine, decide

WAIT = 30_000


def connect_grbl(qtbot, make_window):
    window = make_window(port_lister=lambda: [("sim://grbl?speed=30", "GRBL")])
    bar = window.connection
    bar.driver.setCurrentIndex([key for key, _ in DRIVERS].index("grbl"))
    bar.button.click()
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=WAIT)
    qtbot.waitUntil(lambda: len(window.grbl.settings) > 20, timeout=WAIT)
    return window, window.link.sim.machine


def systems_read(dro) -> bool:
    """The DRO has the machine's six work systems."""
    return bool(dro.systems.supported) and None not in dro.systems.rows[59]


def with_systems_in_check_mode(qtbot, make_window):
    """Connected, unlocked, the work systems read, then check mode on."""
    window, machine = connect_grbl(qtbot, make_window)
    unlocked(qtbot, window)
    qtbot.waitUntil(lambda: systems_read(window.dro), timeout=WAIT)
    window.controls.check_mode.setChecked(True)
    qtbot.waitUntil(lambda: machine.check_mode, timeout=WAIT)
    return window, machine


def unlocked(qtbot, window):
    qtbot.waitUntil(lambda: window.grbl.alarm.shown, timeout=WAIT)
    window.grbl.alarm.buttons["unlock"].click()
    qtbot.waitUntil(lambda: window.binder.status.state == "IDLE" and not window.grbl.alarm.shown,
                    timeout=WAIT)


def test_settings_are_edited_one_write_at_a_time_and_a_refusal_is_said_in_words(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    dialog = window.grbl.open_settings()  # allowed in alarm: GRBL takes $x= idle or in alarm
    assert dialog is not None and dialog.table.rowCount() == len(window.grbl.settings)
    row = next(r for r in range(dialog.table.rowCount()) if dialog.table.item(r, 0).text() == "$110")
    assert dialog.table.item(row, 2).text() == "mm/min" and "X" in dialog.table.item(row, 3).text()
    dialog.table.item(row, 1).setText("512,5")  # a decimal comma as typed in Vietnamese
    dialog.want({111: "520", 0: "1"})  # $0=1: under GRBL's 3 us, refused (error:6)
    assert [dialog.changes.item(i).text() for i in range(dialog.changes.count())] == [
        "$0 (step pulse time): 10 -> 1", "$110 (X maximum rate): 600.000 -> 512.500",
        "$111 (Y maximum rate): 600.000 -> 520"]
    dialog.send_changes()
    qtbot.waitUntil(lambda: dialog.in_flight is None, timeout=WAIT)
    assert "refused" in dialog.note.text() and "at least 3 microseconds" in dialog.note.text()
    assert sorted(dialog.pending) == [0, 110, 111]  # nothing after the refusal was written, all kept
    assert machine.settings[110] == 600
    dialog.want({0: "10"})
    dialog.send_changes()
    qtbot.waitUntil(lambda: not dialog.pending and dialog.in_flight is None, timeout=WAIT)
    assert machine.settings[110] == 512.5 and machine.settings[111] == 520
    assert machine.lost_to_eeprom == 0  # nothing was sent while the machine wrote its EEPROM
    qtbot.waitUntil(lambda: window.grbl.settings.get(110) == "512.500", timeout=WAIT)  # read again


def test_backup_and_restore_show_the_diff_first_and_send_only_what_changed(qtbot, make_window, tmp_path):
    window, machine = connect_grbl(qtbot, make_window)
    dialog = window.grbl.open_settings()
    backup = tmp_path / "mill.txt"
    assert dialog.back_up(str(backup))
    text = backup.read_text()
    assert "$130=150.000\n" in text and "$22=1\n" in text
    backup.write_text(text.replace("$130=150.000", "$130=140.000").replace("$24=100.000", "$24=90")
                      + "$99=1 ; a grblHAL setting\n")
    written = []
    window.link.worker.command_finished.connect(lambda r: written.append(r.verb) if "=" in r.verb else None)
    assert dialog.restore(str(backup))
    assert [dialog.changes.item(i).text() for i in range(dialog.changes.count())] == [
        "$24 (homing locate feed): 100.000 -> 90", "$130 (X maximum travel): 150.000 -> 140"]
    assert "$99" in dialog.note.text() and machine.settings[130] == 150  # nothing sent yet
    dialog.send_changes()
    qtbot.waitUntil(lambda: not dialog.pending and dialog.in_flight is None, timeout=WAIT)
    assert machine.settings[130] == 140 and machine.settings[24] == 90
    assert sorted(written) == ["$130=140", "$24=90"]


@pytest.mark.parametrize("content, where", [
    ("$0=10\n$1=25\n$110=fast\n", "line 3"), ("$0=10\n$0=12\n", "line 2"), ("; nothing\n", "no '$n=value'"),
])
def test_a_malformed_backup_is_refused_naming_file_and_line_and_nothing_changes(
        qtbot, make_window, tmp_path, content, where):
    window, machine = connect_grbl(qtbot, make_window)
    dialog = window.grbl.open_settings()
    path = tmp_path / "broken.txt"
    path.write_text(content)
    assert not dialog.restore(str(path))
    assert "broken.txt" in dialog.note.text() and where in dialog.note.text()
    assert not dialog.pending and dialog.changes.count() == 0


def test_a_missing_backup_is_named(qtbot, make_window, tmp_path):
    window, _machine = connect_grbl(qtbot, make_window)
    dialog = window.grbl.open_settings()
    assert not dialog.restore(str(tmp_path / "gone.txt"))
    assert "gone.txt: no such file" in dialog.note.text() and not dialog.pending


def test_the_frame_protocols_mill_has_no_settings_table_and_says_why():
    verdict = decide("machine_settings", Inputs(Link.UP, Machine.IDLE, True, capabilities=FRAME_CAPABILITIES))
    assert not verdict.allowed and "File > Settings" in verdict.reason
    assert not decide("unlock", Inputs(Link.UP, Machine.ALARM, capabilities=FRAME_CAPABILITIES)).allowed


def test_the_alarm_is_explained_before_unlock_and_reset_comes_first_after_a_limit(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    bar = window.grbl.alarm
    qtbot.waitUntil(lambda: bar.shown, timeout=WAIT)
    assert "locked until it is homed" in bar.label.text() and bar.buttons["unlock"].isEnabled()
    assert not window.notifier.messages
    unlocked(qtbot, window)
    window.link.sim.trip_limit("X")
    qtbot.waitUntil(lambda: bar.shown and bar.code == 1, timeout=WAIT)
    assert "hard limit" in bar.label.text() and "reset" in bar.label.text()
    assert bar.buttons["unlock"].isHidden() and not bar.buttons["reset"].isHidden()
    assert not [m for m in window.notifier.messages if m[1] == "Machine alarm"]  # the banner, no second box
    bar.buttons["reset"].click()
    qtbot.waitUntil(lambda: bar.code is None and not bar.buttons["home"].isHidden(), timeout=WAIT)
    qtbot.waitUntil(lambda: window.grbl.actions["unlock"].isEnabled(), timeout=WAIT)  # locked after the reset
    window.grbl.actions["unlock"].trigger()
    qtbot.waitUntil(lambda: window.binder.status.state == "IDLE" and not bar.shown, timeout=WAIT)
    assert not window.grbl.actions["unlock"].isEnabled()  # nothing to unlock now, and the tooltip says so
    assert "not in alarm" in window.grbl.actions["unlock"].toolTip()


def test_door_and_hold_states_are_said_in_the_status_bar(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    unlocked(qtbot, window)
    window.link.sim.set_door(True)
    qtbot.waitUntil(lambda: "safety door open" in window.status.currentMessage(), timeout=WAIT)
    window.link.sim.set_door(False)
    closed = "safety door closed: Resume goes on"
    qtbot.waitUntil(lambda: closed in window.status.currentMessage(), timeout=WAIT)
    window.operator.resume()
    qtbot.waitUntil(lambda: window.binder.status.state == "IDLE" and not window.grbl.why, timeout=WAIT)


def test_offsets_and_modal_state_come_from_dollar_hash_and_dollar_g(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    dro, panel = window.dro, window.live_panel
    qtbot.waitUntil(lambda: bool(dro.systems.supported) and None not in dro.systems.rows[59], timeout=WAIT)
    assert dro.systems.active == 54 and dro.systems.rows[54] == [0.0, 0.0, 20.0]  # the mill's work offset
    assert panel.values["codes"].text() == "G0 G17 G21 G90 G54 G40"
    window.grbl.alarm.buttons["home"].click()  # a work zero needs the machine homed
    qtbot.waitUntil(lambda: window.binder.status.homed and window.binder.status.state == "IDLE", timeout=WAIT)
    dro.edit_row(55, "Y", 12.5)
    qtbot.waitUntil(lambda: dro.systems.rows[55][1] == 12.5, timeout=WAIT)
    assert machine.gcode.offsets[1][1] == pytest.approx(12.5 - 150)
    dro.select(55)
    qtbot.waitUntil(lambda: dro.systems.active == 55 and "G55" in panel.values["codes"].text(), timeout=WAIT)
    window.operator.zero("X")  # G10 L20 P2: the work zero of the active system, here
    here = machine.mpos()[0]
    qtbot.waitUntil(lambda: machine.gcode.offsets[1][0] == pytest.approx(here, abs=1e-3), timeout=WAIT)
    assert machine.gcode.offsets[0][0] == pytest.approx(-150)  # G54 untouched
    assert panel.values["g92"].text() == "not in force"
    qtbot.waitUntil(lambda: dro.systems.rows[55][0] == pytest.approx(here + 150, abs=1e-3), timeout=WAIT)


def test_override_sliders_drive_grbls_real_time_bytes_and_show_what_it_reports(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    unlocked(qtbot, window)
    panel = window.controls.overrides
    for percent in (110, 127, 133):  # quicker than the reports: each step from what the machine will have
        panel.request("FEED", percent)
    panel.request("SPINDLE", 80)
    panel.request("RAPID", 25)
    qtbot.waitUntil(lambda: window.binder.status.overrides == (133, 80, 25), timeout=WAIT)
    assert machine.overrides == [133, 25, 80]  # GRBL's own order: feed, rapid, spindle
    qtbot.waitUntil(lambda: "feed 133 %, spindle 80 %, rapid 25 %" in panel.machine.text(), timeout=WAIT)


def test_the_override_panel_takes_the_drivers_ranges(qtbot):
    from app.ui.overrides_panel import OverridesPanel

    panel = OverridesPanel()
    qtbot.addWidget(panel)
    sent = []
    panel.override_requested.connect(lambda verb, pct: sent.append((verb, pct)))
    assert panel.sliders["SPINDLE"].minimum() == 50 and panel.sliders["SPINDLE"].maximum() == 150
    panel.set_ranges(GRBL_CAPABILITIES)
    assert [(s.minimum(), s.maximum()) for s in panel.sliders.values()] == [(10, 200), (10, 200)]
    for _ in range(12):
        panel.step("SPINDLE", -10)
    for _ in range(12):
        panel.step("FEED", 10)
    assert sent[-13] == ("SPINDLE", 10) and sent[-1] == ("FEED", 200)
    panel.set_ranges(FRAME_CAPABILITIES)  # the mill again: the 10 % shown becomes 50, not sent
    assert panel.value("SPINDLE") == 50 and len(sent) == 24
    panel.step("SPINDLE", 10)
    panel.step("SPINDLE", 100)
    assert sent[-2:] == [("SPINDLE", 60), ("SPINDLE", 150)]
    assert FRAME_CAPABILITIES.override_range("RAPID") == (25, 50, 100)
    assert FRAME_CAPABILITIES.override_range("FEED") == range(10, 201)


def test_a_grbl_window_sets_the_spindle_below_the_mills_fifty_percent(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    unlocked(qtbot, window)
    panel = window.controls.overrides
    assert panel.sliders["SPINDLE"].minimum() == 10
    for _ in range(7):
        panel.step("SPINDLE", -10)
    qtbot.waitUntil(lambda: window.binder.status.overrides == (100, 30, 100), timeout=WAIT)
    assert machine.overrides == [100, 100, 30]


def test_the_consoles_stream_box_turns_the_workers_verbose_frames_on_and_off(qtbot, make_window):
    window, _machine = connect_grbl(qtbot, make_window)
    console, worker = window.console, window.link.worker
    reports = lambda: "← <" in console.log.toPlainText()  # noqa: E731 (GRBL's status reports)
    console.flush()
    assert not worker.verbose_frames and not reports()
    console.show_stream.setChecked(True)
    qtbot.waitUntil(reports, timeout=WAIT)
    assert worker.verbose_frames
    console.show_stream.setChecked(False)
    qtbot.waitUntil(lambda: not worker.verbose_frames, timeout=WAIT)


def test_g92_from_dollar_hash_reaches_the_live_modal_panel_after_an_mdi_line(qtbot, make_window):
    window, machine = connect_grbl(qtbot, make_window)
    window.grbl.alarm.buttons["home"].click()
    qtbot.waitUntil(lambda: window.binder.status.homed and window.binder.status.state == "IDLE", timeout=WAIT)
    window.link.call("send_command", "G92 X5")  # as another sender would leave it (programs expand G92 here)
    qtbot.waitUntil(lambda: machine.gcode.g92[0] != 0, timeout=WAIT)
    window.operator.mdi("G0 Z-1")  # a job's end reads $# and $G again
    qtbot.waitUntil(lambda: window.live_panel.values["g92"].text().startswith("X"), timeout=WAIT)
    assert window.live_panel.values["g92"].text() == f"X{machine.gcode.g92[0]:g} Y0 Z0"


def test_the_grbl_features_speak_vietnamese(qtbot, make_window):
    from app.ui.language import apply_language

    apply_language("vi")
    window, _machine = connect_grbl(qtbot, make_window)
    bar = window.grbl.alarm
    qtbot.waitUntil(lambda: bar.shown, timeout=WAIT)
    assert bar.label.text().startswith("MÁY ĐANG KHÓA (báo động): Máy khởi động ở trạng thái khóa")
    assert bar.buttons["unlock"].text() == "Mở khóa ($X)"
    dialog = window.grbl.open_settings()
    row = next(r for r in range(dialog.table.rowCount()) if dialog.table.item(r, 0).text() == "$130")
    assert dialog.table.item(row, 3).text() == "hành trình tối đa trục X"
    dialog.table.item(row, 1).setText("140,5")  # typed with a decimal comma
    assert dialog.changes.item(0).text().startswith("$130 (hành trình tối đa trục X): 150.000 -> 140.5")
    assert window.grbl.actions["machine_settings"].text() == "Cài đặt của &máy ($$)…"


def test_on_the_mill_the_grbl_controls_are_off_with_a_word_why(qtbot, window):
    window.connection.button.click()  # the built-in simulator of the student mill
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=WAIT)
    qtbot.waitUntil(lambda: window.binder.inputs().link is Link.UP, timeout=WAIT)
    settings, unlock = window.grbl.actions["machine_settings"], window.grbl.actions["unlock"]
    assert not settings.isEnabled() and "its settings are in File > Settings" in settings.toolTip()
    assert not unlock.isEnabled() and "no alarm lock" in unlock.toolTip()
    assert window.grbl.open_settings() is None and window.grbl.dialog is None
    assert not window.grbl.alarm.shown


def test_a_check_mode_line_keeps_the_work_systems_grbl_will_not_print_then(qtbot, make_window):
    window, _machine = with_systems_in_check_mode(qtbot, make_window)
    dro = window.dro
    window.operator.mdi("G0 Z-1")
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=WAIT)
    assert window.binder.last_job_event.completed
    qtbot.waitUntil(lambda: panel_codes(window).startswith("G0 "), timeout=WAIT)  # $G read again
    assert dro.systems.supported and dro.systems.rows[54] == [0.0, 0.0, 20.0]


def panel_codes(window) -> str:
    return window.live_panel.values["codes"].text()
