"""Touch-off at a tool change in the window, on both drivers: at the prompt of ``T2 M6``
the jog and the work zero are enabled; jog Z down, ``ZERO Z``, jog away, Continue: the
moves after the stop run at the new work Z (positions from the statuses), every line
once (docs/protocol.md, "Program stops and tool changes")."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from app.ui.state_table import Machine, decide
from tests.ui.conftest import when_allowed
from tests.ui.grbl_rig import homed_window_with
from tests.ui.test_program_stops import sim_window_with

SOURCE = """G21 G90
M3 S3000
G0 Z5
G0 X20 Y20
G1 Z-1 F300
G1 X30
T2 M6
G1 Y40 F300
G0 Z5
M5
M2
"""
CUT_Z, LONGER_MM = -1.0, 0.5  # the new tool touches the stock 0.5 mm higher


@pytest.fixture
def frame_window(qtbot, window, tmp_path):
    return sim_window_with(qtbot, window, tmp_path, SOURCE)


@pytest.fixture
def grbl_window(qtbot, make_window, tmp_path):
    return homed_window_with(qtbot, make_window, tmp_path, SOURCE)


def _held(window) -> bool:
    status = window.binder.status
    return status is not None and "W" in status.flags and status.state in ("HOLD", "IDLE")


def _touch_off_and_continue(qtbot, window) -> list:
    """Run the job; at the tool change jog Z down, ZERO Z, jog X away, Continue; the
    statuses after Continue."""
    prompt, binder, jog = window.program_stops.prompt, window.binder, window.controls.jog
    window.operator.start()
    qtbot.waitUntil(lambda: prompt.isVisible() and _held(window), timeout=120_000)
    assert "jog" in prompt.informativeText() and "zero" in prompt.informativeText()
    assert not prompt.isModal()
    qtbot.waitUntil(lambda: all(b.isEnabled() for b in jog.buttons.values()), timeout=10_000)
    zero_buttons = [b for k, b in window.controls.buttons.items() if k.startswith("zero_")]
    assert zero_buttons and all(b.isEnabled() for b in zero_buttons)
    assert binder.inputs().machine is Machine.PROGRAM_STOP
    keys = [a for name, a in window.actions_by_name.items() if name.startswith("jog_")]
    assert keys and all(a.isEnabled() for a in keys)  # the keyboard jog
    assert decide("jog_hold", binder.inputs()).allowed and decide("resume", binder.inputs()).allowed
    window.operator.jog("Z", LONGER_MM - binder.status.z, 600.0)  # down to the stock (old work Z 0.5)
    qtbot.waitUntil(lambda: _held(window) and abs(binder.status.z - LONGER_MM) < 0.01, timeout=30_000)
    qtbot.waitUntil(lambda: window.controls.buttons["zero_Z"].isEnabled(), timeout=10_000)
    window.operator.zero("Z")
    qtbot.waitUntil(lambda: _held(window) and abs(binder.status.z) < 0.01, timeout=30_000)
    when_allowed(qtbot, window, "jog", lambda: window.operator.jog("X", 4.0, 600.0))  # (the zero answered)
    qtbot.waitUntil(lambda: _held(window) and binder.status.x > 33.99, timeout=30_000)
    assert window.operator.refused == []
    seen: list = []
    window.link.worker.status_changed.connect(seen.append)
    qtbot.waitUntil(prompt.continue_button.isEnabled, timeout=10_000)
    qtbot.mouseClick(prompt.continue_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: binder.last_job_event is not None, timeout=120_000)
    assert binder.last_job_event.completed, binder.last_job_event
    return seen


def _cut_at_new_zero(seen: list) -> None:
    """The cut after the stop (G1 Y40 at X30) runs at the program's Z under the new zero
    (the statuses read work Z under the offset in force; run under the old offset the
    cut would read a different Z, as the new zero is not the old one)."""
    cut = [s for s in seen if 20.5 < s.y < 39.5 and abs(s.x - 30.0) < 0.05]
    assert cut, [(s.x, s.y, s.z) for s in seen][:20]
    assert all(abs(s.z - CUT_Z) < 0.05 for s in cut), [(s.y, s.z) for s in cut]


def test_touch_off_at_a_tool_change_on_the_frame_protocol(qtbot, frame_window):
    window = frame_window
    seen = _touch_off_and_continue(qtbot, window)
    _cut_at_new_zero(seen)
    with window.link.sim.lock:
        executed = list(window.link.sim.exec_log)
    assert executed == list(enumerate(window.loaded.program.device_lines))


def test_touch_off_at_a_tool_change_on_grbl(qtbot, grbl_window):
    window = grbl_window
    seen = _touch_off_and_continue(qtbot, window)
    _cut_at_new_zero(seen)


def test_hold_to_jog_at_a_tool_change_on_grbl(qtbot, grbl_window):
    """GRBL's hold-to-jog (``$J=`` towards the travel's end, 0x85 on release) at the stop."""
    window = grbl_window
    prompt, binder = window.program_stops.prompt, window.binder
    window.operator.start()
    qtbot.waitUntil(lambda: prompt.isVisible() and _held(window), timeout=120_000)
    top = binder.status.z
    window.operator.jog_hold(("Z-",), 300.0)
    qtbot.waitUntil(lambda: binder.status.z < top - 1.0, timeout=30_000)
    window.operator.jog_hold((), 300.0)
    qtbot.waitUntil(lambda: _held(window), timeout=30_000)
    assert binder.status.z < top - 1.0 and binder.status.state == "IDLE"  # released: at rest, still W
    window.operator.zero("Z")
    qtbot.waitUntil(lambda: _held(window) and abs(binder.status.z) < 0.01, timeout=30_000)
    assert window.operator.refused == []
    seen: list = []
    window.link.worker.status_changed.connect(seen.append)
    qtbot.mouseClick(prompt.continue_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: binder.last_job_event is not None, timeout=120_000)
    assert binder.last_job_event.completed, binder.last_job_event
    _cut_at_new_zero(seen)
