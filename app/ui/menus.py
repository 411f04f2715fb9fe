"""Menus and shortcuts for everything: File, Machine, View, Help."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QFileDialog, QMenu, QMessageBox

from app.ui.jog_panel import JOG_KEYS
from app.ui.palette import toggle_dark
from app.ui.recent import recent_files
from app.ui.settings.tools_dialog import open_tool_table

FILTER = ("G-code (*.ngc *.nc *.gcode *.gc *.tap *.cnc *.txt);;Point lists (*.xyz *.txt *.csv *.dat);;"
          "All files (*)")


def _action(window, menu: QMenu, text: str, slot, shortcut=None, tip: str = "") -> QAction:
    action = QAction(text, window)
    if shortcut:
        action.setShortcut(QKeySequence(shortcut))
    if tip:
        action.setStatusTip(tip)
    action.triggered.connect(slot)
    menu.addAction(action)
    return action


def build_menus(window) -> dict[str, QAction]:
    actions: dict[str, QAction] = {}
    _file_menu(window, window.menuBar().addMenu("&File"), actions)
    _machine_menu(window, window.menuBar().addMenu("&Machine"), actions)
    _view_menu(window, window.menuBar().addMenu("&View"), actions)
    _help_menu(window, window.menuBar().addMenu("&Help"), actions)
    return actions


def _file_menu(w, menu: QMenu, actions) -> None:
    actions["open"] = _action(w, menu, "&Open…", lambda: open_dialog(w), QKeySequence.StandardKey.Open)
    recent = menu.addMenu("Open &recent")
    recent.aboutToShow.connect(lambda: _fill_recent(w, recent))
    tr = QCoreApplication.translate
    actions["features"] = _action(w, menu, tr("FeatureForm", "New from &features…"), lambda: open_features(w),
                                  "Ctrl+Shift+N", tr("FeatureForm", "pockets, slots, islands, hole patterns"))
    actions["reload"] = _action(w, menu, "&Reload", lambda: w.loaded and w.open_file(w.loaded.path), "F5")
    menu.addSeparator()
    actions["save_sd"] = _action(w, menu, "&Save to SD card…", lambda: _show_dock(w, "sd"), "Ctrl+Shift+S")
    actions["screenshot"] = _action(w, menu, "Save screens&hot…", lambda: _screenshot_dialog(w))
    actions["settings"] = _action(w, menu, "Se&ttings…", w.operator.edit_settings, "Ctrl+,")
    actions["tools"] = _action(w, menu, w.tr("Tool ta&ble…"), lambda: open_tool_table(w))
    menu.addSeparator()
    actions["quit"] = _action(w, menu, "&Quit", w.close, QKeySequence.StandardKey.Quit)


def _machine_menu(w, menu: QMenu, actions) -> None:
    op = w.operator
    actions["connect"] = _action(w, menu, "&Connect / disconnect", w.connection.button.click, "Ctrl+K")
    menu.addSeparator()
    actions["home"] = _action(w, menu, "&Home", lambda: op.home("NORMAL"), "Ctrl+H")
    actions["home_recover"] = _action(w, menu, "Home after a &fault", lambda: op.home("RECOVER"))
    actions["start"] = _action(w, menu, "&Start job", op.start, "Ctrl+R")
    actions["pause"] = _action(w, menu, "&Pause (feed hold)", op.pause, "Ctrl+P")
    actions["resume"] = _action(w, menu, "R&esume", op.resume, "Ctrl+Shift+P")
    actions["stop"] = _action(w, menu, "S&top", op.stop, "Esc", "stop and flush at once")
    menu.addSeparator()
    jog = menu.addMenu("&Jog")
    for (axis, sign), key in JOG_KEYS.items():
        name = f"jog_{axis}{'+' if sign > 0 else '-'}"
        actions[name] = _action(w, jog, f"{axis}{'+' if sign > 0 else '−'}",
                                lambda _=False, a=axis, s=sign: w.controls.jog.jog(a, s), key)
    jog.addSeparator()
    for index, step in enumerate(("0.1 mm", "1 mm", "10 mm")):
        actions[f"step_{index}"] = _action(w, jog, f"Step {step}",
                                           lambda _=False, i=index: w.controls.jog.set_step_index(i),
                                           f"Alt+{index + 1}")
    spindle_on = lambda: op.spindle(w.controls.rpm.value())  # noqa: E731
    actions["spindle_on"] = _action(w, menu, "Spindle o&n", spindle_on, "Ctrl+M")
    actions["spindle_off"] = _action(w, menu, "Spindle o&ff", lambda: op.spindle(0), "Ctrl+Shift+M")
    actions["zero_xy"] = _action(w, menu, "Set work zero X&Y here", lambda: op.zero("XY"), "Ctrl+0")
    actions["zero_z"] = _action(w, menu, "Set work zero &Z here", lambda: op.zero("Z"))
    check = _action(w, menu, "Check mode (&dry run)", w.controls.check_mode.toggle)
    actions["check"] = check


def _view_menu(w, menu: QMenu, actions) -> None:
    actions["fit"] = _action(w, menu, "&Fit program", w.preview.fit, "Ctrl+F")
    keys = QKeySequence.StandardKey
    actions["zoom_in"] = _action(w, menu, "Zoom &in", lambda: w.preview.zoom(1.5), keys.ZoomIn)
    actions["zoom_out"] = _action(w, menu, "Zoom &out", lambda: w.preview.zoom(1 / 1.5),
                                  QKeySequence.StandardKey.ZoomOut)
    grid = _action(w, menu, "&Grid", lambda: w.preview.set_grid(grid.isChecked()), "Ctrl+G")
    grid.setCheckable(True)
    actions["grid"] = grid
    menu.addSeparator()
    for dock in w.docks.values():
        menu.addAction(dock.toggleViewAction())
    menu.addSeparator()
    actions["dark"] = _action(w, menu, "&Dark palette", lambda: toggle_dark(w), "Ctrl+Shift+D")
    actions["reset_layout"] = _action(w, menu, "&Reset layout", w.reset_layout)


def _help_menu(w, menu: QMenu, actions) -> None:
    keys = QKeySequence.StandardKey
    actions["guide"] = _action(w, menu, "Operator &guide", lambda: _guide(w), keys.HelpContents)
    actions["about"] = _action(w, menu, "&About", lambda: _about(w))


def open_dialog(w) -> None:
    start = str(w.loaded.path.parent) if w.loaded else str(Path.cwd())
    path, _ = QFileDialog.getOpenFileName(w, "Open G-code", start, FILTER)
    if path:
        w.open_file(path)


def open_features(w) -> None:
    from app.ui.features.hooks import feature_dialog

    feature_dialog(w).show()


def _fill_recent(w, menu: QMenu) -> None:
    menu.clear()
    files = recent_files(w.qsettings)
    for path in files:
        menu.addAction(path, lambda p=path: w.open_file(p))
    if not files:
        menu.addAction("(none yet)").setEnabled(False)


def _show_dock(w, name: str) -> None:
    w.docks[name].show()
    w.docks[name].raise_()


def _screenshot_dialog(w) -> None:
    path, _ = QFileDialog.getSaveFileName(w, "Save screenshot", "cnc-window.png", "PNG (*.png)")
    if path:
        w.grab().save(path)


def _guide(w) -> None:
    w.notifier.info("Operator guide", GUIDE)


def _about(w) -> None:
    QMessageBox.about(w, "About", ABOUT)


ABOUT = (
    "<b>CNC mill controller</b><br>A desktop controller for a small 3-axis mill: G-code preview, "
    "SD upload, streaming over a checked frame protocol with resume after a link loss, and a "
    "simulator of the machine.<br>PySide6 + pyqtgraph. MIT licence."
)
GUIDE = (
    "1. Connect (the built-in simulator is first in the port list).\n"
    "2. File ▸ Open (or drop a file on the window); check the preview and the Problems list.\n"
    "3. Optionally save the program to the SD card (SD card dock).\n"
    "4. Home (Ctrl+H), then Start (Ctrl+R). Pause Ctrl+P, Resume Ctrl+Shift+P, Stop Esc.\n"
    "5. Jog with Ctrl+arrows (X/Y) and Ctrl+PgUp/PgDn (Z); step Alt+1/2/3.\n"
    "If the link drops, the machine holds; reconnect and resume from the alert."
)
