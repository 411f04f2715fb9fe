"""Program stops in the window (issue 11): M0, M1 (optional stop on and off) and T2 M6
hold the job with a prompt naming the line and the tool; Continue goes on; the
simulator's executed log has every line once, in order; the spindle is off during M6."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.ui.conftest import home_when_allowed, open_and_wait, pace, when_allowed

SPEED = 20
SOURCE = """G21 G90
M3 S3000
G0 Z5
G0 X20 Y20
G1 Z-1 F300
G1 X30
M0
G1 Y30
M1
G1 X20
T2 M6
G1 Y20
G0 Z5
M5
M2
"""


def sim_window_with(qtbot, window, tmp_path, source: str, speed: int = SPEED):
    """``window`` on ``sim://`` at ``speed``, homed, with ``source`` open."""
    window.operator.connect_to(f"sim://?speed={speed}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    path = tmp_path / "stops.ngc"
    path.write_text(source)
    open_and_wait(qtbot, window, path)
    return window


@pytest.fixture
def ready(qtbot, window, tmp_path):
    return sim_window_with(qtbot, window, tmp_path, SOURCE)


def _answer_stops(qtbot, window) -> list[tuple]:
    """Run the job, answering every prompt with Continue; (line, text, status) per stop."""
    prompt, seen = window.program_stops.prompt, []
    before = len(window.program_stops.events)
    window.operator.start()
    ended = lambda: window.binder.last_job_event is not None  # noqa: E731
    while True:
        qtbot.waitUntil(lambda: prompt.isVisible() or ended(), timeout=120_000)
        if ended():
            return seen
        event = window.program_stops.events[before + len(seen)]
        status = window.binder.status
        seen.append((event, prompt.text() + " " + prompt.informativeText(), status))
        qtbot.waitUntil(prompt.continue_button.isEnabled, timeout=60_000)  # the status says it waits
        qtbot.mouseClick(prompt.continue_button, Qt.MouseButton.LeftButton)
        qtbot.waitUntil(lambda: not prompt.isVisible(), timeout=10_000)


def _executed(window) -> list[tuple[int, str]]:
    with window.link.sim.lock:
        return list(window.link.sim.exec_log)


def test_stops_hold_with_a_prompt_and_continue(qtbot, ready):
    window = ready
    lines = window.loaded.program.device_lines
    seen = _answer_stops(qtbot, window)
    assert window.binder.last_job_event.completed, window.binder.last_job_event
    assert [event.line for event, _, _ in seen] == ["M00", "M01", "M06 T2"]
    for (event, text, status), source_line in zip(seen, (7, 9, 11), strict=True):
        assert f"line {source_line}" in text and event.line in text
        assert status.state == "HOLD" and "W" in status.flags
    m0_status, tool_text, m6_status = seen[0][2], seen[2][1], seen[2][2]
    assert "P" in m0_status.flags  # M0 keeps the spindle
    assert "P" not in m6_status.flags and "tool 2" in tool_text and "diameter unknown" in tool_text
    assert _executed(window) == list(enumerate(lines))


def test_optional_stop_switch_off_skips_m01(qtbot, ready):
    window = ready
    window.controls.optional_stop.setChecked(False)
    assert window.profile.job.optional_stop == 0
    seen = _answer_stops(qtbot, window)
    assert [event.line for event, _, _ in seen] == ["M00", "M06 T2"]
    assert _executed(window) == list(enumerate(window.loaded.program.device_lines))


def test_stop_job_at_the_prompt_ends_the_job(qtbot, ready):
    window = ready
    prompt = window.program_stops.prompt
    window.operator.start()
    qtbot.waitUntil(prompt.isVisible, timeout=120_000)
    qtbot.mouseClick(prompt.stop_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert not window.binder.last_job_event.completed
    assert [seq for seq, _ in _executed(window)] == list(range(5))


def test_tool_diameter_comes_from_the_tool_table_when_there_is_one(tmp_path):
    from app.gcode import tools
    from app.ui.stop_prompt import tool_diameter

    tools.save_tools(tmp_path / tools.FILE_NAME, {2: tools.Tool(2, 6.0), 3: tools.Tool(3)})
    assert tool_diameter(2, tmp_path) == 6.0
    assert tool_diameter(3, tmp_path) is None and tool_diameter(7, tmp_path) is None
    assert tool_diameter(None, tmp_path) is None


def test_an_sd_run_prompts_too_and_the_panel_ok_closes_the_prompt(qtbot, ready, tmp_path):
    window = ready
    (tmp_path / "stops.nc").write_text("\n".join(window.loaded.program.device_lines) + "\n")
    pace(window, 2.0)  # the move between M00 and M01 outlasts a status period: the machine is seen running
    when_allowed(qtbot, window, "sd_run", lambda: window.operator.run_from_sd("stops.nc"))  # (a refused
    # run, on a busy machine before the state table allows it, would never prompt)
    prompt = window.program_stops.prompt
    qtbot.waitUntil(prompt.isVisible, timeout=120_000)
    assert window.program_stops.events[-1].line == "M00"
    with qtbot.waitSignal(prompt.finished, timeout=60_000):  # closed, however soon M01 follows
        window.link.sim.panel.press("OK")  # answered on the machine instead
    qtbot.waitUntil(prompt.isVisible, timeout=120_000)  # M01: the prompt comes with the machine's
    # notice, the status that says it waits a moment later; Continue is off until then
    when_allowed(qtbot, window, "resume",
                 lambda: qtbot.mouseClick(prompt.continue_button, Qt.MouseButton.LeftButton))
    qtbot.waitUntil(lambda: prompt.isVisible() and window.program_stops.events[-1].tool == 2, timeout=120_000)
    qtbot.mouseClick(prompt.stop_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.link.sim.main.sd_job is None, timeout=30_000)


def test_the_prompt_answers_only_when_the_state_table_allows_them(qtbot, window):
    """An SD run's prompt comes with the machine's notice; until a status says the machine
    waits, Continue is off (a click would be refused and close the prompt) and says why."""
    from app.comm.stops import stop_event

    window.program_stops.on_stop(stop_event(3, "M00"), sd_run=True)
    window.binder.refresh_enabled()
    prompt = window.program_stops.prompt
    assert prompt.isVisible()
    assert not prompt.continue_button.isEnabled() and "Not now" in prompt.continue_button.toolTip()
    assert not prompt.stop_button.isEnabled()  # nothing runs here: not connected
