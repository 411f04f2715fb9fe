"""The window as a whole: menus, shortcuts, drag-and-drop, recent files, state."""

from PySide6.QtCore import QMimeData, QPointF, Qt, QUrl
from PySide6.QtGui import QDropEvent

from app.ui.program.summary import format_duration
from app.ui.recent import recent_files
from app.ui.settings.prefs import load_prefs
from tests.ui.conftest import SAMPLE_FILES, open_and_wait


def test_menus_cover_everything(window):
    titles = [a.text().replace("&", "") for a in window.menuBar().actions()]
    assert titles == ["File", "Machine", "View", "Help"]
    shortcuts = {name: a.shortcut().toString() for name, a in window.actions_by_name.items()}
    for name in ("open", "home", "start", "pause", "resume", "stop", "jog_X+", "jog_Z-", "step_0", "fit"):
        assert shortcuts[name], name
    assert shortcuts["stop"] == "Esc"
    assert len(set(s for s in shortcuts.values() if s)) == len([s for s in shortcuts.values() if s])


def test_drop_a_file_on_the_window(qtbot, window):
    mime = QMimeData()
    mime.setUrls([QUrl.fromLocalFile(str(SAMPLE_FILES[0]))])
    event = QDropEvent(QPointF(10, 10), Qt.DropAction.CopyAction, mime, Qt.MouseButton.NoButton,
                       Qt.KeyboardModifier.NoModifier)
    with qtbot.waitSignal(window.loader.loaded, timeout=10_000):
        window.dropEvent(event)
    qtbot.waitUntil(lambda: window.loaded is not None)
    assert window.loaded.path == SAMPLE_FILES[0]


def test_recent_files_newest_first(qtbot, window):
    for path in SAMPLE_FILES[:2]:
        open_and_wait(qtbot, window, path)
    assert recent_files(window)[:2] == [str(SAMPLE_FILES[1]), str(SAMPLE_FILES[0])]
    saved = load_prefs(window.config_dir / "prefs.json").prefs
    assert saved.recent_files[:2] == tuple(recent_files(window)[:2])


def test_window_state_is_restored(qtbot, make_window, tmp_path):
    first = make_window(config_dir=tmp_path / "state")
    first.docks["console"].hide()
    first.save_state()
    second = make_window(config_dir=tmp_path / "state")
    assert second.docks["console"].isHidden()


def test_program_panel_shows_summary_and_follows_the_line(qtbot, window):
    loaded = open_and_wait(qtbot, window, SAMPLE_FILES[0])
    summary = window.program_panel.summary.text()
    assert loaded.path.name in summary and "estimated" in summary and "0 errors" in summary
    model = window.program_panel.source_model
    assert model.rowCount() == len(loaded.program.source_lines)
    window.program_panel.set_current_line(12)
    assert model.current_line == 12
    assert model.data(model.index(11, 0), Qt.ItemDataRole.BackgroundRole) is not None


def test_dark_palette_toggles(qtbot, window):
    from PySide6.QtWidgets import QApplication

    window.actions_by_name["dark"].trigger()
    assert QApplication.instance().property("cnc_dark") is True
    window.actions_by_name["dark"].trigger()
    assert QApplication.instance().property("cnc_dark") is False


def test_the_first_picture_is_drawn_at_screen_tolerance_then_refined(qtbot, window):
    with qtbot.waitSignal(window.loader.refined, timeout=30_000) as refined:
        first = open_and_wait(qtbot, window, SAMPLE_FILES[0])
    fine = refined.args[0]
    assert first.preview.tolerance > window.loader.tolerance  # half a pixel of the view
    assert fine.program is first.program and fine.preview.tolerance == window.loader.tolerance
    qtbot.waitUntil(lambda: window.preview.model is fine.preview)
    assert window.loaded is fine and fine.preview.levels_built


def test_dark_palette_and_recent_files_are_kept_in_prefs_json(qtbot, make_window, tmp_path):
    first = make_window(config_dir=tmp_path / "prefs")
    first.actions_by_name["dark"].trigger()
    open_and_wait(qtbot, first, SAMPLE_FILES[0])
    saved = load_prefs(tmp_path / "prefs" / "prefs.json")
    assert saved.prefs.dark is True and saved.prefs.recent_files == (str(SAMPLE_FILES[0]),)
    assert not first.qsettings.contains("dark") and not first.qsettings.contains("recent_files")
    first.actions_by_name["dark"].trigger()  # back to the light palette for the other tests
    second = make_window(config_dir=tmp_path / "prefs")
    assert second.prefs.recent_files == (str(SAMPLE_FILES[0]),) and second.prefs.dark is False


def test_recent_files_and_dark_move_over_from_window_ini_once(make_window, tmp_path):
    from PySide6.QtCore import QSettings

    old = QSettings(str(tmp_path / "old" / "window.ini"), QSettings.Format.IniFormat)
    old.setValue("recent_files", ["/a.ngc", "/b.ngc"])
    old.setValue("dark", True)
    old.setValue("language", "en")
    old.sync()
    window = make_window(config_dir=tmp_path / "old")
    assert window.prefs.recent_files == ("/a.ngc", "/b.ngc") and window.prefs.dark is True
    assert load_prefs(tmp_path / "old" / "prefs.json").prefs == window.prefs
    window.qsettings.sync()
    assert not window.qsettings.contains("recent_files") and not window.qsettings.contains("dark")
    assert window.qsettings.value("language") == "en"  # the language stays where it was


def test_damaged_prefs_give_the_defaults_and_are_named(make_window, notifier, tmp_path):
    (tmp_path / "bad").mkdir()
    (tmp_path / "bad" / "prefs.json").write_text('{"version": 1, "recent_files": "x", "dark": "yes"}')
    window = make_window(config_dir=tmp_path / "bad")
    assert window.prefs.recent_files == () and window.prefs.dark is False
    level, title, text = notifier.messages[0]
    assert level == "warning" and "prefs.json" in text and "recent_files" in text and "'yes'" in text


def test_the_summary_says_the_planners_time_once_it_is_ready(qtbot, window):
    with qtbot.waitSignal(window.loader.prepared, timeout=60_000) as prepared:
        window.open_file(SAMPLE_FILES[0])
        window.loader.shown()
    said = format_duration(prepared.args[0].program.planned.total)
    qtbot.waitUntil(lambda: said in window.program_panel.summary.text(), timeout=5_000)


def test_the_summary_names_the_program_stops_the_estimate_leaves_out(qtbot, window, tmp_path):
    path = tmp_path / "stops.ngc"
    path.write_text("G21 G90\nM3 S3000\nG1 Z-1 F100\nG1 X20 F300\nM0\nT2 M6\nM3 S3000\nG1 X40\nM5\nM2\n")
    with qtbot.waitSignal(window.loader.prepared, timeout=60_000) as prepared:
        window.open_file(path)
        window.loader.shown()
    planned = prepared.args[0].program.planned
    assert (planned.stops, planned.tool_changes) == (2, 1)
    qtbot.waitUntil(lambda: "program stops: 2 (tool changes: 1), not in the estimate"
                    in window.program_panel.summary.text(), timeout=5_000)
