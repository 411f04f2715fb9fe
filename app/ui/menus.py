"""Menus and shortcuts for everything: File, Machine, View, Help."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import QFileDialog, QMenu, QMessageBox

from app.ui.jog_panel import JOG_KEYS
from app.ui.language import LANGUAGES
from app.ui.palette import toggle_dark
from app.ui.recent import recent_files
from app.ui.settings.tools_dialog import open_tool_table

# Every text here is in the "Menus" context; ``retranslate_menus`` re-labels them.
SOURCE_TEXT = "source_text"  # the property holding an action's or menu's untranslated text
SOURCE_TIP = "source_tip"


def _t(text: str) -> str:
    return QCoreApplication.translate("Menus", text)


def file_filter() -> str:
    return QCoreApplication.translate("Menus",
                                      "G-code (*.ngc *.nc *.gcode *.gc *.tap *.cnc *.txt);;"
                                      "Point lists (*.xyz *.txt *.csv *.dat);;All files (*)")


def _action(window, menu: QMenu, text: str, slot, shortcut=None, tip: str = "") -> QAction:
    action = QAction(_t(text), window)
    action.setProperty(SOURCE_TEXT, text)
    if shortcut:
        action.setShortcut(QKeySequence(shortcut))
    if tip:
        action.setProperty(SOURCE_TIP, tip)
        action.setStatusTip(_t(tip))
    action.triggered.connect(slot)
    menu.addAction(action)
    return action


def _menu(parent, text: str) -> QMenu:
    menu = parent.addMenu(_t(text))
    menu.menuAction().setProperty(SOURCE_TEXT, text)
    return menu


def build_menus(window) -> dict[str, QAction]:
    actions: dict[str, QAction] = {}
    bar = window.menuBar()
    _file_menu(window, _menu(bar, QT_TRANSLATE_NOOP("Menus", "&File")), actions)
    _machine_menu(window, _menu(bar, QT_TRANSLATE_NOOP("Menus", "&Machine")), actions)
    _view_menu(window, _menu(bar, QT_TRANSLATE_NOOP("Menus", "&View")), actions)
    _help_menu(window, _menu(bar, QT_TRANSLATE_NOOP("Menus", "&Help")), actions)
    return actions


def retranslate_menus(window) -> None:
    """Re-label every action and menu made here in the current language."""
    for action in window.findChildren(QAction):
        text, tip = action.property(SOURCE_TEXT), action.property(SOURCE_TIP)
        if text:
            action.setText(_t(text))
        if tip:
            action.setStatusTip(_t(tip))


def _file_menu(w, menu: QMenu, actions) -> None:
    actions["open"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Open…"),
                              lambda: open_dialog(w), QKeySequence.StandardKey.Open)
    recent = _menu(menu, QT_TRANSLATE_NOOP("Menus", "Open &recent"))
    recent.aboutToShow.connect(lambda: _fill_recent(w, recent))
    actions["features"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "New from &features…"),
                                  lambda: open_features(w), "Ctrl+Shift+N",
                                  QT_TRANSLATE_NOOP("Menus", "pockets, slots, islands, hole patterns"))
    actions["reload"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Reload"),
                                lambda: w.loaded and w.open_file(w.loaded.path), "F5")
    skip = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Block delete: skip lines starting with /"),
                   lambda: _set_block_delete(w, skip.isChecked()))
    skip.setCheckable(True)
    actions["block_delete"] = skip
    menu.addSeparator()
    actions["save_sd"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Save to SD card…"),
                                 lambda: _show_dock(w, "sd"), "Ctrl+Shift+S")
    actions["screenshot"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Save screens&hot…"),
                                    lambda: _screenshot_dialog(w))
    actions["settings"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Se&ttings…"),
                                  w.operator.edit_settings, "Ctrl+,")
    actions["tools"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Tool ta&ble…"),
                               lambda: open_tool_table(w))
    menu.addSeparator()
    actions["quit"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Quit"),
                              w.close, QKeySequence.StandardKey.Quit)


def _machine_menu(w, menu: QMenu, actions) -> None:
    op = w.operator
    actions["connect"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Connect / disconnect"),
                                 w.connection.button.click, "Ctrl+K")
    menu.addSeparator()
    actions["home"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Home"),
                              lambda: op.home("NORMAL"), "Ctrl+H")
    actions["home_recover"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Home after a &fault"),
                                      lambda: op.home("RECOVER"))
    actions["start"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Start job"), op.start, "Ctrl+R")
    actions["pause"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Pause (feed hold)"), op.pause, "Ctrl+P")
    actions["resume"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "R&esume"), op.resume, "Ctrl+Shift+P")
    actions["stop"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "S&top"), op.stop, "Esc",
                              QT_TRANSLATE_NOOP("Menus", "stop and flush at once"))
    menu.addSeparator()
    jog = _menu(menu, QT_TRANSLATE_NOOP("Menus", "&Jog"))
    for (axis, sign), key in JOG_KEYS.items():
        name = f"jog_{axis}{'+' if sign > 0 else '-'}"
        actions[name] = _action(w, jog, f"{axis}{'+' if sign > 0 else '−'}",
                                lambda _=False, a=axis, s=sign: w.controls.jog.jog(a, s), key)
    jog.addSeparator()
    steps = (QT_TRANSLATE_NOOP("Menus", "Step 0.1 mm"), QT_TRANSLATE_NOOP("Menus", "Step 1 mm"),
             QT_TRANSLATE_NOOP("Menus", "Step 10 mm"), QT_TRANSLATE_NOOP("Menus", "Hold to jog"))
    for index, step in enumerate(steps):
        set_step = lambda _=False, i=index: w.controls.jog.set_step_index(i)  # noqa: E731
        actions[f"step_{index}"] = _action(w, jog, step, set_step, f"Alt+{index + 1}")
    spindle_on = lambda: op.spindle(w.controls.rpm.value())  # noqa: E731
    actions["spindle_on"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Spindle o&n"), spindle_on, "Ctrl+M")
    actions["spindle_off"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Spindle o&ff"),
                                     lambda: op.spindle(0), "Ctrl+Shift+M")
    actions["zero_xy"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Set work zero X&Y here"),
                                 lambda: op.zero("XY"), "Ctrl+0")
    actions["zero_z"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Set work zero &Z here"),
                                lambda: op.zero("Z"))
    check = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Check mode (&dry run)"),
                    w.controls.check_mode.toggle)
    actions["check"] = check
    _override_menu(w, _menu(menu, QT_TRANSLATE_NOOP("Menus", "&Overrides")), actions)


# The overrides' shortcuts (issue 21): brackets step the feed (Ctrl: 10 %, Alt: 1 %) and
# Ctrl+backslash resets it; Alt with comma / full stop steps the spindle and Alt+/ resets
# it; Ctrl+Alt+1..3 pick the rapid rate. (Chosen here, not copied from another program.)
OVERRIDE_KEYS = (
    ("override_feed_plus10", QT_TRANSLATE_NOOP("Menus", "Feed +10 %"), "FEED", 10, "Ctrl+]"),
    ("override_feed_minus10", QT_TRANSLATE_NOOP("Menus", "Feed −10 %"), "FEED", -10, "Ctrl+["),
    ("override_feed_plus1", QT_TRANSLATE_NOOP("Menus", "Feed +1 %"), "FEED", 1, "Alt+]"),
    ("override_feed_minus1", QT_TRANSLATE_NOOP("Menus", "Feed −1 %"), "FEED", -1, "Alt+["),
    ("override_feed_reset", QT_TRANSLATE_NOOP("Menus", "Feed 100 %"), "FEED", None, "Ctrl+\\"),
    ("override_spindle_plus10", QT_TRANSLATE_NOOP("Menus", "Spindle +10 %"), "SPINDLE", 10, "Alt+."),
    ("override_spindle_minus10", QT_TRANSLATE_NOOP("Menus", "Spindle −10 %"), "SPINDLE", -10, "Alt+,"),
    ("override_spindle_reset", QT_TRANSLATE_NOOP("Menus", "Spindle 100 %"), "SPINDLE", None, "Alt+/"),
    ("override_rapid_25", QT_TRANSLATE_NOOP("Menus", "Rapid 25 %"), "RAPID", 25, "Ctrl+Alt+1"),
    ("override_rapid_50", QT_TRANSLATE_NOOP("Menus", "Rapid 50 %"), "RAPID", 50, "Ctrl+Alt+2"),
    ("override_rapid_100", QT_TRANSLATE_NOOP("Menus", "Rapid 100 %"), "RAPID", 100, "Ctrl+Alt+3"),
)


def _override_menu(w, menu: QMenu, actions) -> None:
    panel = w.controls.overrides
    for name, text, verb, amount, key in OVERRIDE_KEYS:
        if verb == "RAPID" or amount is None:
            slot = lambda _=False, v=verb, p=amount or 100: panel.request(v, p)  # noqa: E731
        else:
            slot = lambda _=False, v=verb, d=amount: panel.step(v, d)  # noqa: E731
        actions[name] = _action(w, menu, text, slot, key)


def _view_menu(w, menu: QMenu, actions) -> None:
    actions["fit"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Fit program"), w.preview.fit, "Ctrl+F")
    keys = QKeySequence.StandardKey
    actions["zoom_in"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Zoom &in"),
                                 lambda: w.preview.zoom(1.5), keys.ZoomIn)
    actions["zoom_out"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Zoom &out"),
                                  lambda: w.preview.zoom(1 / 1.5),
                                  QKeySequence.StandardKey.ZoomOut)
    grid = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Grid"),
                   lambda: w.preview.set_grid(grid.isChecked()), "Ctrl+G")
    grid.setCheckable(True)
    actions["grid"] = grid
    menu.addSeparator()
    for dock in w.docks.values():
        menu.addAction(dock.toggleViewAction())
    menu.addSeparator()
    actions["dark"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Dark palette"),
                              lambda: toggle_dark(w), "Ctrl+Shift+D")
    actions["reset_layout"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&Reset layout"), w.reset_layout)
    _language_menu(w, _menu(menu, QT_TRANSLATE_NOOP("Menus", "&Language")), actions)


def _language_menu(w, menu: QMenu, actions) -> None:
    """One checkable entry per language, each named in its own language (not translated)."""
    group = QActionGroup(menu)
    for code, name in LANGUAGES.items():
        action = QAction(name, w, checkable=True)
        action.triggered.connect(lambda _=False, c=code: w.set_language(c))
        group.addAction(action)
        menu.addAction(action)
        actions[f"language_{code}"] = action
    menu.aboutToShow.connect(lambda: actions[f"language_{w.language}"].setChecked(True))


def _help_menu(w, menu: QMenu, actions) -> None:
    keys = QKeySequence.StandardKey
    actions["guide"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "Operator &guide"),
                               lambda: _guide(w), keys.HelpContents)
    actions["about"] = _action(w, menu, QT_TRANSLATE_NOOP("Menus", "&About"), lambda: _about(w))


def open_dialog(w) -> None:
    start = str(w.loaded.path.parent) if w.loaded else str(Path.cwd())
    title = QCoreApplication.translate("Menus", "Open G-code")
    path, _ = QFileDialog.getOpenFileName(w, title, start, file_filter())
    if path:
        w.open_file(path)


def open_features(w) -> None:
    from app.ui.features.hooks import feature_dialog

    feature_dialog(w).show()


def _fill_recent(w, menu: QMenu) -> None:
    menu.clear()
    files = recent_files(w)
    for path in files:
        menu.addAction(path, lambda p=path: w.open_file(p))
    if not files:
        menu.addAction(QCoreApplication.translate("Menus", "(none yet)")).setEnabled(False)


def _set_block_delete(w, on: bool) -> None:
    """The block delete switch (off: "/" lines run, as on LinuxCNC and Fanuc controls);
    the open program is loaded again with it."""
    w.loader.block_delete = on
    if w.loaded:
        w.open_file(w.loaded.path)


def _show_dock(w, name: str) -> None:
    w.docks[name].show()
    w.docks[name].raise_()


def _screenshot_dialog(w) -> None:
    title = QCoreApplication.translate("Menus", "Save screenshot")
    images = QCoreApplication.translate("Menus", "PNG image (*.png)")
    path, _ = QFileDialog.getSaveFileName(w, title, "cnc-window.png", images)
    if path:
        w.grab().save(path)


def _guide(w) -> None:
    w.notifier.info(QCoreApplication.translate("Menus", "Operator guide"), _t(GUIDE))


def _about(w) -> None:
    QMessageBox.about(w, QCoreApplication.translate("Menus", "About"), _t(ABOUT))


ABOUT = QT_TRANSLATE_NOOP(
    "Menus",
    "<b>CNC mill controller</b><br>A desktop controller for a small 3-axis mill: G-code preview, "
    "SD upload, streaming over a checked frame protocol with resume after a link loss, and a "
    "simulator of the machine.<br>PySide6 + pyqtgraph. MIT licence."
)
GUIDE = QT_TRANSLATE_NOOP(
    "Menus",
    "1. Connect (the built-in simulator is first in the port list).\n"
    "2. File ▸ Open (or drop a file on the window); check the preview and the Problems list.\n"
    "3. Optionally save the program to the SD card (SD card dock).\n"
    "4. Home (Ctrl+H), then Start (Ctrl+R). Pause Ctrl+P, Resume Ctrl+Shift+P, Stop Esc.\n"
    "5. Jog with Ctrl+arrows (X/Y) and Ctrl+PgUp/PgDn (Z); step Alt+1/2/3.\n"
    "If the link drops, the machine holds; reconnect and resume from the alert."
)
