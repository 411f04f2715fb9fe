"""Unit tests of the session's small parts: modal preamble, clocks, commands, real time, states."""

import pytest

from app.comm import frame as fr
from app.comm.commands import CommandQueue
from app.comm.heartbeat import LinkMonitor, LinkState
from app.comm.listener import SessionState
from app.comm.modal import modal_state, restart_preamble
from app.comm.realtime import UrgentCommands
from app.comm.rtt import RttEstimator
from app.comm.stream import Stream, sd_crc32
from tests.comm.scripted import Harness

PROGRAM = ["M03 S4500", "G00 X0 Y0 Z5", "G00 X44.793 Y83", "G01 Z-0.8 F80", "G01 Y71.724 F350",
           "G01 X47.586", "G02 X50 Y70 I1 J-1", "G00 Z5", "M05"]


def test_modal_state_and_preamble():
    state = modal_state(PROGRAM, 6)
    assert (state.x, state.y, state.z, state.feed, state.spindle_rpm) == (47.586, 71.724, -0.8, 350.0, 4500.0)
    assert restart_preamble(PROGRAM, 6) == [
        "M03 S4500", "G00 Z5.000", "G00 X47.586 Y71.724 F350", "G01 Z-0.800 F350"]
    assert restart_preamble(PROGRAM, 0) == []
    assert restart_preamble(PROGRAM, 9)[0] == "G00 Z5.000"  # spindle off after M05


def test_restart_stream_maps_back_to_program_lines():
    stream = Stream.job(PROGRAM, RttEstimator(), 16, start=6, preamble=["A", "B", "C"])
    assert stream.window.lines == ["A", "B", "C"] + PROGRAM[6:]
    assert [stream.program_index(s) for s in (0, 2, 3, 5)] == [5, 5, 6, 8]
    assert stream.program_total == len(PROGRAM)


def test_sd_crc32_is_over_lines_joined_with_newline_plus_final_newline():
    assert sd_crc32(["G00 X1", "G01 X2 F100"]) == 0x9E9E5E27  # zlib.crc32(b"G00 X1\nG01 X2 F100\n")
    assert sd_crc32(["a"]) == 0xDDEAA107  # zlib.crc32(b"a\n")


def test_urgent_command_goes_first_and_answers_match_ids():
    queue = CommandQueue()
    first = queue.submit("JOG", ("X", "10", "300"))
    frames, _ = queue.due(0.0)
    assert frames == [first]
    queue.submit("GET", ("KP_X",))
    stop = queue.submit("STOP", urgent=True)
    dropped = queue.supersede()
    assert dropped.id == first.id
    frames, _ = queue.due(0.0)
    assert frames == [stop]
    assert queue.on_answer(fr.Ok(first.id, "JOG")) is None  # stale answer ignored
    assert queue.on_answer(fr.Ok(stop.id, "STOP")).ok


def test_heartbeat_goes_out_while_a_command_is_retried():
    queue = CommandQueue()
    home = queue.submit("HOME")
    frames, _ = queue.due(0.0)
    assert [c.verb for c in queue.heartbeat(frames)] == ["PING"]
    assert queue.heartbeat([fr.Command(9, "STATUS")]) == []
    queue.on_answer(fr.Ok(home.id, "HOME"))
    assert queue.heartbeat([])[0].verb == "PING"


def test_link_monitor_states():
    link = LinkMonitor()
    link.attach(0.0)
    assert not link.update(1.99) and link.state is LinkState.CONNECTED
    assert link.update(2.0) and link.state is LinkState.DEGRADED
    assert link.update(3.0) and link.state is LinkState.LOST
    link.heard(3.1)
    assert link.update(3.1) and link.state is LinkState.CONNECTED


def test_urgent_command_repeats_until_answered_and_gives_up_after_five_seconds():
    ids = iter(range(100, 200)).__next__
    urgent = UrgentCommands(ids)
    hold = urgent.request("HOLD", 0.0)
    assert hold == fr.RealtimeCommand(100, "HOLD")
    assert urgent.due(0.0) == [hold, hold]  # two copies the first time
    assert urgent.due(0.005) == []
    assert urgent.due(0.01) == [hold]
    assert urgent.request("HOLD", 0.02) is hold  # a second click is the same frame
    assert urgent.on_status("RUN") == [] and urgent.on_status("IDLE") == []  # may predate it
    assert urgent.expired(5.1) == [hold]
    hold = urgent.request("HOLD", 6.0)
    stop = urgent.request("STOP", 6.0)
    assert urgent.due(6.0) == [stop, stop]  # a stop replaces a pending hold
    assert urgent.on_answer(fr.Ok(stop.id, "STOP", "IDLE")) == stop and not urgent.pending("STOP")
    assert urgent.on_answer(fr.Ok(stop.id, "STOP", "IDLE")) is None  # a repeat answer
    hold = urgent.request("HOLD", 7.0)
    assert urgent.on_status("HOLD") == [hold] and urgent.due(7.0) == []


def test_state_changes_are_checked():
    h = Harness()
    with pytest.raises(RuntimeError, match="READY -> STREAMING"):
        h.session._set_state(SessionState.STREAMING)


def test_boot_zero_is_not_a_machine_reset():
    h = Harness()
    h.reply(Harness.status(boot="0", state="ALARM", flags=""), Harness.status())
    assert "MACHINE_RESET" not in [e.code for e in h.rec.of("on_error")]


def test_stop_abandons_an_interrupted_job():
    h = Harness()
    h.open_job(["G00 X1", "G00 X2"])
    h.advance(3.1)
    assert h.session.state is SessionState.INTERRUPTED
    h.session.stop()
    assert h.session.state is SessionState.READY
    assert h.rec.last("on_job_finished").reason == "abandoned by the operator"


def test_upload_refused_at_the_end_fails():
    h = Harness()
    h.session.upload_to_sd("x.nc", ["G00 X1"])
    put = [f for f in h.take() if isinstance(f, fr.Command)][0]
    h.reply(fr.Ack(0, 8), fr.Error(put.id, "CRC", "mismatch"))
    job = h.rec.last("on_job_finished")
    assert job.kind == "upload" and not job.completed and "CRC" in job.reason


def test_a_line_too_long_for_a_frame_is_refused_before_sending():
    h = Harness()
    assert not h.session.start_job(["G01 X" + "1" * 100])
    assert h.rec.last("on_error").code == "BAD_LINE"
