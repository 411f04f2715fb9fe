"""Overrides in the window (issue 21): the panel's buttons, slider and shortcuts send the
absolute value through the state table, the machine applies it, and the panel shows what
the machine's status reports."""

from __future__ import annotations

from PySide6.QtCore import Qt

from app.ui.state_table import Inputs, Link, Machine, decide
from tests.ui.conftest import home_when_allowed, open_and_wait, pace

SPEED = 10
SOURCE = "G21 G90\nM3 S3000\nG0 Z5\nG1 X120 F300\nG1 Y60\nG0 Z5\nM5\nM2\n"


def test_the_state_table_allows_overrides_while_a_job_runs_or_holds():
    for machine in (Machine.RUN_HOST, Machine.RUN_SD, Machine.HOLD, Machine.IDLE):
        assert decide("feed_override", Inputs(Link.UP, machine, homed=True)).allowed
    assert not decide("feed_override", Inputs(Link.UP, Machine.HOMING)).allowed
    assert not decide("rapid_override", Inputs(Link.NONE, Machine.RUN_HOST)).allowed
    assert decide("spindle_override", Inputs(Link.UP, Machine.SPINDLE)).allowed


def test_the_panel_steps_clamps_and_is_off_until_connected(window, qtbot):
    panel = window.controls.overrides
    assert not panel.sliders["FEED"].isEnabled()  # not connected: the state table says no
    assert "Not now" in panel.buttons["FEED"][0].toolTip()
    sent = []
    panel.override_requested.connect(lambda verb, pct: sent.append((verb, pct)))
    panel.step("FEED", 10)
    panel.step("FEED", 1)
    for _ in range(12):
        panel.step("FEED", 10)
    panel.step("SPINDLE", -10)
    panel.step("SPINDLE", -10)
    panel.step("SPINDLE", -10)
    assert sent[:2] == [("FEED", 110), ("FEED", 111)] and sent[-4] == ("FEED", 200)
    assert sent[-3:] == [("SPINDLE", 90), ("SPINDLE", 80), ("SPINDLE", 70)]
    assert window.operator.refused[-1][0] == "spindle_override"  # refused: not connected


def test_overrides_reach_the_machine_and_show_in_the_panel(qtbot, window, tmp_path):
    status = lambda: window.binder.status  # noqa: E731
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and status() is not None, timeout=60_000)
    assert status().overrides == (100, 100, 100)
    home_when_allowed(qtbot, window)
    path = tmp_path / "overrides.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    pace(window, 1.0)  # the job lasts half a minute: it is still running at every step below
    window.operator.start()
    qtbot.waitUntil(lambda: status().state == "RUN" and status().x > 5, timeout=60_000)
    panel = window.controls.overrides
    assert panel.sliders["FEED"].isEnabled()
    qtbot.mouseClick(panel.buttons["FEED"][0], Qt.MouseButton.LeftButton)  # -10
    window.actions_by_name["override_feed_minus10"].trigger()  # the Ctrl+[ shortcut's action
    window.actions_by_name["override_rapid_50"].trigger()
    panel.step("SPINDLE", 10)
    qtbot.waitUntil(lambda: status().overrides == (80, 110, 50), timeout=60_000)
    assert window.link.sim.cnc.mc.planner.feed_scale == 0.8
    qtbot.waitUntil(lambda: "feed 80 %" in panel.machine.text(), timeout=60_000)
    assert panel.sliders["FEED"].value() == 80 and panel.rapid_group.checkedId() == 50
    window.operator.pause()
    qtbot.waitUntil(lambda: status().state == "HOLD", timeout=60_000)
    assert panel.buttons["FEED"][-1].isEnabled()  # usable while held
    window.operator.resume()
    qtbot.waitUntil(lambda: status().state == "RUN", timeout=60_000)
    assert status().overrides == (80, 110, 50)  # kept across the hold
    window.operator.stop()
    qtbot.waitUntil(lambda: status().state == "IDLE", timeout=20_000)
