"""A tool change and the check before Start on a GRBL machine, in the window (issue 23):
GRBL refuses M6, so the stream waits until the machine is idle with the spindle stopped
and the tool lifted, then the tool-change prompt; Continue brings the tool back where the
change began with the spindle running and goes on, each line once.
The check before Start uses the machine's own travel ($130-$132) and its live WCO."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from app.comm.grbl.dialect import grbl_lines
from tests.ui.grbl_rig import homed_window_with, lines_run

SOURCE = """G21 G90
M3 S1000
G0 X20 Y20 Z5
G1 Z-1 F300
G1 X120
T2 M6
G1 Y40
G0 Z5
M5
M2
"""


@pytest.fixture
def grbl_window(qtbot, make_window, tmp_path):
    return homed_window_with(qtbot, make_window, tmp_path, SOURCE)


def test_a_tool_change_waits_for_the_idle_machine_with_the_spindle_stopped(qtbot, grbl_window):
    window = grbl_window
    machine, prompt = window.link.sim.machine, window.program_stops.prompt
    window.operator.start()
    qtbot.waitUntil(prompt.isVisible, timeout=120_000)
    assert machine.motion.state == "IDLE" and machine.motion.spindle_target == 0  # idle, spindle off
    lifted_z = lambda: abs(window.binder.status.z - 5.0) < 0.01  # noqa: E731 (the program's Z5, above the G53 one)
    qtbot.waitUntil(lifted_z, timeout=10_000)
    assert "tool 2" in prompt.text() + " " + prompt.informativeText() and "line 6" in prompt.text()
    qtbot.waitUntil(lambda: "W" in window.binder.status.flags, timeout=10_000)
    assert window.binder.status.state == "IDLE"
    qtbot.mouseClick(prompt.continue_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=120_000)
    assert window.binder.last_job_event.completed, window.binder.last_job_event
    device = [g.text for g in grbl_lines(window.loaded.program.device_lines) if g.text]
    cut = device.index("G01 Y40.000") if "G01 Y40.000" in device else next(
        i for i, line in enumerate(device) if line.startswith("G01 Y40"))
    lifted = ["M05", "G00 Z5.000"]  # the spindle stopped, the tool up for the change
    back = ["M03 S1000", "G00 Z5.000", "G00 X120.000 Y20.000 F300", "G01 Z-1.000 F300"]  # where it began
    assert lines_run(window) == device[:cut] + lifted + back + device[cut:]  # never M06


def test_the_check_before_start_uses_the_machines_own_travel(qtbot, grbl_window):
    window = grbl_window
    start = window.controls.buttons["start"]
    qtbot.waitUntil(start.isEnabled, timeout=20_000)
    assert window.preflight.travel.x_max == 150.0 and window.preflight.offset == [0.0, 0.0, 20.0]
    window.link.call("send_command", "$130=100")  # X travel 100 mm: X120 leaves it
    qtbot.waitUntil(lambda: window.preflight.blocks_start(), timeout=20_000)
    assert not start.isEnabled() and "X" in window.preflight.message()
    window.link.call("send_command", "$130=150")
    qtbot.waitUntil(start.isEnabled, timeout=20_000)
