"""A GRBL machine without homing (``$22=0``): it starts unlocked, ``$H`` is refused, so
nothing may wait for a homing: Start, the restart after a reset ("Start here", never
"Home and restart") and the alarm advice (issue 23)."""

from __future__ import annotations

from app.comm.grbl.codes import unlock_advice
from app.comm.grbl.settings import homing_enabled
from app.comm.listener import SessionState
from app.i18n import localize
from tests.comm.grbl.harness import WELCOME, Harness
from tests.comm.grbl.simrig import SimRig

S = SessionState
# the simulated machine powers up 20 mm below its Z switch: the work stays below it
LINES = ["M03 S1000", "G00 Z-15", "G00 X10 Y10"] + [f"G01 X{10 + (i % 2) * 20} Y{10 + i} F600"
                                                      for i in range(40)] + ["G00 Z-15", "M05"]


def test_homing_is_bit_0_of_dollar_22_and_assumed_before_it_is_read():
    assert homing_enabled({}) and homing_enabled({22: "1"}) and homing_enabled({22: "7"})
    assert not homing_enabled({22: "0"}) and not homing_enabled({22: "6"})  # grblHAL: other bits only


def test_the_status_is_trusted_without_homing_only_when_the_machine_has_none():
    h = Harness()
    h.answer_refresh()
    assert not h.session.status.homed  # $22 unknown: assumed to home
    h.feed("$22=1", "ok")
    h.session.command("$$")
    h.take()
    h.feed("$22=0", "ok", "<Idle|MPos:0,0,0|FS:0,0>")
    assert h.session.status.homed and not h.session.homed  # nothing to home; it never homed


def test_a_machine_without_homing_runs_and_restarts_after_a_reset_without_home():
    rig = SimRig({21: 0, 22: 0})  # no switches: no hard limits, no homing
    session, machine = rig.session, rig.machine
    assert not machine.locked and session.status.state == "IDLE" and session.status.homed
    assert session.start_job(LINES, name="square")
    rig.until(lambda: session.job is not None and session.job.done >= 10, what="ten lines done")
    machine.soft_reset()  # someone else resets it while it moves: alarm 3, the position lost
    rig.until(lambda: session.state is S.RESTART_REQUIRED, what="the offer")
    offer = rig.rec.of("on_resume_offer")[-1]
    assert not offer.needs_home and "no homing" in localize(offer.reason)
    rig.until(lambda: session.status.state == "ALARM", what="the alarm report")
    advice = localize(session.unlock_advice())
    assert "no homing" in advice and "($H)" not in advice
    assert not session.confirm_restart()  # refused in alarm: unlock first
    refusal = rig.rec.of("on_error")[-1]
    assert "unlock ($X)" in localize(refusal.text) and "$H" not in localize(refusal.text)
    assert rig.command("$X").ok
    rig.until(lambda: session.status.state == "IDLE" and session.state is S.RESTART_REQUIRED, what="idle")
    mark = len(machine.executed)
    assert session.confirm_restart()
    rig.until(lambda: session.job is None, what="the restarted job to end")
    assert rig.rec.of("on_job_finished")[-1].completed
    ran = rig.executed_since(mark)
    start = offer.from_seq
    assert ran[-(len(LINES) - start):] == LINES[start:]  # from the offered line on, each once
    assert "$H" not in {e.text for e in rig.rec.of("on_frame") if e.direction == "tx"}


def test_a_restart_after_an_unasked_reset_still_asks_for_home_on_a_machine_that_homes():
    h = Harness()
    h.answer_refresh()
    h.session.start_job(["G01 X1 F100", "G01 X2", "G01 X3"])
    h.feed("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok", "ok", "ok")
    h.feed(WELCOME.decode().strip())
    assert h.rec.of("on_resume_offer")[-1].needs_home


def test_the_alarm_advice_without_homing_never_says_home():
    for code in (None, 1, 3, 9):
        text = localize(unlock_advice(code, homing=False))
        assert "($H)" not in text and "homing" in text, (code, text)


def test_the_words_for_a_machine_without_homing_read_in_vietnamese():
    from app.i18n import gettext, set_language

    set_language("vi")
    try:
        for code in (None, 1, 3):
            text = unlock_advice(code, homing=False)
            assert gettext(text.template) != text.template, code
        assert localize(unlock_advice(None, homing=False)).startswith("Máy đang báo động")
    finally:
        set_language(None)


def test_start_here_after_a_link_loss_runs_without_home_on_a_machine_without_homing():
    rig = SimRig({21: 0, 22: 0})
    session, machine = rig.session, rig.machine
    assert session.start_job(LINES)
    rig.until(lambda: session.job is not None and session.job.done >= 5, what="five lines done")
    rig.sim.wires["usb_up"].set_cut(True)
    rig.until(lambda: session.state is S.INTERRUPTED, what="the link lost")
    rig.until(lambda: machine.motion.state == "IDLE", what="its buffer run")
    rig.sim.wires["usb_up"].set_cut(False)
    rig.until(lambda: session.state is S.RESTART_REQUIRED and session.status.state == "IDLE",
              what="the offer")
    offer = rig.rec.of("on_resume_offer")[-1]
    assert not offer.needs_home and session.status.homed
    mark, sent = len(machine.executed), len(rig.rec.of("on_frame"))
    assert session.confirm_restart()  # the reset at rest leaves it unlocked: no $H, no $X
    rig.until(lambda: session.job is None and session.state is S.READY, what="the restarted job's end")
    assert rig.rec.of("on_job_finished")[-1].completed
    ran = rig.executed_since(mark)
    start = rig.rec.of("on_resume_offer")[-1].from_seq
    assert ran[-(len(LINES) - start):] == LINES[start:]
    assert not {"$H", "$X"} & {e.text for e in rig.rec.of("on_frame")[sent:] if e.direction == "tx"}
