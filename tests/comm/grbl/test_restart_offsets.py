"""A restart after a cut-off resets GRBL (or GRBL was reset), which clears the G92 and
tool length offsets with the rest of the parser state; the job read them (``$#``) when
it started, and the restart sets them again, after the units, work system and coolant
(``$G``) and before any move (issue 23)."""

from __future__ import annotations

import pytest

from app.comm.listener import SessionState
from tests.comm.grbl.harness import WELCOME, Harness
from tests.comm.grbl.simrig import SimRig

S = SessionState
PARAMETERS = ("[G54:-150.000,-150.000,-10.000]", "[G55:-100.000,-90.000,-12.000]", "[G92:5.000,-3.000,1.500]",
              "[TLO:0.250]")


def test_the_restart_sets_g92_and_the_tool_length_offset_from_where_the_machine_stands():
    h = Harness()
    h.answer_refresh()
    h.session.start_job(["G00 Z5", "G00 X1 Y1", "G01 Z-1 F100", "G01 X5"])
    assert h.lines()[:3] == ["$G", "$#", "G21 G90 G94 G17"]
    h.feed("[GC:G0 G55 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok", *PARAMETERS, "ok", "ok", "ok", "ok", "ok")
    assert h.session.job.offsets == ((5.0, -3.0, 1.5), 0.25)
    h.feed(WELCOME.decode().strip())  # reset by someone else: G92 and G43.1 are gone
    h.answer_refresh()  # MPos -100,-100,-5 once homed again
    h.take()
    assert h.session.confirm_restart()
    sent = h.lines()
    assert sent[:4] == ["G21 G90 G94 G17", "G55", "G43.1 Z0.250", "G92 X-5.000 Y-7.000 Z5.250"]
    assert sent[4].startswith("G00 Z5")  # the position comes after: it is in the restored frame
    assert h.session.job.offsets == ((5.0, -3.0, 1.5), 0.25)  # a second cut-off restores them again


def test_no_offset_line_when_none_was_in_force_and_no_parameters_read_in_check_mode():
    h = Harness()
    h.answer_refresh(state="Check")
    h.session.start_job(["G01 X1 F100"])
    assert h.lines()[:2] == ["$G", "G21 G90 G94 G17"]  # GRBL refuses $# in check mode (error 8)
    h = Harness()
    h.answer_refresh()
    h.session.start_job(["G01 X1 F100", "G01 X2"])
    h.feed("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", "ok", "[G92:0.000,0.000,0.000]", "[TLO:0.000]", "ok",
           "ok", "ok")
    h.feed(WELCOME.decode().strip())
    h.answer_refresh()
    h.take()
    assert h.session.confirm_restart()
    assert h.lines()[:3] == ["G21 G90 G94 G17", "G54", "G01 X1 F100"]


def test_after_a_link_loss_the_machines_g92_is_what_it_was_before_the_restart_reset_it():
    rig = SimRig({21: 0, 22: 0})  # no switches: runs without homing
    session, machine = rig.session, rig.machine
    assert rig.command("G92 X5 Y-3").ok  # as the operator set it, before the job
    before = tuple(machine.gcode.g92)
    assert any(before)
    lines = ["G00 Z-15", "G00 X10 Y10"] + [f"G01 X{10 + (i % 2) * 20} Y{10 + i} F600" for i in range(30)]
    assert session.start_job(lines)
    rig.until(lambda: session.job is not None and session.job.done >= 5, what="five lines done")
    rig.sim.wires["usb_up"].set_cut(True)  # the link lost: GRBL runs what its buffer holds
    rig.until(lambda: session.state is S.INTERRUPTED, what="the link lost")
    rig.until(lambda: machine.motion.state == "IDLE", what="its buffer run")
    rig.sim.wires["usb_up"].set_cut(False)
    rig.until(lambda: session.state is S.RESTART_REQUIRED, what="the offer")
    mark = len(machine.executed)
    assert session.confirm_restart()  # reset at rest first (G92 cleared), then the job again
    rig.until(lambda: session.job is not None and session.job.boot == session.boots
              and session.job.acked >= session.job.done + 2, what="the restarted job under way")
    ran = rig.executed_since(mark)
    # the simulated machine reports its encoders' MPos (a servo), a few microns from the
    # parser's position that G92 counts from; a stepper GRBL reports the parser's own
    same = pytest.approx(before, abs=0.005)
    assert ran[0] == "G54" and ran[1].startswith("G92 ") and machine.gcode.g92 == same
    rig.until(lambda: session.job is None, what="the job's end")
    assert rig.rec.of("on_job_finished")[-1].completed and machine.gcode.g92 == same
