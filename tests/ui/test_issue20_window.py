"""Issue 20's defects that need no machine, each with its regression test: the timer
ticks every second and stale figures clear; the operator reads source lines only; the
link-lost alert follows the cause and the last state seen; boxes with four sides; no
heartbeat in the console; after-job choices in words; commanded spindle speed beside the
measured one; cnc-sim pseudo-terminals in the port list; no plot line across a gap; the
sentence fixes."""

from __future__ import annotations

import os

import numpy as np

from app.comm.events import CommandResult, JobEvent, LinkEvent, ProgressEvent, ResumeOffer, StatusEvent
from app.ui import session_binder
from app.ui.commanded import SpindleTrack
from app.ui.console import ConsoleView
from app.ui.plot.history import MEASURED, PositionHistory
from app.ui.ports import sim_ptys
from app.ui.preflight import sentence
from app.ui.preview.widget import rectangle_pairs
from app.ui.settings.dialog import ChoiceEdit, SettingsDialog
from app.ui.start_here import tool_before
from tests.ui.conftest import open_and_wait

# Source lines and device lines differ: comments, a blank line and a tool change.
SOURCE = ("(a part)\nG21 G90\n\nT1 M6\nM3 S2000\nG0 X10 Y10\n(cut)\nG1 Z-1 F200\nG1 X20\nG1 Y20\nG1 X10\n"
          "G1 Y10\nG0 Z5\nM5\nM2\n")


class Clock:
    def __init__(self):
        self.now = 1000.0

    def __call__(self):
        return self.now


def _status(state="RUN", flags="HP", done=0, rpm=1990):
    return StatusEvent("1A", state, 1.0, 2.0, 3.0, done, done, 8, rpm, flags, 5.0)


def test_the_timer_ticks_every_second_and_stale_figures_clear(qtbot, window, tmp_path, monkeypatch):
    clock = Clock()
    monkeypatch.setattr(session_binder.time, "monotonic", clock)
    path = tmp_path / "part.ngc"
    path.write_text(SOURCE)
    loaded = open_and_wait(qtbot, window, path)
    binder = window.binder
    binder.state = "STREAMING"
    binder.begin_job(loaded)
    binder.on_progress(ProgressEvent("job", loaded.program.device_count, 1, 2, 3))
    binder.last_job_event = None
    shown = []
    for _ in range(3):  # no line finishes: the elapsed time still moves, second by second
        clock.now += 1.0
        for _ in range(session_binder.SLOW_EVERY):
            binder.tick()
        shown.append(window.status.progress_text.text())
    assert [text.split("elapsed ")[1].split(" ")[0] for text in shown] == ["0:01", "0:02", "0:03"]
    binder.on_job_finished(JobEvent("job", False, "stopped by the operator", 1, loaded.program.device_count))
    clock.now += 5.0
    binder.tick()
    after = window.status.progress_text.text()
    assert "elapsed 0:03" in after and after.endswith("remaining —")  # the clock stopped; nothing remains
    binder.begin_job(None)  # an MDI line: the last job's figures go
    assert window.status.progress_text.text() == "no job"


def test_the_operator_reads_source_lines_only(qtbot, window, tmp_path):
    path = tmp_path / "part.ngc"
    path.write_text(SOURCE)
    loaded = open_and_wait(qtbot, window, path)
    program, binder = loaded.program, window.binder
    lines = program.device_lines
    seq = next(i for i, line in enumerate(lines) if line.startswith("G01 X20"))
    binder.state = "STREAMING"
    binder.begin_job(loaded)
    binder.on_progress(ProgressEvent("job", len(lines), seq - 1, seq, seq))
    binder._show_progress(0.0)
    assert "line 9/15" in window.status.progress_text.text()  # source line 9 of 15, not device lines
    binder.on_resume_offer(ResumeOffer(True, seq, seq - 1, len(lines), False))
    assert "line 9 of 15" in window.alert.body.text()
    window.operator.stop = lambda: None
    binder.on_job_finished(JobEvent("job", False, "refused", seq - 1, len(lines), refused=seq))
    assert "(at line 9;" in window.notifier.messages[-1][2]


def test_the_link_alert_follows_the_cause_and_the_last_state(qtbot, window):
    binder = window.binder
    binder.on_status(_status())
    binder.tick()
    binder.state = "STREAMING"
    binder.on_disconnected("[Errno 5] Input/output error")  # the machine's process was killed
    said = window.alert.body.text()
    assert "serial port" in said and "3 s" not in said.split("\n\n")[0]
    assert "Last state seen: RUN" in said and "has not lost its place" not in said
    assert "#e03030" in window.alert.headline.styleSheet()
    before = len(window.notifier.messages)
    binder.on_error(type("E", (), {"code": "MACHINE_RESET", "text": "the machine was reset"})())
    assert len(window.notifier.messages) == before  # no second box stacked behind the alert
    window.alert.show_offer(False, 4, 15)
    assert "Link restored" in window.alert.headline.text() and "#39a353" in window.alert.headline.styleSheet()
    binder.on_link(LinkEvent("LOST", 3.0, 0.0, False, "no valid frame for 3.0 s"))
    assert "has not answered for 3 s" in window.alert.body.text()
    assert "#e03030" in window.alert.headline.styleSheet()


def test_travel_and_program_boxes_draw_four_sides(window):
    xs, ys = rectangle_pairs(0, 0, 150, 100)
    sides = {frozenset({(xs[i], ys[i]), (xs[i + 1], ys[i + 1])}) for i in range(0, 8, 2)}
    corners = [(0, 0), (150, 0), (150, 100), (0, 100)]
    assert sides == {frozenset({corners[i], corners[(i + 1) % 4]}) for i in range(4)}
    x, y = window.preview.travel_item.getData()
    assert len(x) == 8 and len({(x[i], y[i], x[i + 1], y[i + 1]) for i in range(0, 8, 2)}) == 4


def test_no_heartbeat_in_the_console_under_the_default_filter(qtbot):
    console = ConsoleView()
    qtbot.addWidget(console)
    for kind, text in (("C", "C 812 PING"), ("S", "S 1A IDLE 0 0 0 -1 -1 16 0 H"), ("C", "C 813 HOME NORMAL"),
                       ("O", "O 813 HOME NORMAL")):
        console.add_frame("tx" if kind == "C" else "rx", kind, text)
    console.flush()
    log = console.log.toPlainText()
    assert "PING" not in log and "S 1A" not in log and "C 813 HOME" in log and "O 813 HOME" in log
    console.show_stream.setChecked(True)
    console.add_frame("tx", "C", "C 814 PING")
    console.flush()
    assert "C 814 PING" in console.log.toPlainText()


def test_after_job_is_a_choice_in_words(qtbot, window):
    dialog = SettingsDialog(window.profile, window)
    qtbot.addWidget(dialog)
    edit = dialog.edits["job", "after_job"]
    assert isinstance(edit, ChoiceEdit)
    assert [edit.itemText(i) for i in range(edit.count())] == [
        "stay where it ends", "lift Z to the top", "lift Z, then go to work X0 Y0", "home the machine"]
    edit.setCurrentIndex(2)
    profile, problems = dialog.checked_profile()
    assert not problems and profile.job.after_job == 2
    dialog.restore_defaults()
    assert edit.text() == "1" and edit.currentText() == "lift Z to the top"


def test_commanded_speed_beside_the_measured_one(window):
    lines = ["G00 X1", "M03 S2000", "G01 X2 F100", "M06 T2", "M03 S1500", "G01 X3", "M05", "G00 X0"]
    track = SpindleTrack(lines)
    assert [track.at(seq) for seq in range(8)] == [0, 2000, 2000, 2000, 1500, 1500, 0, 0]
    window.controls.set_rpm(1987, 2000.0)
    assert window.controls.rpm_label.text() == "commanded 2,000 · measured 1,987 rpm"
    window.controls.set_rpm(None, None)
    assert window.controls.rpm_label.text() == "commanded — · measured — rpm"


def test_the_port_list_finds_cnc_sim_pseudo_terminals(tmp_path):
    proc = tmp_path / "proc"
    for pid, args, fds in ((101, [b"python", b"-m", b"backend_sim", b"--pty"],
                            {0: "/dev/pts/1", 5: "/dev/pts/7"}),
                           (102, [b"/usr/bin/cnc-sim", b"--pty", b"--speed", b"5"], {3: "/dev/pts/9"}),
                           (103, [b"cnc-sim", b"--tcp", b"0"], {3: "/dev/pts/4"}),  # not on a pty
                           (104, [b"bash"], {3: "/dev/pts/5"})):
        (proc / str(pid) / "fd").mkdir(parents=True)
        (proc / str(pid) / "cmdline").write_bytes(b"\0".join(args) + b"\0")
        for fd, target in fds.items():
            os.symlink(target, proc / str(pid) / "fd" / str(fd))
    (proc / "self").mkdir()
    assert sim_ptys(proc) == [("/dev/pts/7", 101), ("/dev/pts/9", 102)]
    assert sim_ptys(tmp_path / "nothing") == []


def test_no_plot_line_across_a_reconnect_gap(window):
    history = PositionHistory(16)
    history.append(1.0, (0, 0, 0))
    history.append(2.0, (1, 1, 1))
    history.break_line()
    history.append(40.0, (5, 5, 5))  # after the reconnect
    rows = history.rows()
    assert np.isnan(rows[2, MEASURED]).all() and np.isfinite(rows[[0, 1, 3], MEASURED]).all()
    history.break_line()
    history.break_line()  # a second break adds nothing
    assert len(history) == 5
    assert all(curve.opts["connect"] == "finite" for curve in window.position_plot.curves)


def test_sentences_read_as_sentences(window):
    assert sentence("X+ leaves the travel by 1.000 mm; 1 move in all") == \
        "X+ leaves the travel by 1.000 mm; 1 move in all."
    assert sentence("Done.") == "Done."
    window.binder.on_command(CommandResult(7, "RESUME", (), False, "close the cover first", "COVER_OPEN"))
    assert window.status.currentMessage().startswith("RESUME: ")


def test_start_here_names_the_tool_in_the_spindle():
    lines = ["M06 T1", "G00 X1", "M00", "M06 T2", "G01 X2 F100", "M06", "G01 X3"]
    assert [tool_before(lines, i) for i in (0, 1, 3, 4, 6)] == [None, 1, 1, 2, 0]


def test_all_problems_at_once_even_past_a_line_that_does_not_compile(qtbot, window, tmp_path):
    """A syntax error no longer hides the unsupported words, lathe codes and travel findings
    after it, in an expanded program as in a plain one; the Problems list shows them all."""
    for first in ("#1 = 5\nG21 G90\nG0 X#1 Y10\nG1 X[1 + ] F100\n", "G21 G90\nG0 X5 Y10\nG1 X20 Y$ F100\n"):
        path = tmp_path / "bad.ngc"
        path.write_text(first + "G1 Q5 X30\nG7 X40\nG1 X400 Y10 F100\nM2\n")
        loaded = open_and_wait(qtbot, window, path)
        program, n = loaded.program, len(first.splitlines())
        errors = sorted((d.line, str(d.message)) for d in program.errors)
        assert [line for line, _ in errors] == [n, n + 1, n + 2], errors
        assert any(d.line == n + 3 and "beyond travel" in str(d.message) for d in program.warnings)
        listed = window.program_panel.problems.model().rowCount()
        assert listed == len(program.errors) + len(program.warnings)


def test_a_point_list_with_a_bad_word_names_its_word(qtbot, window, tmp_path):
    path = tmp_path / "points.xyz"
    path.write_text("1 2 3\n4 five 6\n7 8 9\n")
    window.open_file(path)  # recognised as a point list, not read as G-code
    dialog = window.import_dialog
    qtbot.waitUntil(lambda: "five" in dialog.problem.text(), timeout=10_000)
    assert "line 2, column 3" in dialog.problem.text() and "(y)" in dialog.problem.text()
    dialog.close()
