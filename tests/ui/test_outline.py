"""Issue 21, "Trace the outline" in the window: the button runs the outline as a job
(spindle off, at the job's top Z, the rectangle or the convex hull), checked against the
travel first, held by Pause; refused by the state table before homing."""

from __future__ import annotations

from PySide6.QtCore import Qt

from tests.ui import test_machine_controls
from tests.ui.conftest import open_and_wait, pace

SPEED = 20  # as test_machine_controls' fixture
homed = test_machine_controls.connected  # the fixture: connected at 20x, homed
JOB = "G21 G90\nG00 Z5\nG00 X10 Y10\nM03 S3000\nG01 Z-1 F200\nG01 X40 Y10 F600\nG03 X40 Y30 I0 J10\n" \
      "G01 X10 Y30\nG01 X10 Y10\nG00 Z5\nM05\nM30\n"


def executed(window) -> list[str]:
    with window.link.sim.lock:
        return [line for _, line in window.link.sim.exec_log]


def feed_corners(lines: list[str]) -> list[tuple[float, float]]:
    """Where each G01 line of ``lines`` ends in X and Y (device lines name only what changes)."""
    x = y = None
    out = []
    for line in lines:
        words = {w[0]: float(w[1:]) for w in line.split() if w[0] in "XY"}
        x, y = words.get("X", x), words.get("Y", y)
        if line.startswith("G01"):
            out.append((x, y))
    return out


def open_job(qtbot, window, tmp_path, text=JOB):
    path = tmp_path / "job.ngc"
    path.write_text(text)
    open_and_wait(qtbot, window, path)


def test_outline_traces_the_rectangle_spindle_off_at_the_top_z(qtbot, homed, tmp_path):
    window = homed
    open_job(qtbot, window, tmp_path)
    qtbot.waitUntil(window.outline.button.isEnabled, timeout=10_000)
    before = len(executed(window))
    qtbot.mouseClick(window.outline.button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=120_000)
    assert window.binder.last_job_event.completed
    lines = executed(window)[before:]
    assert not any(line.startswith("M03") for line in lines)
    assert feed_corners(lines) == [(50, 10), (50, 30), (10, 30), (10, 10)]
    assert window.link.sim.cnc.mc.spindle_rpm == 0


def test_outline_convex_hull_and_a_hold_stops_it(qtbot, homed, tmp_path):
    window = homed
    open_job(qtbot, window, tmp_path)
    qtbot.waitUntil(window.outline.button.isEnabled, timeout=10_000)
    window.outline.hull.setChecked(True)
    outline = [line for line in window.outline.program_lines() if line.startswith("G01")]
    pace(window, 1.0)  # the outline takes seconds: the Pause below lands while it runs
    qtbot.mouseClick(window.outline.button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.status.state == "RUN", timeout=60_000)
    qtbot.mouseClick(window.controls.buttons["pause"], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.status.state == "HOLD", timeout=30_000)
    qtbot.mouseClick(window.controls.buttons["stop"], Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert not window.binder.last_job_event.completed
    ran = [line for line in executed(window) if line.startswith("G01")]
    assert len(ran) < len(outline), "the hold did not stop the outline"  # how far: the machine's speed


def test_an_outline_past_the_travel_is_refused_before_anything_is_sent(qtbot, homed, tmp_path):
    window = homed
    far = window.profile.travel.x_max + 50
    open_job(qtbot, window, tmp_path, f"G21 G90\nG00 Z5\nG00 X10 Y10\nG01 X{far:g} Y10 F600\nM30\n")
    window.controls.check_mode.setChecked(True)  # the job itself may run as a dry run past the
    window.controls.override_travel.setChecked(True)  # travel; its outline is still checked
    qtbot.waitUntil(window.outline.button.isEnabled, timeout=10_000)
    before = len(executed(window))
    window.outline.trace()
    level, title, _text = window.notifier.last()
    assert level == "error" and title == "Outline leaves the travel"
    assert len(executed(window)) == before and window.binder.status.state == "IDLE"


def test_outline_is_refused_before_homing(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    path = tmp_path / "job.ngc"
    path.write_text(JOB)
    open_and_wait(qtbot, window, path)
    window.outline.trace()
    assert window.operator.refused[-1] == ("outline", "home the machine first")
    assert not window.outline.button.isEnabled()
