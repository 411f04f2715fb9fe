"""Program stops and tool changes end to end: Session <-> simulator (issue 11).

The machine holds at ``M00``, ``M01`` (optional stop on) and ``M06 T2``; the session
reports each once; ``RESUME`` goes on. The oracle: the executed log is every line once,
in order; the spindle is off and Z at the clearance height during the tool change.
"""

from __future__ import annotations

from app.comm.listener import SessionState
from app.comm.rtt import RttEstimator
from app.comm.stops import StopWatch, is_stop_line, stop_event
from app.comm.stream import Stream
from tests.comm.simlink import FAST_HOMING, SimLink, assert_oracle

PROGRAM = [
    "M03 S3000", "G00 Z5", "G00 X20 Y20", "G01 Z-1 F300", "G01 X30",
    "M00", "G01 Y30", "M01", "G01 X20", "M06 T2", "G01 Y20", "G00 Z5", "M05", "M02",
]
STOPS = [5, 7, 9]


def test_stop_lines_are_read():
    assert is_stop_line("M00") and is_stop_line("M1") and is_stop_line("M06 T2")
    assert not is_stop_line("M03 S100") and not is_stop_line("M02")
    assert stop_event(9, "M06 T2").tool == 2 and stop_event(9, "M06 T2").code == 6
    assert stop_event(5, "M00").tool is None and stop_event(7, "M01").code == 1
    watch = StopWatch()
    assert watch.update("HW", 4) == 5 and watch.update("HW", 4) is None
    assert watch.update("H", 5) is None and watch.update("HW", 6) == 7


def test_the_stream_holds_after_each_stop_line_until_the_machine_has_finished_it():
    stream = Stream.job(PROGRAM, RttEstimator(), free=32)
    assert stream.stops == STOPS
    assert [frame.seq for frame in stream.window.due(0.0)] == list(range(6))  # up to M00, not past it
    stream.window.on_ack(5, 32, 0.01)
    stream.finish_line(4)  # the lines before the stop are done: the machine holds at M00
    assert stream.window.due(0.02) == []
    stream.finish_line(5)  # RESUME: M00 finished
    assert [frame.seq for frame in stream.window.due(0.03)] == [6, 7]  # to the next stop, M01
    restarted = Stream.job(PROGRAM, RttEstimator(), free=32, start=8, preamble=["G21", "G90"])
    assert restarted.stops == [3]  # M06 T2 after the two preamble lines and line 8
    assert [frame.seq for frame in restarted.window.due(0.0)] == [0, 1, 2, 3]


def _link(tmp_path, **settings) -> SimLink:
    link = SimLink(check=False, profile=FAST_HOMING, sd_dir=tmp_path)  # its own flash (work offset)
    link.home()
    for name, value in settings.items():
        link.command_ok("SET", name.upper(), value)
    return link


def _run_answering(link: SimLink, lines: list[str]) -> list:
    """Run ``lines``; at each stop, record (event, rpm, machine z, spindle flag), then RESUME."""
    seen = []
    assert link.session.start_job(lines)
    ended = lambda: link.rec.of("on_job_finished")  # noqa: E731
    while not ended():
        waiting = lambda: len(link.rec.of("on_program_stop")) > len(seen) or ended()  # noqa: E731
        assert link.run_until(waiting, 120.0), "neither a stop nor the end"
        if ended():
            break
        link.run_for(0.5)  # the machine keeps holding while the operator thinks
        mc = link.sim.cnc.mc
        status = link.session.status
        seen.append((link.rec.of("on_program_stop")[-1], mc.spindle_rpm, mc.measured_mm[2], status))
        assert link.session.resume()
    return seen


def test_the_machine_holds_at_each_stop_and_continues(tmp_path):
    link = _link(tmp_path)
    seen = _run_answering(link, PROGRAM)
    job = link.rec.last("on_job_finished")
    assert job.completed, job
    assert [event.index for event, *_ in seen] == STOPS
    assert [event.line for event, *_ in seen] == ["M00", "M01", "M06 T2"]
    for event, *_, status in seen:
        assert status.state == "HOLD" and "W" in status.flags and status.done == event.index - 1
        assert status.acc == event.index  # the host sent nothing past the stop line
    (_, rpm0, z0, _), _, (tool, rpm6, z6, _) = seen
    assert rpm0 > 2000 and z0 < 20  # M00 keeps the spindle and the tool where it was
    assert tool.tool == 2 and rpm6 < 100 and abs(z6 - 30.0) < 0.05  # M06: spindle off, Z up
    assert_oracle(link.executed(), PROGRAM)
    mc = link.sim.cnc.mc  # after the job (AFTERJOB 1, the default): Z lifted to the top
    assert link.run_until(lambda: mc.state == "IDLE" and abs(mc.measured_mm[2] - 30.0) < 0.01, 30.0)


def test_after_the_job_go_to_work_zero_or_stay(tmp_path):
    link = _link(tmp_path, optstop=0, afterjob=2)
    link.command_ok("ZERO", "XY")  # work X0 Y0 = machine (0, 0) after homing
    link.command_ok("JOG", "X", 40, 600)
    link.command_ok("ZERO", "XY")  # now work zero is machine X40 Y0
    _run_answering(link, PROGRAM)
    mc = link.sim.cnc.mc
    near = lambda p, q: max(abs(a - b) for a, b in zip(p, q, strict=True)) < 0.01  # noqa: E731
    at_zero = lambda: mc.state == "IDLE" and near(mc.measured_mm, (40.0, 0.0, 30.0))  # noqa: E731
    assert link.run_until(at_zero, 60.0), mc.measured_mm
    link.command_ok("SET", "AFTERJOB", 0)
    link.command_ok("SET", "OPTSTOP", 1)
    assert link.command("SET", "AFTERJOB", 4).code == "BAD_PARAM"


def test_optional_stop_off_runs_through_m01(tmp_path):
    link = _link(tmp_path, optstop=0)
    seen = _run_answering(link, PROGRAM)
    assert [event.index for event, *_ in seen] == [5, 9]
    assert_oracle(link.executed(), PROGRAM)


def test_stop_job_at_a_tool_change_ends_it_cleanly(tmp_path):
    link = _link(tmp_path)
    assert link.session.start_job(PROGRAM)
    assert link.run_until(lambda: link.rec.of("on_program_stop"), 120.0)
    link.session.resume()
    assert link.run_until(lambda: len(link.rec.of("on_program_stop")) == 2, 120.0)
    link.session.resume()
    assert link.run_until(lambda: len(link.rec.of("on_program_stop")) == 3, 120.0)
    link.session.stop()
    assert link.run_until(lambda: link.rec.of("on_job_finished"), 30.0)
    assert not link.rec.last("on_job_finished").completed
    assert [seq for seq, _ in link.executed()] == list(range(9))
    assert link.session.state is SessionState.READY


def test_a_link_loss_at_a_stop_resumes_and_asks_again(tmp_path):
    link = _link(tmp_path)
    assert link.session.start_job(PROGRAM)
    assert link.run_until(lambda: link.rec.of("on_program_stop"), 120.0)
    link.sim.faults.unplug()
    link.step()
    assert link.session.state is SessionState.INTERRUPTED
    link.run_for(4.0)  # host lost on the machine too; it keeps holding at the stop
    assert link.sim.cnc.mc.waiting is not None and link.sim.cnc.status().flags.endswith("W")
    link.sim.faults.replug()
    link.attach()
    assert link.run_until(lambda: link.session.state is SessionState.RESUME_OFFERED, 3.0)
    assert link.session.resume_after_reconnect()
    assert link.run_until(lambda: len(link.rec.of("on_program_stop")) == 2, 5.0)  # asked again
    assert link.rec.of("on_program_stop")[1].index == STOPS[0]
    assert link.sim.cnc.mc.waiting is not None  # RESUME FROM did not release the stop
    seen = [link.rec.of("on_program_stop")[1]]
    while len(seen) < 3:
        assert link.session.resume()
        count = len(link.rec.of("on_program_stop"))
        assert link.run_until(lambda c=count: len(link.rec.of("on_program_stop")) > c, 120.0)
        seen.append(link.rec.of("on_program_stop")[-1])
    assert [event.index for event in seen] == STOPS
    assert link.session.resume()
    assert link.run_until(lambda: link.rec.of("on_job_finished"), 120.0)
    assert link.rec.last("on_job_finished").completed
    assert_oracle(link.executed(), PROGRAM)
