"""A tool change on a GRBL machine (issue 23): the stream waits for the idle machine, the
spindle stops, the tool is lifted near the top of the Z travel (``G53``, once homed) for
the prompt, and after it goes back where the change started (the lift again, the
spindle, the program's highest Z, its XY, down to its Z) before the program goes on;
the lines added carry the program's indices, so progress and the line map stay its own."""

from __future__ import annotations

import random
from dataclasses import replace

import pytest

from app.comm.grbl.dialect import tool_change_height
from app.comm.grbl.toolchange import state_after
from app.comm.modal import ModalState, modal_state
from tests.comm.grbl.harness import Harness
from tests.comm.grbl.simrig import SimRig

PROGRAM = ["M03 S1000", "G00 Z5", "G00 X10 Y20", "G01 Z-1 F100", "G01 X30", "G00 Z5", "M06 T2",
           "G01 Z-1 F100", "G01 X10", "G00 Z5", "M05"]
STOP = PROGRAM.index("M06 T2")


def _to_the_prompt(h: Harness, lines: list[str]) -> list[str]:
    """Start ``lines``; answer everything up to the tool change's sync; what was sent."""
    h.session.start_job(lines)
    sent = []
    while not h.rec.of("on_program_stop"):
        out = h.lines()
        assert out, "the stream stopped before the prompt"
        sent += out
        h.feed(*["ok"] * len(out))
    return sent


def test_the_tool_is_lifted_with_g53_for_the_prompt_and_brought_back_once_homed():
    h = Harness()
    h.answer_refresh()  # $132=30, no $27: the lift goes to 1 mm below the top, machine Z -1
    h.session.command("$H")
    h.feed("ok")
    sent = _to_the_prompt(h, PROGRAM)
    assert sent[-4:] == ["G00 Z5", "M05", "G53 G00 Z-1.000", "G4 P0"]  # stopped, lifted, then the prompt
    assert h.rec.of("on_program_stop")[-1].index == STOP and h.session.job.done == STOP - 1
    h.session.resume()
    assert h.lines() == ["G53 G00 Z-1.000", "M03 S1000", "G00 Z5.000", "G00 X30.000 Y20.000 F100",
                         "G01 Z-1 F100", "G01 X10", "G00 Z5", "M05", "G4 P0"]
    h.feed(*["ok"] * 9)
    job = h.rec.of("on_job_finished")[-1]
    assert job.completed and job.total == len(PROGRAM) and job.done == len(PROGRAM) - 1


def test_a_change_begun_at_depth_goes_back_down_at_the_feed_and_never_lifts_a_higher_tool():
    h = Harness()
    h.answer_refresh()
    lines = ["M03 S1000", "G00 Z5", "G00 X10 Y20", "G01 Z-1 F100", "M06 T2", "G01 X30"]
    sent = _to_the_prompt(h, lines)  # not homed: its machine Z says nothing; the program's top
    assert sent[-3:] == ["M05", "G00 Z5.000", "G4 P0"]
    h.session.resume()
    assert h.lines()[:4] == ["M03 S1000", "G00 Z5.000", "G00 X10.000 Y20.000 F100", "G01 Z-1.000 F100"]
    h = Harness()
    h.answer_refresh()
    h.session.command("$H")
    h.feed("ok")
    sent = _to_the_prompt(h, ["G00 Z9.5", "M06 T1", "G00 X1"])  # above the lift's work Z 9 already
    assert sent[-2:] == ["G00 Z9.5", "G4 P0"]
    h.session.resume()
    assert h.lines()[:2] == ["G00 Z9.500", "G00 X1"]


def test_the_height_is_the_top_of_the_travel_less_the_homing_pull_off():
    assert tool_change_height({132: "30.000", 27: "5.000"}) == -5.0
    assert tool_change_height({132: "30.000", 27: "0.2"}) == -1.0  # at least 1 mm off the switch
    assert tool_change_height({130: "150"}) is None
    down = {132: "30.000", 27: "2", 23: "4"}  # Z homes down
    assert tool_change_height(down) == -2.0  # the space is still [-max, 0]
    assert tool_change_height(down, "VNMZ,15,128") == 28.0  # unless the origin is set where it homes


def test_on_the_simulated_grbl_the_change_is_made_high_with_the_spindle_stopped_then_goes_on():
    rig = SimRig({27: 1})  # GRBL's default pull-off
    session, machine = rig.session, rig.machine
    assert rig.command("$H").ok
    rig.fresh_report()
    mark = len(machine.executed)
    assert session.start_job(PROGRAM, name="two tools")
    rig.until(lambda: bool(rig.rec.of("on_program_stop")), what="the tool change prompt")
    assert machine.mpos()[2] == pytest.approx(-1.0, abs=0.01)  # lifted near the top
    assert machine.motion.spindle_rpm == 0 and machine.gcode.spindle == 5
    x = machine.mpos()[0]
    assert rig.command("G91 G0 X-20 Y15").ok and rig.command("G90").ok  # the operator moves aside
    rig.until(lambda: session.grbl_status.state == "Idle" and machine.mpos()[0] < x - 19, what="moved aside")
    session.resume()
    rig.until(lambda: session.job is None, what="the job's end")
    assert rig.rec.of("on_job_finished")[-1].completed
    ran = rig.executed_since(mark)
    back = ran.index("G53 G00 Z-1.000", ran.index("G53 G00 Z-1.000") + 1)  # after the prompt
    assert ran[back:back + 4] == ["G53 G00 Z-1.000", "M03 S1000", "G00 Z5.000", "G00 X30.000 Y20.000 F100"]
    assert ran[back + 4:] == PROGRAM[STOP + 1:]


def _random_program(rng, n: int) -> list[str]:
    lines = []
    for _ in range(n):
        kind = rng.random()
        axes = " ".join(f"{a}{rng.uniform(-50, 50):.3f}" for a in "XYZ" if rng.random() < 0.5)
        feed = f" F{rng.choice([100, 250, 600])}" if rng.random() < 0.2 else ""
        if kind < 0.6:
            lines.append(f"G0{rng.choice('0123')} {axes}{feed}".strip())
        elif kind < 0.7:
            lines.append(rng.choice(["M03 S1000", "M03 S2400", "M05", "M02"]))
        elif kind < 0.8:
            lines.append(f"G04 P{rng.uniform(0, 1):.2f}")
        else:
            lines.append(f"G01{feed}".strip() if feed else "G04 P0")
    return lines


def test_the_state_at_a_change_is_what_reading_every_line_gives():
    rng = random.Random(23)
    for trial in range(300):
        lines = _random_program(rng, rng.randint(0, 60))
        before = modal_state(["M03 S500", "G00 X1 Y2 Z3 F50"], 2) if trial % 2 else ModalState()
        expected = replace(before)
        for line in lines:
            expected.apply(line)
        assert state_after(before, lines) == expected, (trial, lines)
