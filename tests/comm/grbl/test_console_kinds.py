"""What the consoles hide of GRBL's traffic (issue 23): the polled ``?`` reports, the job's
lines and their ``ok``; what they show: every command and its ``ok``, messages, errors,
and the report that answers an operator's own ``?``."""

from __future__ import annotations

import io

from app.comm.grbl.console import GrblPrinter
from tests.comm.grbl.harness import Harness

REPORT = "<Idle|MPos:0.000,0.000,0.000|FS:0,0>"


def _frames(h: Harness, direction: str) -> list[tuple[str, str]]:
    return [(e.kind, e.text) for e in h.rec.of("on_frame") if e.direction == direction]


def test_a_commands_ok_is_shown_a_job_lines_ok_and_the_polls_are_not():
    h = Harness()
    h.answer_refresh()
    h.rec.events.clear()
    h.session.send_command("$G")
    h.feed("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok")
    h.session.start_job(["G01 X1 F100"])
    h.feed("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok", "[G92:0.000,0.000,0.000]", "[MSG:Pgm End]",
           "ok", "ok", REPORT)
    rx = _frames(h, "rx")
    assert rx[:2] == [("rx", "[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]"), ("rx", "ok")]  # the command's
    kinds = [kind for kind, _ in rx[2:]]  # the job's $G, $#, preamble, then a report
    assert kinds == ["preamble", "ok", "preamble", "rx", "ok", "ok", "<"]  # a message is always shown
    assert {kind for kind, _ in _frames(h, "tx")} == {"command", "preamble", "job", "sync"}


def test_the_operators_question_mark_is_answered_by_the_next_report_shown_in_the_console():
    h = Harness()
    h.answer_refresh()
    h.rec.events.clear()
    cid = h.session.send_command("?")
    assert h.take() == b"?"  # the real-time byte, no line: nothing to count, no ok to wait for
    assert _frames(h, "tx") == [("command", "?")]
    h.feed(REPORT)
    assert _frames(h, "rx") == [("report", REPORT)]
    answer = [r for r in h.rec.of("on_command_done") if r.id == cid]
    assert len(answer) == 1 and answer[0].ok and answer[0].info == REPORT
    h.feed(REPORT)
    assert _frames(h, "rx")[-1] == ("<", REPORT)  # the polls after it are hidden again


def test_a_question_mark_waiting_when_the_link_is_lost_fails_with_it():
    h = Harness()
    h.answer_refresh()
    cid = h.session.send_command("?")
    h.advance(3.5)
    answer = [r for r in h.rec.of("on_command_done") if r.id == cid]
    assert len(answer) == 1 and answer[0].code == "LINK_LOST"


def test_a_setting_typed_in_the_console_is_sent_alone_and_waited_for():
    h = Harness()
    h.answer_refresh()
    h.session.send_command("$10=3")
    h.session.send_command("$$")
    assert h.lines() == ["$10=3"]  # GRBL stops reading while it writes its EEPROM
    h.feed("ok")
    assert h.lines() == ["$$"]


def test_the_quiet_command_line_console_prints_commands_and_the_asked_report_only():
    h = Harness()
    out = io.StringIO()
    printer = GrblPrinter(out, quiet=True)
    h.answer_refresh()
    for name, event in h.rec.events:
        if name == "on_frame":
            printer.on_frame(event)
    text = out.getvalue()
    assert "> $$" in text and "< $130=150.000" in text and "< <Idle" not in text
