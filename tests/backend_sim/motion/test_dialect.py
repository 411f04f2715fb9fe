"""The CNC MCU's own dialect parser: golden cases, refusals, arc extents, soft limits."""

import pytest

from app.profile import MachineProfile
from backend_sim.motion.dialect import DialectError, DialectParser, Move, soft_limit_violation

GOLDEN = [
    ("G00 X10 Y20", dict(kind="rapid", target=(10.0, 20.0, 30.0), feed=0.0)),
    ("G0 Z5", dict(kind="rapid", target=(0.0, 0.0, 25.0))),
    ("G01 X1.5 Y-0.5 Z-1 F300", dict(kind="line", target=(1.5, -0.5, 19.0), feed=300.0)),
    ("G1X.5F100", dict(kind="line", target=(0.5, 0.0, 30.0), feed=100.0)),
    ("G02 X10 Y0 I5 J0 F200", dict(kind="arc", target=(10.0, 0.0, 30.0), center=(5.0, 0.0), clockwise=True)),
    ("G03 X0 Y0 I5 J0 Z-2 F200",
     dict(kind="arc", target=(0.0, 0.0, 18.0), center=(5.0, 0.0), clockwise=False)),
    ("G04 P0.25", dict(kind="dwell", seconds=0.25, target=(0.0, 0.0, 30.0))),
    ("M03 S12000", dict(kind="spindle", rpm=12000.0)),
    ("M3 S500", dict(kind="spindle", rpm=500.0)),
    ("M05", dict(kind="spindle", rpm=0.0)),
    ("M02", dict(kind="end")),
    ("M30", dict(kind="end")),
]


@pytest.mark.parametrize(("line", "expect"), GOLDEN)
def test_golden(line, expect):
    move = DialectParser().parse(7, line)
    assert move.seq == 7 and move.source == line
    for key, value in expect.items():
        assert getattr(move, key) == pytest.approx(value), key


ERRORS = [
    ("G01 Q5 F100", "BAD_LINE", "unknown word Q"),
    ("G17", "BAD_LINE", "unsupported G17"),
    ("X5", "BAD_LINE", "no G or M word"),
    ("", "BAD_LINE", "empty line"),
    ("g01 x1", "BAD_LINE", "cannot read"),
    ("G01 X1 X2 F1", "BAD_LINE", "word X twice"),
    ("G01 G00 X1", "BAD_LINE", "more than one"),
    ("G01 X1", "NO_FEED", "without a feed"),
    ("G01 X1 F0", "BAD_VALUE", "feed"),
    ("G02 X1 Y1 I0 J0 F100", "BAD_ARC", "zero radius"),
    ("G02 X30 Y0 I5 J0 F100", "BAD_ARC", "differs"),
    ("G02 X10 Y0 F100", "BAD_LINE", "missing I"),
    ("G04", "BAD_LINE", "needs P"),
    ("G04 P-1", "BAD_VALUE", "P-1"),
    ("M03 S-5", "BAD_VALUE", "S-5"),
    ("M05 S100", "BAD_LINE", "unknown word S"),
]


@pytest.mark.parametrize(("line", "code", "text"), ERRORS)
def test_errors(line, code, text):
    parser = DialectParser()
    with pytest.raises(DialectError) as info:
        parser.parse(0, line)
    assert info.value.code == code
    assert text in info.value.text
    assert parser.position == (0.0, 0.0, 30.0)  # a refused line changes nothing


def test_modal_feed_and_omitted_axes():
    p = DialectParser(offset=(1.0, 2.0, 3.0), position=(0.0, 0.0, 0.0))
    p.parse(0, "G01 X10 F250")
    move = p.parse(1, "G01 Y5")
    assert move.feed == 250.0
    assert move.target == (11.0, 7.0, 0.0)
    assert p.position == (11.0, 7.0, 0.0)


def test_spindle_speed_is_modal():
    p = DialectParser()
    with pytest.raises(DialectError, match="needs S"):
        p.parse(0, "M03")
    assert p.parse(1, "M03 S1200").rpm == 1200.0
    assert p.parse(2, "M05").rpm == 0.0
    assert p.parse(3, "M03").rpm == 1200.0


def test_arc_extent_includes_bulge():
    start = (0.0, 0.0, 0.0)
    move = Move(0, "arc", (10.0, 0.0, 0.0), 100.0, center=(5.0, 0.0), clockwise=True)
    lo, hi = move.extent(start)
    assert hi[1] == pytest.approx(5.0) and lo[1] == pytest.approx(0.0)
    ccw = Move(0, "arc", (10.0, 0.0, 0.0), 100.0, center=(5.0, 0.0), clockwise=False)
    assert ccw.extent(start)[0][1] == pytest.approx(-5.0)


@pytest.mark.parametrize(("line", "expect"), [
    ("G01 X151.2 F100", "X+ 151.200 > 150"),
    ("G01 X-1 F100", "X- -1.000 < 0"),
    ("G01 Y150.5 F100", "Y+ 150.500 > 150"),
    ("G01 Z11 F100", "Z+ 31.000 > 30"),
    ("G01 Z-20.5 F100", "Z- -0.500 < 0"),
    ("G03 X20 Y1 I5 J0 F100", "Y- -4.000 < 0"),
    ("G02 X20 Y1 I5 J0 F100", None),
    ("G01 X150 Y150 Z-20 F100", None),
    ("G04 P1", None),
])
def test_soft_limits_name_axis_and_direction(line, expect):
    parser = DialectParser(position=(10.0, 1.0, 20.0))
    start = parser.position
    move = parser.parse(0, line)
    assert soft_limit_violation(start, move, MachineProfile().travel) == expect
