"""The whole operator story, clicked through the window on the simulator (issue 5):
connect, open a real Inkscape sample, preview, save to SD, home, start, pause (the
machine holds), resume, lose the link mid-job (alert at once, machine stops), reconnect,
resume exactly where it stopped, run to the end (100 %, final point, no line twice)."""

import numpy as np
import pytest
from PySide6.QtCore import Qt

from app.ui.program.summary import bounds_array
from tests.ui.conftest import SAMPLES, open_and_wait

SPEED = 20  # the machine holds 3 wall seconds after the cut: the job must outlast them
JOB_TIMEOUT_MS = 150_000


def _click(qtbot, button):
    assert button.isEnabled(), button.text()
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)


def _status(window):
    return window.binder.status


def _connect(qtbot, window, url):
    window.connection.ports.setEditText(url)
    _click(qtbot, window.connection.button)
    qtbot.waitUntil(lambda: window.binder.connected and _status(window) is not None, timeout=60_000)
    assert "connected" in window.connection.link.text()


@pytest.mark.slow
def test_operator_story(qtbot, window, tmp_path):
    sd = tmp_path / "sd"
    sd.mkdir()
    _connect(qtbot, window, f"sim://?speed={SPEED}&sd={sd}")
    sim = window.link.sim
    assert window.machine_panel.panel is sim.panel

    # Open a real Inkscape sample: the preview shows it, extents = program bounds.
    loaded = open_and_wait(qtbot, window, SAMPLES / "arcs_circles.ngc")
    program = loaded.program
    (xmin, ymin, _), (xmax, ymax, _) = bounds_array(program.toolpath.bounds)
    assert window.preview.plotted_bounds() == pytest.approx((xmin, xmax, ymin, ymax), abs=1e-3)

    # Save to SD: the file on the card is the normalised program.
    assert window.sd_panel.name.text() == "arcs_circles.nc"
    _click(qtbot, window.sd_panel.save)
    try:
        qtbot.waitUntil(lambda: "verified" in window.sd_panel.result.text(), timeout=60_000)
    except qtbot.TimeoutError:  # seen once in a full run, never alone: say what the window showed
        raise AssertionError(f"SD save not verified: panel {window.sd_panel.result.text()!r}, "
                             f"session {window.binder.state}, status {window.binder.status}") from None
    assert (sd / "arcs_circles.nc").read_text() == "\n".join(program.device_lines) + "\n"
    qtbot.waitUntil(lambda: window.sd_panel.files.topLevelItemCount() == 1, timeout=60_000)

    # Home, start.
    _click(qtbot, window.controls.buttons["home"])
    qtbot.waitUntil(lambda: _status(window).homed and _status(window).state == "IDLE", timeout=60_000)
    _click(qtbot, window.controls.buttons["start"])
    qtbot.waitUntil(lambda: window.binder.job_done >= 5, timeout=60_000)

    # Pause: the machine holds (no motion across a second of machine time).
    _click(qtbot, window.controls.buttons["pause"])
    qtbot.waitUntil(lambda: _status(window).state == "HOLD", timeout=60_000)
    held = _wait_still(qtbot, window)
    qtbot.waitUntil(lambda: _status(window).time > held.time + 1.0, timeout=60_000)
    assert np.allclose(_status(window).position, held.position, atol=1e-3)
    assert _status(window).done < len(program.device_lines) - 1
    assert window.controls.buttons["resume"].isEnabled()

    # Resume, then cut the USB link mid-job.
    _click(qtbot, window.controls.buttons["resume"])
    qtbot.waitUntil(lambda: _status(window).state == "RUN", timeout=60_000)
    total = len(program.device_lines)
    qtbot.waitUntil(lambda: window.binder.job_done >= total // 5, timeout=JOB_TIMEOUT_MS)
    # The link notices at once (its own clock, wall-paced, read in the worker's thread as it
    # says so); the window shows it when its event loop comes to it: on a host that stalls
    # the whole machine (seen: 3.1 s in a full run under heavy steal time, 0.2-0.8 s alone)
    # that is later, so the window's part is held to come after, with the cause.
    noticed = []
    window.link.worker.disconnected.connect(lambda _reason: noticed.append(window.link.clock()),
                                            Qt.ConnectionType.DirectConnection)
    cut_at = window.link.clock()
    sim.faults.unplug()
    qtbot.waitUntil(window.alert.isVisible, timeout=60_000)
    assert len(noticed) == 1 and noticed[0] - cut_at <= 3.0
    assert window.binder.alert_clock >= noticed[0]
    said = window.alert.body.text()  # the cause (the port failed), the machine's rule, its last state
    assert "serial port" in said and "holds" in said and "Last state seen: RUN" in said
    # The machine holds on the path, or (its host-lost timer being wall-clock, at 20x) it
    # has already run out of queued lines: either way it stands still mid-job.
    qtbot.waitUntil(lambda: _machine_state(sim) in ("HOLD", "IDLE"), timeout=60_000)

    # Reconnect and resume exactly where it stopped.
    sim.faults.replug()
    _click(qtbot, window.alert.reconnect)
    qtbot.waitUntil(lambda: window.alert.resume.isVisible(), timeout=60_000)
    assert "kept its position" in window.alert.body.text()
    _click(qtbot, window.alert.resume)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=JOB_TIMEOUT_MS)

    event = window.binder.last_job_event
    assert event.completed, event
    qtbot.waitUntil(lambda: window.status.progress.value() == 1000, timeout=30_000)
    assert window.binder.tracker.view(0).percent == 100.0
    top_z = window.profile.travel.z_max - window.profile.travel.work_z  # after the job: Z lifted
    qtbot.waitUntil(lambda: _status(window).state == "IDLE" and abs(_status(window).z - top_z) < 0.01,
                    timeout=60_000)
    assert np.allclose(_status(window).position[:2], program.toolpath.end[-1][:2], atol=0.01)
    seqs = [seq for seq, _ in sim.exec_log]
    assert seqs == list(range(total))
    assert [line for _, line in sim.exec_log] == list(program.device_lines)
    assert len(window.history) > 10  # the live plot was fed


def _wait_still(qtbot, window, tries=20):
    """The status once two frames half a second (machine time) apart show the same position."""
    for _ in range(tries):
        before = _status(window)
        qtbot.waitUntil(lambda b=before: _status(window).time >= b.time + 0.5, timeout=60_000)
        if np.allclose(_status(window).position, before.position, atol=1e-3):
            return _status(window)
    raise AssertionError("the machine never came to rest")


def _machine_state(sim):
    with sim.lock:
        return sim.cnc.mc.state
