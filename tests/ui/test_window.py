"""The window as a whole: menus, shortcuts, drag-and-drop, recent files, state."""

from PySide6.QtCore import QMimeData, QPointF, Qt, QUrl
from PySide6.QtGui import QDropEvent

from app.ui.recent import recent_files
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
    assert recent_files(window.qsettings)[:2] == [str(SAMPLE_FILES[1]), str(SAMPLE_FILES[0])]


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
