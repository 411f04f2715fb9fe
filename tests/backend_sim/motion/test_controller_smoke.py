"""Smoke test of the MotionController API the CNC MCU layer uses."""

from backend_sim.motion import DialectParser, Finished, MotionController
from backend_sim.motion.accuracy import home


def test_home_then_run_a_few_lines():
    ctl = MotionController(start_mm=(20.0, 30.0, 25.0))
    home(ctl)
    assert ctl.homed and ctl.measured_mm == (0.0, 0.0, 30.0)
    parser = DialectParser(position=ctl.commanded_mm)
    for seq, line in enumerate(["G00 X5 Y5", "G01 Z-0.5 F200", "G01 X10 F400", "M30"]):
        ctl.enqueue(parser.parse(seq, line))
    assert ctl.state == "RUN" and ctl.free_slots() == ctl.capacity - 4
    ctl.advance(10_000)
    finished = [e.seq for e in ctl.events() if isinstance(e, Finished)]
    assert finished == [0, 1, 2, 3]
    assert ctl.idle() and ctl.state == "IDLE"
    assert max(abs(a - b) for a, b in zip(ctl.measured_mm, (10.0, 5.0, 19.5), strict=True)) < 0.005
