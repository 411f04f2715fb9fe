"""Issue 21, hold-to-jog in the window: the jog buttons in the "Hold" mode and the arrow
and PageUp/PageDown keys jog while held and stop on release; two keys jog the
diagonal; the state table's "jog_hold" control keeps a held button enabled during its
own jog and refuses a press during a job. On the simulator at 1x (the keep-alives run
on the simulated clock of the worker)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLineEdit

from app.ui.jog_panel import HOLD_MODE
from app.ui.state_table import Inputs, Link, Machine, decide


@pytest.fixture
def connected(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed=1&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    qtbot.waitUntil(lambda: window.binder.status.state == "IDLE", timeout=60_000)
    return window


def state(window) -> str:
    return window.binder.status.state


def test_the_state_table_allows_hold_to_jog_idle_and_during_its_own_jog_only():
    up = Inputs(link=Link.UP, homed=True)
    assert decide("jog_hold", up).allowed
    assert decide("jog_hold", Inputs(link=Link.UP, machine=Machine.JOG)).allowed
    assert not decide("jog", Inputs(link=Link.UP, machine=Machine.JOG)).allowed
    for machine in (Machine.RUN_HOST, Machine.HOLD, Machine.COVER_OPEN, Machine.ALARM, Machine.HOMING):
        assert not decide("jog_hold", Inputs(link=Link.UP, machine=machine, homed=True)).allowed
    assert not decide("jog_hold", Inputs(link=Link.DEGRADED)).allowed


def test_a_held_button_jogs_and_its_release_stops_it(qtbot, connected):
    window, panel = connected, connected.controls.jog
    window.actions_by_name["step_3"].trigger()  # Alt+4: the Hold mode
    assert panel.step_group.checkedId() == HOLD_MODE and panel.hold_mode
    button = panel.buttons["X", 1]
    x0 = window.binder.status.x
    qtbot.mousePress(button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: state(window) == "JOG" and window.binder.status.x > x0 + 1.0, timeout=20_000)
    assert button.isEnabled()  # the state table keeps it: its release must come
    qtbot.mouseRelease(button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: state(window) == "IDLE", timeout=5_000)
    x = window.binder.status.x
    assert "no keep-alive" not in window.console.log.toPlainText()
    qtbot.wait(400)  # no motion after the release: a fixed look, not a condition
    assert abs(window.binder.status.x - x) < 0.01
    assert not panel.held


def test_two_arrow_keys_jog_the_diagonal_and_step_mode_still_steps(qtbot, connected):
    window, panel = connected, connected.controls.jog
    start = window.binder.status
    target = panel.buttons["X", 1]  # a key event for any control of the window, not a text field
    qtbot.keyPress(target, Qt.Key.Key_Right)
    qtbot.keyPress(target, Qt.Key.Key_Up)
    assert panel.held == {"X+", "Y+"}
    moved = lambda: window.binder.status.x > start.x + 1.0 and window.binder.status.y > start.y + 1.0  # noqa: E731
    qtbot.waitUntil(lambda: state(window) == "JOG" and moved(), timeout=20_000)
    status = window.binder.status
    assert abs((status.x - start.x) - (status.y - start.y)) < 0.2  # the diagonal
    qtbot.keyRelease(target, Qt.Key.Key_Up)
    qtbot.keyRelease(target, Qt.Key.Key_Right)
    assert not panel.held
    qtbot.waitUntil(lambda: state(window) == "IDLE", timeout=5_000)
    x = window.binder.status.x
    window.actions_by_name["step_1"].trigger()  # 1 mm steps stay
    window.actions_by_name["jog_X+"].trigger()
    qtbot.waitUntil(lambda: state(window) == "IDLE" and abs(window.binder.status.x - x - 1.0) < 0.05,
                    timeout=20_000)


def test_keys_typed_into_a_field_are_the_field_s(qtbot, connected):
    window, panel = connected, connected.controls.jog
    field = window.console.mdi
    assert isinstance(field, QLineEdit) and field.isEnabled()
    field.setFocus()
    for key in (Qt.Key.Key_Left, Qt.Key.Key_Up, Qt.Key.Key_PageDown):  # Up goes on to the parents
        qtbot.keyPress(field, key)
        assert not panel.held
        qtbot.keyRelease(field, key)


def test_the_cover_ends_a_held_jog_and_refuses_the_next_press(qtbot, connected):
    window, panel = connected, connected.controls.jog
    sim = window.link.sim
    target = panel.buttons["X", 1]
    qtbot.keyPress(target, Qt.Key.Key_Right)
    qtbot.waitUntil(lambda: state(window) == "JOG", timeout=20_000)
    sim.panel.set_cover(True)
    qtbot.waitUntil(lambda: "C" in window.binder.status.flags and sim.cnc.mc.state == "IDLE", timeout=5_000)
    qtbot.keyRelease(target, Qt.Key.Key_Right)
    qtbot.keyPress(target, Qt.Key.Key_Right)
    assert window.operator.refused[-1] == ("jog_hold", "the cover is open")
    assert not panel.held
    qtbot.keyRelease(target, Qt.Key.Key_Right)
    sim.panel.set_cover(False)
