"""Preflight with the real work offset (issue 11): with work zero at machine X50 a file
spanning X 0..120 cannot start; the message names the line, the axis, the direction and
by how much; moving the work zero back lets it start; check mode may override."""

from __future__ import annotations

from tests.ui.conftest import home_when_allowed, open_and_wait, when_allowed

SPEED = 20
SOURCE = "G21 G90\nG0 Z5\nG0 X0 Y0\nG1 Z-1 F600\nG1 X120\nG1 Y20\nG0 Z5\n"


def _idle_at_x(window, x: float) -> bool:
    status = window.binder.status
    return abs(status.x - x) < 0.01 and status.state == "IDLE"


def test_work_zero_at_x50_blocks_start_until_moved_back(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    qtbot.waitUntil(lambda: window.binder.status.homed and _idle_at_x(window, 0.0), timeout=60_000)
    path = tmp_path / "wide.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    start = window.controls.buttons["start"]
    qtbot.waitUntil(lambda: None not in window.preflight.offset, timeout=10_000)
    assert start.isEnabled() and not window.preflight.errors
    when_allowed(qtbot, window, "jog", lambda: window.operator.jog("X", 50.0, 600.0))
    qtbot.waitUntil(lambda: _idle_at_x(window, 50.0), timeout=60_000)
    when_allowed(qtbot, window, "zero", lambda: window.operator.zero("X"))  # work zero at machine X50
    qtbot.waitUntil(lambda: bool(window.preflight.errors), timeout=10_000)
    message = window.preflight.message()
    assert "line 5" in message and "X+" in message and "by 20.000 mm" in message, message
    assert not start.isEnabled()
    assert any(title == "Program leaves the travel" for _, title, _ in window.notifier.messages)
    window.operator.start()  # refused here, nothing sent
    assert window.binder.last_job_event is None and window.binder.state == "READY"
    window.controls.check_mode.setChecked(True)  # a dry run may override, explicitly
    assert not start.isEnabled()
    window.controls.override_travel.setChecked(True)
    assert start.isEnabled()
    window.operator.start()  # the dry run: the machine refuses the line mid-run, cleanly
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert not window.binder.last_job_event.completed
    ended = [text for _, title, text in window.notifier.messages if title == "Job ended"][-1]
    assert "line 5 was refused" in ended and "axis X in the + direction" in ended, ended  # source line
    window.controls.override_travel.setChecked(False)
    window.controls.check_mode.setChecked(False)
    when_allowed(qtbot, window, "jog", lambda: window.operator.jog("X", -50.0, 600.0))  # (the job's
    qtbot.waitUntil(lambda: _idle_at_x(window, -50.0), timeout=60_000)  # end may not show yet)
    when_allowed(qtbot, window, "zero", lambda: window.operator.zero("X"))  # back to machine X0
    qtbot.waitUntil(lambda: not window.preflight.errors, timeout=10_000)
    assert start.isEnabled()


def test_the_check_runs_again_when_the_profile_changes(qtbot, window, tmp_path):
    from dataclasses import replace

    path = tmp_path / "wide.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    assert not window.preflight.errors  # default work offset, 150 mm of X travel
    profile = window.profile
    window.operator.apply_settings(replace(profile, travel=replace(profile.travel, x_max=110.0)))
    assert window.preflight.errors and "X+ leaves the travel by 10.000 mm" in window.preflight.message()
    assert window.preflight.blocks_start()
