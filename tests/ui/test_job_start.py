"""Start reads a relative first move from where the machine stands (issue 19): after a
jog, ``G91 G00 Z-2`` as a job, and as an MDI line, is sent as one Z move from there."""

from __future__ import annotations

from PySide6.QtCore import Qt

from app.comm.modal import restart_preamble
from tests.ui.conftest import open_and_wait, when_allowed


def _jogged(qtbot, window, tmp_path):
    window.operator.connect_to(f"sim://?speed=50&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    window.controls.check_mode.setChecked(True)
    for axis, distance in (("X", 14.5), ("Z", 10)):
        before = getattr(window.binder.status, axis.lower())
        when_allowed(qtbot, window, "jog", lambda a=axis, d=distance: window.operator.jog(a, d, 900))

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


RELATIVE = "G21 G91\nG00 Z-2\nG01 X5 F600\nG01 Y4\nG01 X-3\nG01 Y-1.5\nG00 Z2\nM2\n"
# the work position after each line of RELATIVE, from a start at (x, y, z)
STEPS = {2: (0, 0, -2), 3: (5, 0, -2), 4: (5, 4, -2), 5: (2, 4, -2), 6: (2, 2.5, -2), 7: (2, 2.5, 0)}


def _targets(executed):
    """(x, y, z) each executed move line goes to, the axes it leaves out kept."""
    where, out = {}, []
    for line in executed:
        words = {w[0]: float(w[1:]) for w in line.split()[1:] if w[0] in "XYZ"}
        if line.startswith(("G00", "G01")):
            where.update(words)
            out.append((where.get("X"), where.get("Y"), where.get("Z")))
    return out


def test_start_here_in_a_relative_program_moves_only_from_the_reported_position(qtbot, window, tmp_path):
    """Start here at line 5 of a G91 program: the preamble goes to where line 4 leaves the
    tool counted from where the machine stands, and the lines from there follow on."""
    status = _jogged(qtbot, window, tmp_path)
    path = tmp_path / "relative.ngc"
    path.write_text(RELATIVE)
    loaded = open_and_wait(qtbot, window, path)
    assert "G01 X2" in loaded.program.device_lines  # the preview's reading, from the origin
    window.program_panel.start_here_requested.emit(5)  # "G01 X-3"
    qtbot.waitUntil(lambda: window.start_here.dialog is not None and window.start_here.dialog.isVisible(),
                    timeout=20_000)
    job, k = window.start_here.job, window.start_here.pending
    assert job is not loaded.program and job.device_lines[k].startswith("G01 X")
    at = [status.x + 5, status.y + 4, status.z - 2]
    assert f"X{at[0]:.3f} Y{at[1]:.3f}" in window.start_here.dialog.informativeText()
    qtbot.mouseClick(window.start_here.start_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert window.binder.last_job_event.completed
    executed = _executed(window)
    assert executed == restart_preamble(job.device_lines, k) + job.device_lines[k:]
    targets = _targets(executed)
    want = [tuple(round(p + d, 3) for p, d in zip((status.x, status.y, status.z), STEPS[n], strict=True))
            for n in (5, 6, 7)]
    assert [tuple(round(v, 3) for v in t) for t in targets[-3:]] == want
    for x, y, _ in targets:  # never towards the origin the preview was read from
        assert x is None or x >= status.x - 0.001
        assert y is None or y >= status.y - 0.001


def test_save_to_sd_of_a_relative_program_is_read_from_the_reported_position(qtbot, window, tmp_path):
    status = _jogged(qtbot, window, tmp_path)
    path = tmp_path / "relative.ngc"
    path.write_text(RELATIVE)
    open_and_wait(qtbot, window, path)
    window.operator.upload("REL.NC")
    qtbot.waitUntil(lambda: window.binder.last_upload_event is not None, timeout=60_000)
    assert window.binder.last_upload_event.completed
    saved = [line for line in (tmp_path / "REL.NC").read_text().splitlines() if line.startswith("G0")]
    assert saved[0] == f"G00 Z{status.z - 2:g}"
    assert saved[1] == f"G01 X{status.x + 5:g} F600"


def test_the_reading_again_runs_off_the_gui_thread(qtbot, window, tmp_path):
    """While a relative program is read again from the machine's position the window's
    thread is free: Start returns at once, the job goes out when the reading is done."""
    import threading

    status = _jogged(qtbot, window, tmp_path)
    path = tmp_path / "relative.ngc"
    path.write_text(RELATIVE)
    loaded = open_and_wait(qtbot, window, path)
    program = loaded.program
    release, threads, read = threading.Event(), [], program._again

    def held(position):
        threads.append(threading.current_thread())
        release.wait(60)
        return read(position)

    program._again = held
    window.operator.start()  # returns with the reading still held
    assert window.operator.machine_start.busy and window.binder.last_job_event is None
    assert "Reading the program again" in window.status.currentMessage()
    release.set()
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    assert threads and threads[0] is not threading.main_thread()
    assert f"G00 Z{status.z - 2:g}" in _executed(window)[-7:]


def test_a_failed_reading_again_is_said_and_nothing_is_sent(qtbot, window, tmp_path):
    _jogged(qtbot, window, tmp_path)
    path = tmp_path / "relative.ngc"
    path.write_text(RELATIVE)
    loaded = open_and_wait(qtbot, window, path)
    sent = len(_executed(window))

    def broken(position):
        raise MemoryError("no room")

    loaded.program._again = broken
    with qtbot.waitSignal(window.notifier.notified, timeout=20_000) as said:
        window.operator.start()
    level, title, text = said.args
    assert level == "error" and title == "Program not started" and "MemoryError: no room" in text
    assert not window.operator.machine_start.busy and window.binder.last_job_event is None
    assert len(_executed(window)) == sent
