"""The cover in the window (issue 11): opened mid-job, the banner and the status say so,
the spindle stops, every moving command is refused at once, no link alert; closed,
nothing restarts until Resume, then the job completes."""

from __future__ import annotations

from tests.ui.conftest import home_when_allowed, open_and_wait

SPEED = 20
SOURCE = "G21 G90\nM3 S3000\nG0 Z5\nG0 X10 Y10\nG1 Z-1 F300\nG1 X120 F100\nG1 Y60\nG0 Z5\nM5\nM2\n"
# (the long cut, 3.3 s at SPEED 20, outlasts a window that lags on a busy host: at F200 the job
# once ended, 1.7 s after it began, before the cover opened)


def test_cover_open_mid_job_banner_refusals_and_resume(qtbot, window, tmp_path):
    status = lambda: window.binder.status  # noqa: E731
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    path = tmp_path / "cover.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    window.operator.start()
    qtbot.waitUntil(lambda: status().done >= 3 and status().rpm > 2500, timeout=60_000)
    sim = window.link.sim
    sim.panel.set_cover(True)
    qtbot.waitUntil(lambda: window.cover_banner.bar.isVisible(), timeout=60_000)
    assert "COVER OPEN" in window.status.currentMessage()
    qtbot.waitUntil(lambda: status().rpm == 0 and status().state == "HOLD", timeout=60_000)
    assert sim.panel.oled_text()[0] == "COVER OPEN"
    before = len(window.notifier.messages)
    window.operator.jog("X", 1.0, 300.0)  # the window refuses them itself: nothing is sent
    window.operator.spindle(1000)
    assert window.operator.refused[-2:] == [("jog", "the cover is open"), ("spindle_on", "the cover is open")]
    assert "refused: the cover is open" in window.status.currentMessage()
    window.link.call("jog", "X", 1.0, 300.0)  # and the machine refuses them too, were they sent
    window.link.call("send_command", "SPINDLE 1000")
    qtbot.waitUntil(lambda: len([m for m in window.notifier.messages[before:] if "COVER_OPEN" in m[2]]) == 2,
                    timeout=10_000)
    held_at = status().done
    sim.panel.set_cover(False)
    qtbot.waitUntil(lambda: not window.cover_banner.bar.isVisible(), timeout=10_000)
    # a status relayed from before the spindle stopped may still arrive (the main MCU's may be
    # a little old): the machine must be held, spindle off, and nothing run on
    qtbot.waitUntil(lambda: status().state == "HOLD" and status().rpm == 0, timeout=10_000)
    assert status().done == held_at
    window.operator.resume()
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=120_000)
    assert window.binder.last_job_event.completed
    assert not window.alert.isVisible() and window.binder.link_state == "CONNECTED"
