"""A GRBL machine's link cut mid-job, in the window (issue 23): GRBL has no heartbeat, so
no status report for 2 s is "degraded" and 3 s "lost", with the same alert as the
student mill; once the machine answers again the window offers Start here at the line
after the last one known finished (its ok came back and a report showed its motion
done), says that GRBL cannot resume exactly, and the restart runs each line once."""

from __future__ import annotations

import pytest

from app.comm.events import ResumeOffer
from app.comm.grbl.dialect import grbl_lines
from tests.ui.grbl_rig import homed_window, lines_run

MOVES = 150


def _program(tmp_path):
    moves = "".join(f"G01 X{10 + (i % 2) * 2} Y{10 + i * 0.5:g}\n" for i in range(MOVES))
    path = tmp_path / "long.ngc"
    path.write_text(f"G21 G90\nG00 X10 Y10 Z5\nM03 S1000\nG01 Z-1 F120\n{moves}G00 Z5\nM05\nM02\n")
    return path


@pytest.fixture
def grbl_job(qtbot, make_window, tmp_path):
    """The window homed on the simulated GRBL machine, a long job running."""
    window = homed_window(qtbot, make_window, _program(tmp_path))
    window.operator.start()
    session = window.link.worker.session
    qtbot.waitUntil(lambda: session.job is not None and session.job.acked >= 30, timeout=60_000)
    return window


def test_silence_degrades_then_loses_the_link_then_offers_start_here(qtbot, grbl_job):
    window, binder = grbl_job, grbl_job.binder
    sim = window.link.sim
    links = []
    window.link.worker.link_changed.connect(lambda event: links.append(event.state))
    sim.wires["usb_up"].set_cut(True)  # the machine goes on with its buffer; nothing comes back
    qtbot.waitUntil(lambda: binder.link_state == "DEGRADED", timeout=10_000)
    assert not window.alert.isVisible()  # degraded only: no alert yet
    qtbot.waitUntil(lambda: binder.link_state == "LOST", timeout=10_000)
    assert links[-2:] == ["DEGRADED", "LOST"]
    assert window.alert.isVisible() and "no status report for 3 s" in window.alert.body.text()
    assert "does not notice that this computer is gone" in window.alert.body.text()
    # the session says LOST, then INTERRUPTED: two queued signals, which a busy window may
    # not yet have handled both of when the first is seen
    qtbot.waitUntil(lambda: binder.state == "INTERRUPTED", timeout=5_000)
    qtbot.waitUntil(lambda: sim.machine.motion.state == "IDLE", timeout=60_000)  # its buffer ran
    sim.wires["usb_up"].set_cut(False)
    qtbot.waitUntil(lambda: window.alert.restart.isVisible(), timeout=20_000)
    session = window.link.worker.session
    job = session.last_job
    said = window.alert.body.text()
    assert "GRBL cannot resume a job exactly" in said
    line = binder.source_line(job.done + 1)
    assert f"line {line} of" in said and window.alert.restart.text() == f"Start here at line {line}"
    assert job.done == job.acked  # idle after the cut: every answered line has finished
    restart_runs_each_line_once(qtbot, window, job.done + 1)


def restart_runs_each_line_once(qtbot, window, start: int) -> None:
    """Start here (device line ``start``) runs the lines from there once, behind the modes."""
    binder = window.binder
    program = window.loaded.program
    expected = [g.text for g in grbl_lines(program.device_lines) if g.text]
    before = len(lines_run(window))
    window.alert.restart.click()
    qtbot.waitUntil(lambda: binder.last_job_event is not None and binder.state == "READY", timeout=120_000)
    assert binder.last_job_event.completed, binder.last_job_event
    restarted = lines_run(window)[before:]
    assert restarted[:2] == ["G54", "M03 S1000"]  # the work system and spindle before the line come first
    assert restarted[-(len(expected) - start):] == expected[start:]  # then each line once, in order


def _pace(sim, speed: float) -> None:
    with sim.lock:
        sim.clock.set_speed(speed)
        sim.wake()


def test_the_offered_line_follows_what_the_machine_finishes_after_the_offer(qtbot, grbl_job):
    window, binder = grbl_job, grbl_job.binder
    sim = window.link.sim
    _pace(sim, 1)  # the buffer now lasts many seconds: the offer comes while it still runs
    sim.wires["usb_up"].set_cut(True)
    qtbot.waitUntil(lambda: binder.link_state == "LOST", timeout=10_000)
    sim.wires["usb_up"].set_cut(False)
    qtbot.waitUntil(lambda: window.alert.restart.isVisible(), timeout=20_000)
    first = window.alert.restart.text()
    assert sim.machine.motion.state != "IDLE"
    _pace(sim, 30)
    qtbot.waitUntil(lambda: sim.machine.motion.state == "IDLE", timeout=60_000)
    job = window.link.worker.session.last_job
    qtbot.waitUntil(lambda: job.done == job.acked, timeout=10_000)  # the idle report came
    line = binder.source_line(job.done + 1)
    qtbot.waitUntil(lambda: window.alert.restart.text() == f"Start here at line {line}", timeout=10_000)
    assert first != window.alert.restart.text() and f"line {line} of" in window.alert.body.text()
    restart_runs_each_line_once(qtbot, window, job.done + 1)


def test_a_failed_port_then_reconnect_offers_start_here(qtbot, grbl_job):
    window, binder = grbl_job, grbl_job.binder
    sim = window.link.sim
    sim.host_port.set_unplugged(True)  # the cable pulled: the port fails
    qtbot.waitUntil(lambda: window.alert.isVisible() and window.alert.reconnect.isVisible(), timeout=10_000)
    assert "serial port" in window.alert.body.text() and binder.state == "INTERRUPTED"
    sim.host_port.set_unplugged(False)
    window.alert.reconnect.click()
    qtbot.waitUntil(lambda: window.alert.restart.isVisible(), timeout=30_000)
    assert "GRBL cannot resume a job exactly" in window.alert.body.text()
    window.alert.abandon.click()  # the operator abandons it instead
    binder.on_resume_offer(ResumeOffer(False, 3, 2, 10, False))  # already on its way: not shown again
    assert not window.alert.isVisible()
    qtbot.waitUntil(lambda: binder.state == "READY", timeout=10_000)
    assert not window.alert.isVisible()
    qtbot.waitUntil(lambda: binder.last_job_event is not None, timeout=10_000)
    assert not binder.last_job_event.completed and binder.tracker.ended is not None  # the clock stops


def test_the_grbl_alert_in_vietnamese(qtbot, window):
    from tests.ui.untranslated import english_in_vietnamese

    window.set_language("vi")
    alert = window.alert
    alert.show_lost("report_silence", True, host_watch=False, last_state="RUN")
    lost = alert.body.text()
    alert.show_restart_offer(12, 40, needs_home=True)
    offer = [alert.body.text(), alert.restart.text()]
    alert.show_restart_offer(12, 40, needs_home=False)
    assert alert.restart.text() == "Chạy từ dòng 12"
    assert "3 s" in lost and "GRBL không thể" in offer[0] and "12" in offer[0]
    said = [("alert", text) for text in (lost, *offer, alert.restart.text())]
    assert "\n".join(english_in_vietnamese(said)) == ""
