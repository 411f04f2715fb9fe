"""The window on a GRBL machine without homing (``$22=0``, issue 23): it starts unlocked
and refuses ``$H``, so Start asks for no homing, and the check before Start does not
hold the program against a travel its power-up coordinates say nothing of."""

from __future__ import annotations

from tests.ui.conftest import open_and_wait
from tests.ui.test_grbl_features import WAIT, connect_grbl, unlocked


def test_start_needs_no_homing_and_no_travel_check_on_a_machine_without_homing(qtbot, make_window, tmp_path):
    window, machine = connect_grbl(qtbot, make_window)
    unlocked(qtbot, window)
    path = tmp_path / "far.ngc"
    path.write_text("G21 G90\nG0 Z-15\nG0 X500 Y10\nG0 Z-15\nM2\n")  # X500: past a 150 mm travel
    open_and_wait(qtbot, window, path)
    start = window.controls.buttons["start"]
    qtbot.waitUntil(window.preflight.blocks_start, timeout=WAIT)
    assert not window.binder.status.homed and not start.isEnabled()
    window.link.call("send_command", "$22=0")  # homing off: its coordinates are where it powered up
    qtbot.waitUntil(lambda: machine.settings[22] == 0, timeout=WAIT)
    qtbot.waitUntil(lambda: window.binder.status.homed, timeout=WAIT)  # nothing to home
    qtbot.waitUntil(start.isEnabled, timeout=WAIT)
    assert not window.preflight.blocks_start() and not window.grbl.alarm.homing
