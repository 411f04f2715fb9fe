"""The sans-IO GRBL session against a machine scripted by hand (no threads, no sleeps)."""

from __future__ import annotations

import pytest

from app.comm.grbl import protocol as p
from app.comm.grbl.codes import error_text
from app.comm.grbl.jobflow import held_modes
from app.comm.grbl.operations import _override_bytes
from app.comm.grbl.protocol import parse_line
from app.comm.listener import SessionState
from tests.comm.grbl.harness import WELCOME, Harness


def test_nothing_but_status_queries_before_the_machine_speaks():
    h = Harness(greet=False)
    h.advance(1.0)
    assert set(h.take()) == {ord("?")}
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    assert h.lines() == ["$I", "$$", "$#", "$G"]


def test_connect_reads_machine_and_becomes_ready():
    h = Harness()
    assert h.lines() == ["$I", "$$", "$#", "$G"]
    h.answer_refresh()
    s = h.session
    assert s.state is SessionState.READY
    assert s.settings[130] == "150.000" and s.parameters["G54"] == "-150.000,-150.000,-10.000"
    assert s.info.planner_blocks == 15 and s.info.build.startswith("1.1h")
    assert s.status.position == pytest.approx((50.0, 50.0, 5.0))
    assert s.grbl_status.mpos == pytest.approx((-100.0, -100.0, -5.0))


@pytest.mark.parametrize("line, flavour, version", [
    ("Grbl 1.1h ['$' for help]", "grbl", "1.1h"),
    ("GrblHAL 1.1f ['$' or '$HELP' for help]", "grblhal", "1.1f"),
])
def test_welcome_names_the_flavour(line, flavour, version):
    h = Harness(greet=False)
    h.feed(line)
    info = h.rec.of("on_machine_info")[-1]
    assert (info.flavour, info.version) == (flavour, version)
    assert h.session.boots == 1


def test_reports_keep_sticky_fields_and_convert_positions():
    h = Harness()
    h.answer_refresh()
    h.feed("<Run|WPos:1.000,2.000,3.000|FS:300,1000|Ov:120,50,100|A:S>")
    st = h.session.grbl_status
    assert st.wco == (-150.0, -150.0, -10.0)  # from the earlier report
    assert st.mpos == pytest.approx((-149.0, -148.0, -7.0))
    assert st.overrides == (120, 50, 100) and st.accessories == "S"
    assert "P" in h.session.status.flags and h.session.status.state == "RUN"
    h.feed("<Idle|WPos:1.000,2.000,3.000|FS:0,0|Ov:100,100,100>")
    assert h.session.grbl_status.accessories == ""


def test_character_counting_never_overfills_the_buffer():
    h = Harness()
    h.answer_refresh()
    lines = [f"G01 X{i}.123 Y{i}.456 F300" for i in range(200)]
    assert h.session.start_job(lines)
    in_flight, sent_all = [], []
    while True:
        sent = h.lines()
        sent_all += sent
        in_flight += [len(x) + 1 for x in sent]
        assert sum(in_flight) <= 128
        if not in_flight:
            break
        in_flight.pop(0)
        h.feed("ok")
    assert sent_all[:3] == ["$G", "$#", "G21 G90 G94 G17"] and sent_all[3:-1] == lines
    assert sent_all[-1] == "G4 P0"
    job = h.rec.of("on_job_finished")[-1]
    assert job.completed and job.done == 199


def test_error_mid_job_stops_at_once_naming_the_line_then_resets_when_held():
    h = Harness()
    h.answer_refresh()
    lines = ["G01 X1 F100", "G01 X2", "G99 X3", "G01 X4", "G01 X5"]
    h.session.start_job(lines, line_map=[10, 11, 12, 13, 14])
    h.take()
    h.feed("ok", "ok", "ok", "ok", "ok", "error:20")  # $G, $#, preamble, X1, X2, then the G99 line
    data = h.take()
    assert b"!" in data and b"\x18" not in data
    err = h.rec.of("on_error")[-1]
    assert "line 12" in err.text and "error 20" in err.text and str(error_text(20)) in err.text
    assert h.session.state is SessionState.STOPPING
    h.feed("ok", "<Hold:1|MPos:0,0,0|FS:0,0>")
    assert b"\x18" not in h.take()
    h.feed("<Hold:0|MPos:0,0,0|FS:0,0>")
    assert b"\x18" not in h.take()  # the first report at rest may have been asked before the hold
    h.feed("<Hold:0|MPos:0,0,0|FS:0,0>")
    assert b"\x18" in h.take()
    h.feed(WELCOME.decode().strip())
    job = h.rec.of("on_job_finished")[-1]
    assert not job.completed and job.refused == 2 and "buffer" in job.reason
    assert h.session.state is SessionState.READY


def test_check_mode_lists_every_refused_line():
    h = Harness()
    h.answer_refresh(state="Check")
    h.session.start_job(["G01 X1 F100", "M06 X", "G01 X2", "G77"])
    h.take()
    h.feed("ok", "ok", "ok", "error:36", "ok", "error:20")
    h.take()
    h.feed("ok")
    job = h.rec.of("on_job_finished")[-1]
    assert not job.completed and "2 refused" in job.reason


def test_program_stop_waits_for_the_machine_then_prompts():
    h = Harness()
    h.answer_refresh()
    h.session.start_job(["G01 X1 F100", "M06 T2", "G01 X2"])
    assert h.lines() == ["$G", "$#", "G21 G90 G94 G17", "G01 X1 F100", "G4 P0"]
    h.feed("ok", "ok", "ok", "ok")
    assert not h.rec.of("on_program_stop")
    h.feed("ok")  # the sync: everything before has finished
    stop = h.rec.of("on_program_stop")[-1]
    assert (stop.index, stop.code, stop.tool) == (1, 6, 2)
    h.advance(0.5)
    assert h.lines() == []
    h.session.resume()
    assert h.lines() == ["G01 F100", "G01 X2", "G4 P0"]  # back as it was (no Y, no Z known: the feed)


def test_a_tool_change_stops_the_spindle_for_the_prompt_and_restarts_it():
    h = Harness()
    h.answer_refresh()
    h.session.start_job(["M03 S1000", "G01 X1 F100", "M06 T2", "G01 X2", "M01", "G01 X3"])
    assert h.lines() == ["$G", "$#", "G21 G90 G94 G17", "M03 S1000", "G01 X1 F100", "M05", "G4 P0"]
    h.feed("ok", "ok", "ok", "ok", "ok", "ok")
    assert not h.rec.of("on_program_stop") and h.session.job.done == -1
    h.feed("ok")  # the sync: the spindle has stopped, everything before has finished
    assert h.rec.of("on_program_stop")[-1].tool == 2 and h.session.job.done == 1
    h.session.resume()
    assert h.lines() == ["M03 S1000", "G01 F100", "G01 X2", "G4 P0"]  # M01 keeps the spindle as GRBL's M0
    h.feed("ok", "ok", "ok", "ok")
    assert h.rec.of("on_program_stop")[-1].code == 1 and h.session.job.done == 3


def test_settings_write_is_sent_alone_and_waited_for():
    h = Harness()
    h.answer_refresh()
    h.session.write_setting(110, 500)
    h.session.command("$G")
    assert h.lines() == ["$110=500"]
    h.advance(0.3)
    assert h.lines() == []
    h.feed("ok")
    assert h.lines() == ["$G"] and h.session.settings[110] == "500"


def test_silence_degrades_then_loses_the_link_but_not_while_homing():
    h = Harness()
    h.answer_refresh()
    h.advance(2.1)
    assert h.rec.of("on_link_changed")[-1].state == "DEGRADED"
    h.advance(1.0)
    assert h.rec.of("on_link_changed")[-1].state == "LOST"
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    h.session.home()
    h.advance(10.0)
    assert h.rec.of("on_link_changed")[-1].state == "CONNECTED"


def cut_off(h) -> None:
    """Ten moves; six answers (the $G, the $#, the preamble, lines 0-2), a report with two
    planner blocks in use (line 0 finished), then the link lost."""
    h.answer_refresh()
    h.session.command("$H")
    h.feed("ok")
    h.session.start_job([f"G01 X{i} F100" for i in range(10)])
    h.take()
    h.feed("ok", "ok", "ok", "ok", "ok", "ok", "<Run|MPos:0,0,0|FS:100,0|Bf:13,100>")
    h.advance(3.5)
    assert h.session.state is SessionState.INTERRUPTED


def test_link_loss_mid_job_offers_start_here_after_last_finished_line():
    h = Harness()
    cut_off(h)
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    offer = h.rec.of("on_resume_offer")[-1]
    assert offer.from_seq == 3 and h.session.state is SessionState.RESTART_REQUIRED
    h.take()
    assert h.session.confirm_restart()
    assert h.lines() == []  # a line cut off mid-way may wait in GRBL's buffer: reset first
    h.feed("<Run|MPos:0,0,0|FS:100,0>")
    assert b"\x18" not in h.take()  # never while it moves (alarm 3, the position lost)
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    assert b"\x18" in h.take()
    h.feed(WELCOME.decode().strip())
    sent = h.lines()
    assert sent[:4] == ["$I", "$$", "$#", "$G"] and sent[4:6] == ["G21 G90 G94 G17", "G54"]
    assert "G01 X3 F100" in sent and h.session.homed  # a reset at rest keeps the position


def test_the_offered_line_follows_what_the_machine_finishes_until_the_operator_answers():
    h = Harness()
    cut_off(h)
    h.feed("<Run|MPos:0,0,0|FS:100,0|Bf:12,100>")  # back while the machine still runs its buffer
    offered = lambda: [o.from_seq for o in h.rec.of("on_resume_offer")]  # noqa: E731
    assert offered() == [1]
    h.feed("<Run|MPos:0,0,0|FS:100,0|Bf:14,100>")  # one block in use: lines 0 and 1 finished
    assert offered() == [1, 2] and h.session.state is SessionState.RESTART_REQUIRED
    h.feed("<Run|MPos:0,0,0|FS:100,0|Bf:14,100>")  # nothing new: no new offer
    h.feed("<Idle|MPos:0,0,0|FS:0,0|Bf:15,100>")
    assert offered() == [1, 2, 3]
    assert "line 4" in h.rec.of("on_resume_offer")[-1].reason and h.rec.of("on_progress")[-1].done == 2
    h.take()
    assert h.session.confirm_restart()
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    assert b"\x18" in h.take()
    h.feed(WELCOME.decode().strip())
    sent = h.lines()
    assert "G01 X3 F100" in sent and "G01 X2 F100" not in sent  # each line once


def test_a_confirmed_restart_waiting_for_rest_starts_after_what_finished_meanwhile():
    h = Harness()
    cut_off(h)
    h.feed("<Run|MPos:0,0,0|FS:100,0|Bf:12,100>")
    assert h.rec.of("on_resume_offer")[-1].from_seq == 1
    assert h.session.confirm_restart()  # while the machine still runs
    h.feed("<Run|MPos:0,0,0|FS:100,0|Bf:14,100>")
    assert b"\x18" not in h.take()
    h.feed("<Idle|MPos:0,0,0|FS:0,0|Bf:15,100>")
    assert b"\x18" in h.take() and len(h.rec.of("on_resume_offer")) == 1
    h.feed(WELCOME.decode().strip())
    sent = h.lines()
    assert "G01 X3 F100" in sent and not {"G01 X0 F100", "G01 X1 F100", "G01 X2 F100"} & set(sent)


def test_a_restart_after_a_reset_restores_the_work_system_and_coolant_the_job_ran_in():
    h = Harness()
    h.answer_refresh()
    lines = ["M03 S1000", "G00 Z5", "G00 X1 Y1", "G01 Z-1 F100", "G01 X5", "G01 Y5", "G01 X1"]
    h.session.start_job(lines)
    assert h.lines()[:3] == ["$G", "$#", "G21 G90 G94 G17"]  # the modes and offsets read first
    h.feed("[GC:G0 G55 G17 G21 G90 G94 M5 M8 T0 F0 S0]", "ok", "ok", "ok", "ok", "ok", "ok", "ok", "ok")
    h.feed("<Run|MPos:0,0,0|FS:100,0|Bf:14,100>")  # lines 0-4 answered, 4 may still be planned
    h.feed(WELCOME.decode().strip())  # reset by someone else: GRBL is back in G54, coolant off
    offer = h.rec.of("on_resume_offer")[-1]
    assert offer.needs_home and offer.from_seq == 4 and h.session.state is SessionState.RESTART_REQUIRED
    h.answer_refresh()  # its $G now says G54 M9: not what the job ran in
    h.take()
    assert h.session.confirm_restart()
    sent = h.lines()
    assert sent[:3] == ["G21 G90 G94 G17", "G55", "M8"]  # no second $G: the job's own modes
    assert sent[3:7] == ["M03 S1000", "G00 Z5.000", "G00 X1.000 Y1.000 F100", "G01 Z-1.000 F100"]
    assert sent[7] == "G01 X5"
    assert h.session.job.modes == ("G55", "M8")  # a second cut-off restarts the same way


@pytest.mark.parametrize("reconnect", ["<Idle|MPos:0,0,0|FS:0,0>", None])
def test_stop_abandons_a_job_cut_off_by_a_link_loss(reconnect):
    h = Harness()
    h.answer_refresh()
    h.session.start_job([f"G01 X{i} F100" for i in range(10)])
    h.feed("ok", "ok", "ok")
    h.advance(3.5)
    assert h.session.state is SessionState.INTERRUPTED
    if reconnect:
        h.feed(reconnect)
        assert h.session.state is SessionState.RESTART_REQUIRED
    h.take()
    h.session.stop()  # the alert's "Abandon job", or Stop
    assert h.session.state is SessionState.READY and h.session.job is None
    assert b"!" in h.take()  # held, then reset once at rest: the buffer may still be running
    assert not h.session.confirm_restart()
    ended = h.rec.of("on_job_finished")
    assert len(ended) == 1 and not ended[0].completed and "abandoned" in ended[0].reason


@pytest.mark.parametrize("then", ["stop", "lost"])
def test_start_here_after_a_link_loss_waits_for_the_reset_and_can_be_stopped_or_cut_off(then):
    h = Harness()
    h.answer_refresh()
    h.session.start_job([f"G01 X{i} F100" for i in range(10)])
    h.feed("ok", "ok", "ok", "ok")
    h.advance(3.5)
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    assert h.session.confirm_restart()
    assert h.session.state is SessionState.STARTING  # the job is starting: reset first
    h.take()
    if then == "stop":
        h.session.stop()
        assert h.session.state is SessionState.READY and not h.rec.of("on_job_finished")[-1].completed
        h.feed(WELCOME.decode().strip())  # the reset stop() and the restart both asked for
        assert h.session.job is None and h.session.state is SessionState.READY
        return
    h.advance(3.5)  # silent again before the machine came to rest
    assert h.session.state is SessionState.INTERRUPTED
    h.feed("<Idle|MPos:0,0,0|FS:0,0>")
    assert h.session.state is SessionState.RESTART_REQUIRED and len(h.rec.of("on_resume_offer")) == 2
    assert h.session.confirm_restart()
    h.feed("<Idle|MPos:0,0,0|FS:0,0>", WELCOME.decode().strip())
    assert h.session.state is SessionState.STREAMING and "G01 X2 F100" in h.lines()


@pytest.mark.parametrize(("state", "modes"), [
    ("G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0", ("G54",)),
    ("G1 G59 G17 G21 G90 G94 M3 M7 M8 T1 F100 S900", ("G59", "M7", "M8")),
    ("", ()),
])
def test_held_modes_from_the_parser_state(state, modes):
    assert held_modes(state) == modes


def test_status_is_polled_faster_while_running():
    h = Harness()
    h.answer_refresh()
    h.take()
    h.advance(1.0, step=0.01)
    idle = h.take().count(b"?")
    h.session.start_job(["G01 X1 F100"])
    h.advance(0.3, step=0.01)
    h.take()
    h.advance(1.0, step=0.01)
    assert 4 <= idle <= 6 and 9 <= h.take().count(b"?") <= 11


@pytest.mark.parametrize("current, target, expected", [
    (100, 130, p.FEED_PLUS_10 * 3),
    (100, 97, p.FEED_MINUS_1 * 3),
    (150, 100, p.FEED_100),
    (180, 105, p.FEED_100 + p.FEED_PLUS_1 * 5),
    (100, 100, b""),
])
def test_override_bytes(current, target, expected):
    got = _override_bytes(current, target, p.FEED_100, (p.FEED_PLUS_10, p.FEED_MINUS_10),
                          (p.FEED_PLUS_1, p.FEED_MINUS_1))
    assert got == expected


def test_grblhal_buffer_size_from_its_build_info():
    h = Harness(greet=False)
    h.take()
    h.feed("GrblHAL 1.1f ['$' or '$HELP' for help]")
    h.take()
    h.feed("[VER:1.1f.20230919:]", "[OPT:VNMSL,35,1024,3,0]", "[FIRMWARE:grblHAL]", "ok")
    assert h.session.counter.capacity == 1024 and h.session.info.flavour == "grblhal"


def test_garbage_lines_are_named_not_fatal():
    h = Harness()
    h.answer_refresh()
    h.session.feed(b"<Idle|MPos:nan,0,0>\r\n\xff\xfe\r\n")
    assert any("unreadable" in e.text for e in h.rec.of("on_log"))
    assert isinstance(parse_line("<Idle|MPos:nan,0,0>"), p.Unknown)


def test_every_grbl_code_and_setting_reads_in_vietnamese():
    from app.comm.grbl.codes import ALARMS, ERRORS, SETTINGS, alarm_text, setting_info
    from app.i18n import gettext, localize, set_language

    set_language("vi")
    try:
        untranslated = [t for t in [*ERRORS.values(), *ALARMS.values()] if gettext(t) == t]
        untranslated += [t for s in SETTINGS.values() for t in (s.name, s.meaning) if gettext(t) == t]
        assert not untranslated
        assert localize(alarm_text(1)).startswith("chạm công tắc hành trình")
        assert localize(setting_info(131).name) == "hành trình tối đa trục Y"
    finally:
        set_language(None)


@pytest.mark.parametrize("verb, line", [
    ("SPINDLE 1200", "M3 S1200"), ("SPINDLE OFF", "M5"), ("ZERO XY", "G10 L20 P1 X0 Y0"),
    ("HOME", "$H"), ("JOG Z -1 300", "$J=G91 G21 Z-1.000 F300"), ("G0 X10", "G0 X10"), ("$$", "$$"),
])
def test_frame_protocol_verbs_become_grbl_lines(verb, line):
    h = Harness()
    h.answer_refresh()
    h.session.send_command(verb)
    assert h.lines() == [line]


def test_frame_protocol_queries_answered_from_what_grbl_reported():
    h = Harness()
    h.answer_refresh()  # WCO -150,-150,-10 with $130-$132 150/150/30 and $23=3
    h.session.send_command("GET OFFSET_Z")
    h.session.send_command("SET KP_X 2")
    h.session.send_command("SET OPTSTOP 0")
    results = h.rec.of("on_command_done")[-3:]
    assert results[0].info == "OFFSET_Z 20.000" and results[1].code == "UNSUPPORTED"
    assert not h.session.optional_stop and h.lines() == []
    h.session.list_sd()
    assert h.rec.of("on_command_done")[-1].code == "UNSUPPORTED"


def test_done_follows_the_planner_size_without_buffer_reports():
    h = Harness()
    h.answer_refresh()  # [OPT:V,15,128]; $10=1: no Bf in the reports
    lines = [f"G01 X{i % 10} F100" for i in range(40)]
    h.session.start_job(lines)
    for _ in range(33):  # $G, $#, the preamble and 30 lines answered
        h.take()
        h.feed("ok")
    h.feed("<Run|MPos:0,0,0|FS:100,0>")
    progress = h.session.job.progress()
    assert progress.acked == 29 and progress.done == 29 - 15


def test_frame_protocol_get_and_zero_wait_for_what_grbl_reports():
    h = Harness()
    h.session.send_command("GET OFFSET_X")  # nothing known yet: answered later, not guessed
    assert not [r for r in h.rec.of("on_command_done") if r.verb == "GET"]
    h.answer_refresh()  # $$ and a report with WCO -150,-150,-10
    got = [r for r in h.rec.of("on_command_done") if r.verb == "GET"]
    assert len(got) == 1 and got[0].info == "OFFSET_X 0.000"
    h.session.send_command("ZERO X")
    assert h.lines() == ["G10 L20 P1 X0"]
    h.feed("ok")
    assert not [r for r in h.rec.of("on_command_done") if r.verb == "ZERO"]
    h.feed("<Idle|MPos:-100.000,-100.000,-5.000|FS:0,0|WCO:-100.000,-150.000,-10.000>")
    zero = [r for r in h.rec.of("on_command_done") if r.verb == "ZERO"]
    assert len(zero) == 1 and zero[0].info == "X50.000 Y0.000 Z20.000"


def test_the_time_spent_preparing_a_big_job_is_not_the_machine_s_silence(monkeypatch):
    """Start reads nothing while it prepares the lines (a million take a second or two):
    the link stays up, and a real silence after it is still seen."""
    from app.comm.grbl import jobflow

    h = Harness()
    h.answer_refresh()
    h.advance(0.5)
    h.feed("<Idle|MPos:-100.000,-100.000,-5.000|FS:0,0>")
    prepare = jobflow.grbl_lines

    def slow_prepare(*args, **kwargs):
        h.now += 3.5  # the host busy for longer than the lost limit
        return prepare(*args, **kwargs)

    monkeypatch.setattr(jobflow, "grbl_lines", slow_prepare)
    changes = len(h.rec.of("on_link_changed"))
    assert h.session.start_job(["G00 X1", "G01 X2 F600"])
    assert h.rec.of("on_link_changed")[changes:] == []  # neither degraded nor lost
    h.advance(3.1)  # then the machine says nothing: lost as always
    assert h.rec.of("on_link_changed")[-1].state == "LOST"
