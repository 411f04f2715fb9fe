"""What the window's GRBL features ask of the session (issue 23), without threads: the
work systems through the frame protocol's words ($# and $G), overrides stepped from
what the machine will have, holds and door states in words, the alarm advice."""

from __future__ import annotations

import pytest

from app.comm.grbl import protocol as p
from app.comm.grbl.codes import HOLDS, hold_text, unlock_advice
from app.i18n import localize, set_language
from tests.comm.grbl.harness import WELCOME, Harness

PARAMETERS = ("[G54:-150.000,-150.000,-10.000]", "[G55:-100.000,-50.000,-12.500]",
              "[G56:0.000,0.000,0.000]", "[G57:0.000,0.000,0.000]", "[G58:0.000,0.000,0.000]",
              "[G59:0.000,0.000,0.000]", "[G28:0.000,0.000,0.000]", "[G30:0.000,0.000,0.000]",
              "[G92:0.000,0.000,0.000]", "[TLO:0.000]", "[PRB:0.000,0.000,0.000:0]")
REPORT = "<Idle|MPos:-100.000,-100.000,-5.000|FS:0,0>"


def results(h: Harness, verb: str) -> list:
    return [r for r in h.rec.of("on_command_done") if r.verb == verb]


def test_get_wcs_reads_offsets_and_parser_state_then_rows_in_the_frame_protocols_frame():
    h = Harness()
    h.answer_refresh()
    h.session.send_command("GET WCS")
    assert h.lines() == ["$#"]
    h.feed(*PARAMETERS, "ok")
    assert h.lines() == ["$G"]
    h.feed("[GC:G0 G55 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok")
    assert not results(h, "GET")  # answered once a report after it shows the machine now
    h.feed(REPORT)
    assert [r.info for r in results(h, "GET")] == ["WCS 55"]
    h.session.send_command("GET G55_X")
    h.session.send_command("GET G55_Z")
    h.session.send_command("GET G54_Y")
    # machine mm from the near end of the travel ($130-$132 150/150/30: GRBL's space is [-max, 0])
    assert [r.info for r in results(h, "GET")[1:]] == ["G55_X 50.000", "G55_Z 17.500", "G54_Y 0.000"]


def test_set_row_sends_g10_l2_in_grbl_coordinates_and_answers_from_the_new_parameters():
    h = Harness()
    h.answer_refresh()
    h.session.send_command("SET G56_Y 25.5")
    assert h.lines() == ["G21 G10 L2 P3 Y-124.500"]
    h.feed("ok")
    assert h.lines() == ["$#"]
    moved = "[G56:0.000,-124.500,0.000]"
    h.feed(*[row.replace("[G56:0.000,0.000,0.000]", moved) for row in PARAMETERS], "ok")
    h.feed(REPORT)
    assert [r.info for r in results(h, "SET")] == ["G56_Y 25.500"]


@pytest.mark.parametrize("args, code", [("SET G54_X abc", "BAD_ARGS"), ("SET G54_X inf", "BAD_ARGS")])
def test_set_row_refuses_what_is_not_a_number_and_sends_nothing(args, code):
    h = Harness()
    h.answer_refresh()
    h.session.send_command(args)
    assert h.lines() == [] and results(h, "SET")[-1].code == code


def test_set_wcs_selects_the_system_and_a_refusal_is_the_machines_error():
    h = Harness()
    h.answer_refresh(state="Alarm")
    h.session.send_command("SET WCS 57")
    assert h.lines() == ["G57"]
    h.feed("error:9")
    refused = results(h, "SET")[-1]
    assert not refused.ok and refused.code == "error:9" and "locked" in localize(refused.info)
    h.session.send_command("SET WCS 57")
    h.take()
    h.feed("ok", "[GC:G0 G57 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok", REPORT)
    assert results(h, "SET")[-1].info == "WCS 57"


def test_zero_writes_the_active_systems_zero():
    h = Harness()
    h.answer_refresh()
    h.session.send_command("$G")
    h.take()
    h.feed("[GC:G0 G59 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok")
    h.session.send_command("ZERO XY")
    assert h.lines() == ["G10 L20 P6 X0 Y0"]


def test_overrides_step_from_what_the_machine_will_have_not_from_the_last_report():
    h = Harness()
    h.answer_refresh()
    h.session.set_feed_override(110)
    h.session.set_feed_override(125)  # before any report: +10 then +10 +1*5, not +10 +10 +1*5 from 100
    sent = h.take().translate(None, b"?")
    assert sent == p.FEED_PLUS_10 + p.FEED_PLUS_10 + p.FEED_PLUS_1 * 5
    h.feed("<Idle|MPos:0,0,0|FS:0,0|Ov:100,100,100>")  # made before the bytes were read: not believed
    h.session.set_feed_override(130)
    assert h.take().translate(None, b"?") == p.FEED_PLUS_1 * 5
    h.feed("<Idle|MPos:0,0,0|FS:0,0|Ov:130,100,100>")
    h.session.set_feed_override(90)  # far from the value: reset to 100 then down
    assert h.take().translate(None, b"?") == p.FEED_100 + p.FEED_MINUS_10


def test_a_report_after_the_next_one_is_believed_over_what_was_asked():
    h = Harness()
    h.answer_refresh()
    h.session.set_spindle_override(150)
    h.take()
    h.feed("<Idle|MPos:0,0,0|FS:0,0>", "<Idle|MPos:0,0,0|FS:0,0|Ov:100,100,140>")  # the machine stopped short
    assert h.session.merger.overrides_now() == (100, 100, 140)
    h.session.set_spindle_override(150)
    assert h.take().translate(None, b"?") == p.SPINDLE_PLUS_10


@pytest.mark.parametrize("report, why", [
    ("<Hold:0|MPos:0,0,0|FS:0,0>", "Hold:0"), ("<Hold:1|MPos:0,0,0|FS:0,0>", "Hold:1"),
    ("<Door:2|MPos:0,0,0|FS:0,0>", "Door:2"), ("<Door|MPos:0,0,0|FS:0,0>", "Door:0"),
    ("<Idle|MPos:0,0,0|FS:0,0>", ""), ("<Alarm|MPos:0,0,0|FS:0,0>", ""),
])
def test_status_says_why_grbl_holds(report, why):
    h = Harness()
    h.answer_refresh()
    h.feed(report)
    status = h.rec.of("on_status")[-1]
    assert status.why == why
    assert bool(hold_text(why)) == bool(why)


def test_holds_and_alarm_advice_read_in_vietnamese():
    set_language("vi")
    try:
        for state in HOLDS:
            assert localize(hold_text(state)) != str(hold_text(state)), state
        for code in (None, 1, 2, 5, 9):
            assert localize(unlock_advice(code)) != str(unlock_advice(code)), code
    finally:
        set_language(None)
    assert "reset" in unlock_advice(1) and "home" in unlock_advice(9).lower()


def test_get_wcs_failing_for_now_is_not_a_machine_without_work_systems():
    h = Harness()
    h.answer_refresh()
    h.session.send_command("GET WCS")
    h.feed("error:8")  # $# refused while not idle (check mode, a cycle)
    assert [(r.ok, r.code) for r in results(h, "GET")] == [(False, "error:8")]
    h.session.send_command("GET WCS")
    h.take()
    h.feed(WELCOME.decode().strip())  # a reset cut it off
    assert [(r.ok, r.code) for r in results(h, "GET")][-1] == (False, "RESET")
    h.answer_refresh()
    h.session.send_command("GET WCS")
    h.feed("error:3")  # a firmware that has no $#: no work systems at all
    assert [(r.ok, r.code) for r in results(h, "GET")][-1] == (False, "UNSUPPORTED")
