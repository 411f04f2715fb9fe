"""Start reads a relative first move from where the machine stands (issue 19): after a
jog, ``G91 G00 Z-2`` as a job, and as an MDI line, is sent as one Z move from there."""

from __future__ import annotations

from tests.ui.conftest import open_and_wait


def _jogged(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed=50&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    window.controls.check_mode.setChecked(True)
    for axis, distance in (("X", 14.5), ("Z", 10)):
        before = getattr(window.binder.status, axis.lower())
        window.operator.jog(axis, distance, 900)
        def arrived(a=axis, b=before, d=distance):
            status = window.binder.status
            return abs(getattr(status, a.lower()) - b - d) < 0.01 and status.state == "IDLE"

        qtbot.waitUntil(arrived, timeout=60_000)
    return window.binder.status


def _executed(window):
    with window.link.sim.lock:
        return [line for _, line in window.link.sim.exec_log]


def test_start_sends_a_relative_first_move_from_the_machine_position(qtbot, window, tmp_path):
    status = _jogged(qtbot, window, tmp_path)
    path = tmp_path / "retract.ngc"
    path.write_text("G91 G00 Z-2\nG90 G00 X20\n")
    loaded = open_and_wait(qtbot, window, path)
    assert loaded.program.device_lines == ["G00 Z-2", "G00 X20"]  # read from the origin
    assert "Z moves relative" in window.status.currentMessage()
    window.operator.start()
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert _executed(window)[-2:] == [f"G00 Z{status.z - 2:g}", "G00 X20"]


def test_an_mdi_relative_move_starts_from_the_machine_position(qtbot, window, tmp_path):
    status = _jogged(qtbot, window, tmp_path)
    window.operator.mdi("G91 G0 Z-1.5")
    qtbot.waitUntil(lambda: len(_executed(window)) >= 1, timeout=60_000)
    assert _executed(window)[-1] == f"G00 Z{status.z - 1.5:g}"
