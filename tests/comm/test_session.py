"""Session unit tests with scripted machine replies and an injected clock (no sleeps)."""

import zlib

import pytest

from app.comm import frame as fr
from app.comm.listener import SessionState
from app.comm.rtt import RttEstimator
from tests.comm.scripted import BOOT, Harness

LINES = [f"G01 X{i} Y0 F300" for i in range(40)]


def streaming(lines=LINES, free=16):
    h = Harness(status=Harness.status(free=free))
    h.open_job(lines)
    return h


# ---------------------------------------------------------------------- credit window


def test_window_is_min_of_free_and_sixteen():
    h = streaming(free=20)
    assert h.take_data() == list(range(16))
    h.reply(fr.Ack(1, 20))
    assert h.take_data() == [16, 17]


def test_window_respects_a_small_free_count():
    h = streaming(free=3)
    assert h.take_data() == [0, 1, 2]
    h.reply(fr.Ack(0, 2))
    assert h.take_data() == []  # acc 0 + free 2 = seq 2: already sent
    h.reply(fr.Ack(2, 0))
    assert h.take_data() == []
    h.reply(Harness.status("RUN", acc=2, done=1, free=1))
    assert h.take_data() == [3]


def test_status_credit_unblocks_a_full_queue():
    h = streaming(free=2)
    assert h.take_data() == [0, 1]
    h.reply(fr.Ack(1, 0))
    h.advance(3.0)
    assert h.take_data() == []  # no credit, nothing in flight, no resend
    h.reply(Harness.status("RUN", acc=1, done=0, free=1))
    assert h.take_data() == [2]


# ---------------------------------------------------------------------- go-back-N


def test_nak_resends_only_its_seq_and_ignores_repeats():
    h = streaming()
    h.take()
    h.clock.now += 0.03
    h.reply(fr.Ack(2, 16), fr.Nak(3))
    assert h.take_data() == [3, 16, 17, 18]  # selective repeat: 3 alone, then new frames
    h.reply(fr.Nak(3))  # caused by frames already in flight
    assert h.take_data() == []


def test_timeout_resends_the_first_unacked_frame_alone():
    h = streaming()
    h.take()
    h.advance(0.49)
    assert h.take_data() == []
    h.advance(0.03)
    assert h.take_data() == [0]  # the machine keeps what lies above a gap


def test_late_ack_after_a_probe_is_honoured():
    h = streaming()
    h.take()
    h.advance(0.52)
    assert h.take_data() == [0]
    h.reply(fr.Ack(7, 16))
    assert h.take_data() == list(range(16, 24))


def test_garbled_replies_are_never_acks():
    h = streaming()
    h.take()
    bad = bytearray(fr.encode(fr.Ack(7, 16)))
    bad[2] ^= 0x01  # "A 6 16" with the CRC of "A 7 16"
    h.reply(bytes(bad), b"A 7 16\n", b"A 7 16*0000\n")
    assert h.session.stream.window.acked == -1
    assert all(not e.ok for e in h.rec.of("on_frame") if e.direction == "rx" and e.kind == "?")


# ---------------------------------------------------------------------- timeouts


def test_rtt_timeout_maths():
    rtt = RttEstimator()
    assert rtt.timeout == 0.5
    rtt.sample(0.02)
    assert rtt.srtt == 0.02 and rtt.rttvar == 0.01
    assert rtt.timeout == pytest.approx(0.06)  # max(30 ms, 0.02 + 4 * 0.01)
    assert rtt.probe_timeout == pytest.approx(0.04)  # min(timeout, max(15 ms, 2 * 0.02))
    rtt.sample(0.2)
    assert rtt.srtt == pytest.approx(0.0425)
    assert rtt.rttvar == pytest.approx(0.0525)
    assert rtt.timeout == pytest.approx(0.0425 + 4 * 0.0525)
    for _ in range(10):
        rtt.expired()
    assert rtt.timeout == 2.0
    rtt.sample(0.02)
    assert rtt.timeout < 0.3


def test_ten_retries_of_one_seq_abort_the_job_with_a_named_error():
    h = streaming()
    start = h.clock.now
    for _ in range(60):  # the machine answers PINGs but every D frame is lost
        h.advance(0.5)
        h.reply(Harness.status("IDLE"))
    errors = [e.code for e in h.rec.of("on_error")]
    assert "RETRIES_EXHAUSTED" in errors
    job = h.rec.last("on_job_finished")
    assert not job.completed and "resent 10 times" in job.reason
    assert [f for f in h.take() if isinstance(f, fr.RealtimeCommand) and f.verb == "STOP"]  # told to stop
    sends = [f for f in h.rec.of("on_frame") if f.direction == "tx" and f.text.startswith("D 0 ")]
    assert len(sends) == 11
    assert errors.count("RETRIES_EXHAUSTED") == 1
    assert h.session.state is SessionState.READY
    assert h.clock.now - start <= 30.0


# ---------------------------------------------------------------------- heartbeat


def test_ping_every_quarter_second_and_link_states():
    h = Harness()
    start = h.clock.now
    pings = []
    for _ in range(350):
        h.advance(0.01)
        pings += [h.clock.now for f in h.take() if isinstance(f, fr.Command) and f.verb == "PING"]
    assert pings[0] - start == pytest.approx(0.25, abs=0.011)  # a quarter second after the STATUS
    gaps = [b - a for a, b in zip(pings, pings[1:], strict=False)]
    assert gaps[0] == pytest.approx(0.25, abs=0.011)  # 4 a second (issue 18) ...
    assert gaps[1:] and all(d == pytest.approx(0.02, abs=0.011) for d in gaps[1:])  # 50 once silent 0.5 s
    states = [(e.state, round(e.silent_s, 2)) for e in h.rec.of("on_link_changed")]
    assert [s for s, _ in states][-2:] == ["DEGRADED", "LOST"]
    assert states[-2][1] == pytest.approx(2.0, abs=0.011) and states[-1][1] == pytest.approx(3.0, abs=0.011)
    h.reply(Harness.status())
    assert h.rec.last("on_link_changed").state == "CONNECTED"


def test_garbage_is_no_sign_of_life():
    h = Harness()
    for _ in range(32):
        h.advance(0.1)
        h.reply(b"S garbage*1234\n")
    assert h.rec.last("on_link_changed").state == "LOST"


# ---------------------------------------------------------------------- real-time commands


def _urgent(out, verb):
    return [f for f in out if isinstance(f, fr.RealtimeCommand) and f.verb == verb]


def test_feed_hold_is_an_r_frame_repeated_every_10_ms_until_the_status_shows_hold():
    h = streaming()
    h.take()
    h.session.pause()
    first = h.take()
    holds = _urgent(first, "HOLD")
    assert len(holds) == 2 and holds[0] == holds[1]  # two copies at once
    assert fr.LEGACY_BYTES[:1] not in first and fr.LEGACY_BYTES[1:] not in first
    times = []
    for _ in range(5):
        h.advance(0.005)
        times += [h.clock.now for _ in _urgent(h.take(), "HOLD")]
    assert len(times) == 2 and times[1] - times[0] == pytest.approx(0.01, abs=0.006)
    h.reply(Harness.status("HOLD", acc=7, done=2))
    h.advance(0.5)
    assert not _urgent(h.take(), "HOLD")
    assert h.session.state is SessionState.PAUSED


def test_hold_ends_with_its_answer_and_a_stale_idle_status_ends_nothing():
    h = streaming()
    h.take()
    h.session.pause()
    hold = _urgent(h.take(), "HOLD")[0]
    h.reply(Harness.status("IDLE", acc=7, done=2))  # sent before the machine took the hold
    h.advance(0.02)
    assert _urgent(h.take(), "HOLD")
    h.reply(fr.Ok(hold.id, "HOLD", "RUN"))
    h.advance(0.1)
    assert not _urgent(h.take(), "HOLD")
    assert h.rec.last("on_command_done").verb == "HOLD"


def test_stop_is_an_r_frame_until_answered_and_the_job_ends_when_the_machine_is_idle():
    h = streaming()
    h.take()
    h.session.stop()
    out = h.take()
    stop = _urgent(out, "STOP")[0]
    assert not [f for f in out if isinstance(f, fr.Command) and f.verb == "STOP"]
    h.reply(fr.Ack(7, 8), fr.Nak(8))
    h.advance(0.1)
    out = h.take()
    assert len(_urgent(out, "STOP")) >= 5 and not [f for f in out if isinstance(f, fr.Data)]
    h.reply(Harness.status("IDLE", acc=7, done=3))  # may predate the stop: the job goes on stopping
    assert h.session.state is SessionState.STOPPING
    h.reply(fr.Ok(stop.id, "STOP", "HOLD"))
    h.advance(0.05)
    assert not _urgent(h.take(), "STOP") and h.session.state is SessionState.STOPPING
    h.reply(Harness.status("IDLE", acc=7, done=3))
    assert h.session.state is SessionState.READY
    assert h.rec.last("on_job_finished").reason == "stopped by the operator"


def test_a_hold_the_host_did_not_ask_for_is_reported_with_its_reason():
    h = streaming()
    h.reply(fr.Status(BOOT, "HOLD", 0, 0, 10, 7, 2, 8, 0, "HL", "LINK"))
    hold = h.rec.last("on_hold")
    assert (hold.why, hold.source, hold.asked) == ("LINK", "link", False)
    assert "lost the link" in hold.text
    assert any("the machine holds (the link)" in e.text for e in h.rec.of("on_log"))
    h.reply(fr.Status(BOOT, "HOLD", 0, 0, 10, 7, 2, 8, 0, "HL", "LINK"))
    assert len(h.rec.of("on_hold")) == 1  # once per cause
    h.reply(Harness.status("RUN", acc=7, done=3))
    assert h.rec.last("on_hold").why == ""
    h.session.pause()
    h.reply(fr.Status(BOOT, "HOLD", 0, 0, 10, 7, 3, 8, 0, "H", "HOST"))
    assert h.rec.last("on_hold").asked and h.rec.last("on_hold").source == "host"


def test_resend_rate_of_the_last_minute_rides_on_the_link_event():
    h = streaming()
    for _ in range(30):
        h.reply(fr.Nak(8))
        h.advance(0.2)
        h.reply(fr.Ack(8, 8))
        h.reply(fr.Ack(h.session.stream.window.high_sent, 8))
    event = h.rec.last("on_link_changed")
    assert event.sent_last_min > 0 and event.resent_last_min > 0
    assert event.resend_rate == pytest.approx(event.resent_last_min / event.sent_last_min)
    h.advance(61.0)  # a minute later nothing is left in the window
    assert h.session.health.sent(h.clock.now) == 0


# ---------------------------------------------------------------------- commands


def test_command_retried_with_the_same_id_until_answered():
    h = Harness()
    cid = h.session.home()
    sent = []
    for _ in range(200):
        h.advance(0.01)
        sent += [f for f in h.take() if isinstance(f, fr.Command)]
    homes = [c for c in sent if c.verb == "HOME"]
    assert {c.id for c in homes} == {cid} and len(homes) >= 3
    assert {c.verb for c in sent} == {"HOME", "PING"}  # the heartbeat carries on beside it
    h.reply(fr.Ok(cid, "HOME", "NORMAL"))
    result = h.rec.last("on_command_done")
    assert result.ok and result.id == cid and result.verb == "HOME"


def test_one_command_outstanding_others_wait():
    h = Harness()
    first = h.session.send_command("GET KP_X")
    second = h.session.send_command("GET KP_Y")
    assert [c.id for c in h.take() if isinstance(c, fr.Command)] == [first]
    h.reply(fr.Ok(first, "GET", "KP_X 8"))
    assert [c.id for c in h.take() if isinstance(c, fr.Command)] == [second]


def test_unanswered_command_times_out():
    h = Harness()
    cid = h.session.send_command("GET KP_X")
    h.advance(4.5)
    h.reply(Harness.status())
    result = [r for r in h.rec.of("on_command_done") if r.id == cid][0]
    assert not result.ok and result.code in ("TIMEOUT", "LINK_LOST")


def test_sd_list_collects_info_rows():
    h = Harness()
    cid = h.session.list_sd()
    h.reply(fr.Info(cid, "a.nc 120 10"), fr.Info(cid, "b.nc 50 3"), fr.Ok(cid, "SD", "LIST 2"))
    assert h.rec.last("on_command_done").rows == ("a.nc 120 10", "b.nc 50 3")


# ---------------------------------------------------------------------- jobs


def test_job_completes_on_the_last_f():
    h = streaming(LINES[:3])
    assert h.take_data() == [0, 1, 2]
    h.reply(fr.Ack(2, 13), fr.Finished(1))
    assert h.session.state is SessionState.STREAMING
    h.reply(fr.Finished(2))
    job = h.rec.last("on_job_finished")
    assert job.completed and job.done == 2 and h.session.state is SessionState.READY


def test_job_refused_while_a_stream_is_active():
    h = streaming()
    assert not h.session.start_job(LINES)
    assert h.rec.last("on_error").code == "BUSY"


def test_machine_refuses_job():
    h = Harness()
    h.session.start_job(LINES)
    job = h.command("JOB")
    h.reply(fr.Error(job.id, "BUSY", "machine is RUN"))
    assert not h.rec.last("on_job_finished").completed
    assert h.take_data() == []


def test_refused_line_ends_the_job_and_is_not_resent():
    h = streaming()
    h.take()
    h.reply(fr.Ack(4, 12), fr.Error(None, "SOFT_LIMIT", "5 X+ 151.000 > 150"))
    h.advance(3.0)
    assert h.take_data() == []
    job = h.rec.last("on_job_finished")
    assert not job.completed and "SOFT_LIMIT" in job.reason


def test_resend_rate_warning():
    h = streaming(LINES * 3)
    h.take()
    for seq in range(0, 100, 3):
        h.reply(fr.Ack(seq - 1, 16), fr.Nak(seq))
        h.clock.now += 0.2
    assert h.rec.last("on_link_changed").quality_warning
    assert any(e.level == "warning" and "resent" in e.text for e in h.rec.of("on_log"))


def test_upload_sends_count_and_crc32():
    h = Harness()
    lines = ["G00 X1", "G01 X2 F100"]
    assert h.session.upload_to_sd("part.nc", lines)
    out = h.take()
    put = [f for f in out if isinstance(f, fr.Command)][0]
    crc = zlib.crc32(b"G00 X1\nG01 X2 F100\n")
    assert put.args == ("PUT", "part.nc", "2", f"{crc:08X}")
    assert [f.seq for f in out if isinstance(f, fr.Data)] == [0]
    h.reply(fr.Ack(0, 8))
    assert h.take_data() == [1]
    h.reply(fr.Ack(1, 8), fr.Ok(put.id, "SD", "PUT part.nc"))
    assert h.rec.last("on_job_finished").completed


def test_upload_frames_wait_until_the_sd_put_itself_has_been_sent():
    h = Harness()
    listing = h.session.list_sd()  # a command outstanding: SD PUT queues behind it
    h.take()
    assert h.session.upload_to_sd("part.nc", ["G00 X1", "G01 X2 F100"])
    assert h.take() == []  # no D frame may reach a machine with no upload open (BAD_SEQ)
    h.reply(fr.Ok(listing, "SD", "LIST"))
    out = h.take()
    kinds = [type(f) for f in out]
    assert kinds[0] is fr.Command and out[0].args[0] == "PUT" and fr.Data in kinds  # PUT first


# ---------------------------------------------------------------------- link loss and resume


def lose_link(h):
    h.advance(3.05)
    assert h.session.state is SessionState.INTERRUPTED
    h.take()


def test_same_boot_offers_resume_from_acc_plus_one():
    h = streaming()
    h.take()
    h.reply(fr.Ack(5, 16), fr.Finished(2))
    lose_link(h)
    h.reply(Harness.status("HOLD", acc=5, done=3, flags="HL"))
    offer = h.rec.last("on_resume_offer")
    assert offer.same_boot and offer.from_seq == 6 and not offer.needs_home
    assert h.session.state is SessionState.RESUME_OFFERED
    assert h.take_data() == []  # no automatic resume
    h.session.resume_after_reconnect()
    cmd = h.command("RESUME")
    assert cmd.args == ("FROM", "6")
    h.reply(fr.Ok(cmd.id, "RESUME", "FROM 6"))
    assert h.take_data() == list(range(6, 22))  # the window of 16


def test_new_boot_requires_home_and_confirmation():
    h = streaming(["M03 S1000", "G00 Z5", "G00 X1 Y1", "G01 Z-1 F100", "G01 X5 Y1", "G01 X5 Y5"])
    h.take()
    h.reply(fr.Ack(5, 10), fr.Finished(3))
    lose_link(h)
    h.reply(Harness.status("IDLE", flags="", boot="0000BEEF"))
    offer = h.rec.last("on_resume_offer")
    assert not offer.same_boot and offer.needs_home and offer.from_seq == 4
    assert h.session.state is SessionState.RESTART_REQUIRED
    assert not h.session.confirm_restart()
    assert h.rec.last("on_error").code == "HOME_REQUIRED"
    h.reply(Harness.status("IDLE", flags="H", boot="0000BEEF"))
    assert h.session.confirm_restart()
    job = h.command("JOB")
    h.reply(fr.Ok(job.id, "JOB", job.args[0]))
    sent = [f.line for f in h.take() if isinstance(f, fr.Data)]
    preamble = ["M03 S1000", "G00 Z5.000", "G00 X1.000 Y1.000 F100", "G01 Z-1.000 F100"]
    assert sent == preamble + ["G01 X5 Y1", "G01 X5 Y5"]
    h.reply(fr.Ack(5, 10), fr.Finished(5))
    job = h.rec.last("on_job_finished")
    assert job.completed and job.done == 5


def test_machine_reset_mid_job_is_seen_and_not_resumed():
    h = streaming()
    h.take()
    h.reply(Harness.status("RUN", acc=7, done=1))
    h.take()
    h.reply(fr.Alarm("BOOT", "1234ABCD"), Harness.status("IDLE", flags="", boot="1234ABCD"))
    assert h.session.state is SessionState.RESTART_REQUIRED
    assert "MACHINE_RESET" in [e.code for e in h.rec.of("on_error")]
    h.advance(2.0)
    assert h.take_data() == []


def test_write_failure_is_a_link_loss_not_a_crash():
    h = streaming()

    def broken(_data):
        raise OSError("device unplugged")

    h.session._write = broken
    h.reply(fr.Ack(7, 16))
    assert h.session.state is SessionState.INTERRUPTED
    assert h.rec.last("on_link_changed").state == "DISCONNECTED"
    assert BOOT
