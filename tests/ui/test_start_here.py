"""Start here (issue 11): right-click a source line, the confirmation shows the restored
state, Start runs the preamble and the lines from there; progress counts from there."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QMenu

from app.comm.modal import restart_preamble
from tests.ui.conftest import OFFSCREEN_NOISE, open_and_wait

SOURCE = ("G21 G90\nM3 S2500\nG0 Z5\nG0 X20 Y20\nG1 Z-1 F300\nG1 X60 F400\nG0 Z5\nG0 X30 Y60\n"
          "G1 Z-2 F200\nG1 X50\nG0 Z5\nM5\nM2\n")


def test_start_here_confirms_the_restored_state_and_runs_from_the_line(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed=50&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    window.controls.check_mode.setChecked(True)
    path = tmp_path / "part.ngc"
    path.write_text(SOURCE)
    loaded = open_and_wait(qtbot, window, path)
    lines = loaded.program.device_lines
    window.program_panel.start_here_requested.emit(9)  # "G1 Z-2 F200", as the context menu does
    box = window.start_here.dialog
    assert box is not None and box.isVisible()
    k = window.start_here.pending
    assert lines[k] == "G01 Z-2 F200"
    text = box.text() + "\n" + box.informativeText()
    assert "line 9" in text and "S2500" in text and "F400" in text and "X30.000 Y60.000" in text
    qtbot.mouseClick(window.start_here.start_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert window.binder.last_job_event.completed
    with window.link.sim.lock:
        executed = [line for _, line in window.link.sim.exec_log]
    assert executed == restart_preamble(lines, k) + lines[k:]
    assert window.binder.tracker.first == k and window.binder.tracker.view(0).percent == 100.0


@pytest.mark.qt_log_ignore(*OFFSCREEN_NOISE, "does not support grabbing the keyboard")  # a popup, offscreen
def test_the_source_listing_offers_start_here(qtbot, window, tmp_path):
    path = tmp_path / "part.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    view = window.program_panel.source
    assert view.contextMenuPolicy() == Qt.ContextMenuPolicy.CustomContextMenu
    action = window.program_panel.start_here_action
    assert not action.isEnabled() and "not connected" in action.toolTip()  # the state table's word
    action.setEnabled(True)  # as the table enables it once connected and homed
    with qtbot.waitSignal(window.program_panel.start_here_requested, timeout=5000) as blocker:
        row = window.program_panel.source_model.index(3, 0)
        window.program_panel._source_menu(view.visualRect(row).center())
        popup = next(w for w in QApplication.topLevelWidgets() if isinstance(w, QMenu) and w.isVisible())
        popup.actions()[0].trigger()
        popup.close()
    assert blocker.args == [4]
