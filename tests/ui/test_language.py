"""The window in Vietnamese and English (issue 12): a scripted session (connect, open,
run, pause, a link loss, an error, each settings tab) walks every visible text and
fails on any that is still English in Vietnamese, or shows an unfilled placeholder in
either language; switching at run time re-labels menus, panels and the Problems list."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from app import i18n
from app.ui.language import apply_language, saved_language
from app.ui.ports import available_ports
from app.ui.settings.dialog import ORDER
from app.ui.settings.tools_dialog import open_tool_table
from tests.ui.conftest import SAMPLES, open_and_wait, pace
from tests.ui.untranslated import english_in_vietnamese, placeholders
from tests.ui.visible import all_texts

SPEED = 40
BAD = "G0 X10 Y10\nG1 Z-1 F100\nG1 X155 Y10\nG1 A5\nG2 X20 Y20\n"  # one travel warning, two errors


def _click(qtbot, button):
    assert button.isEnabled(), button.text()
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def _session(qtbot, window, tmp_path) -> list[tuple[str, str]]:
    """Drive the window through an operator's session; every text seen on the way."""
    seen = all_texts(window)
    bad = tmp_path / "bad.ngc"
    bad.write_text(BAD)
    open_and_wait(qtbot, window, bad)
    seen += all_texts(window)
    sd = tmp_path / "sd"
    sd.mkdir()
    window.connection.ports.setEditText(f"sim://?speed={SPEED}&sd={sd}")
    _click(qtbot, window.connection.button)
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    window.operator.start()  # refused: the program has errors
    seen += all_texts(window)
    open_and_wait(qtbot, window, SAMPLES / "arcs_circles.ngc")
    window.operator.start()  # refused: not homed
    _click(qtbot, window.sd_panel.save)
    qtbot.waitUntil(lambda: window.sd_panel.files.topLevelItemCount() == 1, timeout=60_000)
    _click(qtbot, window.controls.buttons["home"])
    qtbot.waitUntil(lambda: window.binder.status.homed and window.binder.status.state == "IDLE",
                    timeout=60_000)
    told = len(window.notifier.messages)
    window.operator.jog("X", -50.0, 300.0)  # past the travel: the machine refuses (soft limit)
    qtbot.waitUntil(lambda: len(window.notifier.messages) > told, timeout=60_000)
    pace(window, 5.0)  # the job lasts over half a minute: paused, resumed and unplugged mid-run
    _click(qtbot, window.controls.buttons["start"])
    qtbot.waitUntil(lambda: window.binder.job_done >= 5, timeout=60_000)
    _click(qtbot, window.controls.buttons["pause"])
    qtbot.waitUntil(lambda: window.binder.status.state == "HOLD", timeout=60_000)
    seen += all_texts(window)
    _click(qtbot, window.controls.buttons["resume"])
    qtbot.waitUntil(lambda: window.binder.job_done >= 20, timeout=60_000)
    window.link.sim.faults.unplug()
    qtbot.waitUntil(window.alert.isVisible, timeout=60_000)
    seen += all_texts(window, window.alert)
    window.link.sim.faults.replug()
    _click(qtbot, window.alert.reconnect)
    qtbot.waitUntil(lambda: window.alert.resume.isVisible() or window.alert.restart.isVisible(),
                    timeout=60_000)
    seen += all_texts(window.alert)
    _click(qtbot, window.alert.abandon)
    window.actions_by_name["guide"].trigger()  # Help ▸ Operator guide (a message)
    for action in window.menuBar().actions():  # menus filled on opening (Open recent)
        for sub in action.menu().actions():
            if sub.menu() is not None:
                sub.menu().aboutToShow.emit()
    seen += all_texts(window) + _settings_texts(qtbot, window) + _tool_table_texts(qtbot, window)
    seen += [(f"notifier.{level}", text) for level, title, text in window.notifier.messages]
    seen += [(f"notifier.{level}.title", title) for level, title, text in window.notifier.messages]
    window.operator.disconnect()
    return seen


def _settings_texts(qtbot, window) -> list[tuple[str, str]]:
    dialog = window.operator.edit_settings()
    qtbot.waitExposed(dialog)
    seen = []
    for index in range(len(ORDER)):  # each tab shown in turn
        dialog.tabs.setCurrentIndex(index)
        seen += all_texts(dialog)
    edit = next(iter(dialog.edits.values()))
    edit.setText("abc")
    dialog.accept()  # refused: the value is named and the dialog stays
    assert dialog.isVisible() and dialog.error.text()
    seen += all_texts(dialog)
    dialog.reject()
    return seen


def _tool_table_texts(qtbot, window) -> list[tuple[str, str]]:
    dialog = open_tool_table(window)
    qtbot.waitExposed(dialog)
    dialog.add_row(1, 6.0)
    dialog.add_row(2, 3.0)
    dialog.table.item(1, 1).setText("-4")  # out of range: named, in the operator's language
    dialog.table.item(0, 2).setText("abc")  # not a number
    dialog.accept()
    assert dialog.isVisible() and dialog.error.text()
    seen = all_texts(dialog)
    dialog.reject()
    return seen


@pytest.mark.slow
def test_vietnamese_session_shows_no_english(qtbot, make_window, tmp_path):
    window = make_window(port_lister=available_ports)
    window.set_language("vi")
    seen = _session(qtbot, window, tmp_path)
    assert len(seen) > 300
    assert "\n".join(english_in_vietnamese(seen)) == ""
    assert "\n".join(placeholders(seen)) == ""
    assert any("Về gốc máy" in text for _, text in seen)


@pytest.mark.slow
def test_english_session_has_no_placeholders(qtbot, make_window, tmp_path):
    window = make_window(port_lister=available_ports)
    seen = _session(qtbot, window, tmp_path)
    assert "\n".join(placeholders(seen)) == ""
    assert any(text == "Home" for _, text in seen)


def test_switching_language_relabels_menus_panels_and_problems(qtbot, window, tmp_path):
    bad = tmp_path / "bad.ngc"
    bad.write_text(BAD)
    open_and_wait(qtbot, window, bad)
    menus = [a.text() for a in window.menuBar().actions()]
    problem = window.program_panel.problems.model().index(0, 3).data()
    assert menus[0] == "&File" and window.docks["program"].windowTitle() == "Program"
    window.set_language("vi")
    assert [a.text() for a in window.menuBar().actions()][:3] == ["&Tệp", "&Máy", "&Xem"]
    assert window.docks["program"].windowTitle() == "Chương trình"
    assert window.controls.buttons["home"].text() == "Về gốc máy"
    assert window.program_panel.tabs.tabText(1) == "Sự cố (2 lỗi, 1 cảnh báo)"
    vietnamese = [window.program_panel.problems.model().index(i, 3).data() for i in range(3)]
    assert vietnamese[0] == "máy này không có trục A (chỉ có X, Y và Z)"
    assert "vượt hành trình trục X" in vietnamese[2]
    assert "dòng" in window.program_panel.summary.text() and "0.00" not in window.program_panel.summary.text()
    assert window.qsettings.value("language") == "vi" and saved_language(window.qsettings) == "vi"
    window.set_language("en")
    assert [a.text() for a in window.menuBar().actions()][0] == "&File"
    assert window.program_panel.problems.model().index(0, 3).data() == problem
    assert window.program_panel.tabs.tabText(1) == "Problems (2 errors, 1 warning)"


def test_numbers_follow_the_language_and_entry_takes_both(qtbot, window):
    from app.ui.numbers import decimal, parse_number

    window.status.set_position(12.5, -3.25, 1234.0)
    assert "12.500" in window.status.position.text()
    window.set_language("vi")
    assert "12,500" in window.status.position.text() and decimal(0.1, 1) == "0,1"
    axis = window.position_plot.plot.getAxis("left")
    assert axis.tickStrings([0.5, 1.0], 1.0, 0.5) == ["0,5", "1,0"]
    typed = ("1,5", "1.5", "1.234,5", "1,234.5")
    assert [parse_number(t) for t in typed] == ["1.5", "1.5", "1234.5", "1234.5"]
    dialog = window.operator.edit_settings()
    dialog.edits["pid", "kd"].setText("0,07")
    dialog.accept()
    assert not dialog.isVisible() and window.profile.pid.kd == pytest.approx(0.07)


def test_core_messages_follow_the_window(qtbot, window):
    message = i18n.msg("line {line}, column {column}", line=3, column=7)
    assert i18n.localize(message) == "line 3, column 7"
    window.set_language("vi")
    assert i18n.localize(message) == "dòng 3, cột 7"
    assert window.connection.ports.itemText(0)  # the port list is re-read in the language


def test_language_remembered_and_system_default(qtbot, make_window, tmp_path):
    first = make_window(config_dir=tmp_path / "c")
    first.set_language("vi")
    first.save_state()
    second = make_window(config_dir=tmp_path / "c")
    assert saved_language(second.qsettings) == "vi"
    apply_language(saved_language(second.qsettings))
    assert second.windowTitle() == "Điều khiển máy phay CNC"


def test_machine_codes_in_the_operators_language(qtbot, window):
    from app.ui.codes import alarm_text, refusal_text

    assert refusal_text("NOT_HOMED", "home first") == "the machine is not homed (NOT_HOMED: home first)"
    window.set_language("vi")
    assert refusal_text("NOT_HOMED", "home first") == "máy chưa về gốc (NOT_HOMED)"
    assert refusal_text("SOFT_LIMIT", "X+ 151.200 > 150") == (
        "lệnh di chuyển sẽ vượt hành trình (giới hạn mềm): "
        "trục X theo chiều +: 151,200 mm vượt quá giới hạn 150 mm")
    assert alarm_text("COVER_OPEN", "") == "nắp che đang mở: không được phép chuyển động (COVER_OPEN)"


def test_system_locale_decides_until_the_operator_chooses(qtbot, window, monkeypatch):
    from PySide6.QtCore import QLocale

    from app.ui import language
    from app.ui.main import parse_args

    monkeypatch.setattr(language.QLocale, "system", staticmethod(lambda: QLocale("vi_VN")))
    assert saved_language(window.qsettings) == "vi"
    window.set_language("en")
    assert saved_language(window.qsettings) == "en"
    assert parse_args(["--lang", "vi"]).lang == "vi" and parse_args([]).lang is None


def test_the_window_fonts_have_every_letter_of_the_translation(qapp):
    from PySide6.QtGui import QFontDatabase, QFontInfo, QFontMetrics
    from PySide6.QtWidgets import QApplication

    from tests.ui.untranslated import I18N, _po_pairs, _ts_pairs

    pairs = _ts_pairs(I18N / "cnc_vi.ts") + _po_pairs(I18N / "vi" / "LC_MESSAGES" / "cnc.po")
    letters = {c for _, forms in pairs for form in forms for c in form if ord(c) > 127 and c.isalpha()}
    assert {"ệ", "ố", "ữ", "đ", "ạ"} <= letters
    for font in (QApplication.font(), QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont)):
        metrics = QFontMetrics(font)
        missing = sorted(c for c in letters if not metrics.inFontUcs4(ord(c)))
        assert missing == [], f"{QFontInfo(font).family()} lacks {''.join(missing)}"
