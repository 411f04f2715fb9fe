"""The envelope check against a row-by-row reference: every move's box (an arc's from
all the quadrant points it sweeps, a line's from the axes it moves), whatever the
block size and however many values are shown."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.gcode import checks, load_text
from app.gcode.arcs import arc_box
from app.gcode.ops import ARC_CCW, ARC_CW, PLANE_AXES
from app.profile import MachineProfile


def _reference(ops, limits):
    """{(axis, sign): (rows, values)} worked out one row at a time."""
    starts = ops.starts()
    found: dict = {}
    for row in range(len(ops)):
        if ops.kind[row] > ARC_CCW:
            continue
        start, end = starts[row], ops.end[row]
        if ops.kind[row] in (ARC_CW, ARC_CCW):
            axes = np.array([PLANE_AXES[ops.plane[row]]])
            low, high = (b[0] for b in arc_box(start[None], end[None], ops.center[row][None], axes,
                                               ops.turn[row:row + 1]))
        else:
            low = np.where(end == start, np.inf, end)
            high = np.where(end == start, -np.inf, end)
        for axis in range(3):
            for sign, value, hit in (("+", high[axis], high[axis] > limits[axis, 1] + 1e-9),
                                     ("-", low[axis], low[axis] < limits[axis, 0] - 1e-9)):
                if hit:
                    rows, values = found.setdefault((axis, sign), ([], []))
                    rows.append(row)
                    values.append(value)
    return found


def _check(text: str, monkeypatch, block: int, shown: int, shift: float = 0.0) -> None:
    ops = load_text(text).ops
    limits = checks._limits(MachineProfile()) - shift
    monkeypatch.setattr(checks, "BLOCK", block)
    got = {("XYZ".index(name), sign): (rows, values, count)
           for name, sign, _, rows, values, count in checks._violations(ops, limits, shown)}
    want = _reference(ops, limits)
    assert sorted(got) == sorted(want)
    for key, (rows, values) in want.items():
        assert got[key][0].tolist() == rows[:shown], key
        assert got[key][1].tolist() == values[:shown], key
        assert got[key][2] == len(rows), key


PROGRAM = """G21 G90 G0 X10 Y10 Z5
G1 Z-1 F300
G2 X140 Y10 I65 J0
G3 X10 Y10 I-65 J0
G1 X160 Y20
G1 X160 Y30
G2 X160 Y30 I-20 J0
G0 X0 Y0
G18 G2 X20 Z-1 I10 K0
G19 G3 Y20 Z-1 J10 K0
G17 G2 X100 Y20 Z-3 I40 J0
G1 X-5
G3 X-5 Y0 I0 J-10
M2
"""


@pytest.mark.parametrize("block", [1, 2, 3, 1 << 16])
@pytest.mark.parametrize("shown", [1, 2, 200])
@pytest.mark.parametrize("shift", [0.0, 40.0, 120.0])
def test_envelope_matches_the_row_by_row_reference(monkeypatch, block, shown, shift):
    _check(PROGRAM, monkeypatch, block, shown, shift)


_coord = st.integers(-300, 300).map(lambda k: k / 2)
_PLANES = {"G17": (0, 1, "IJ"), "G18": (2, 0, "KI"), "G19": (1, 2, "JK")}


@st.composite
def arc_programs(draw):
    """Lines and arcs (every plane, some helical) whose ends lie on their circles."""
    rows, at = ["G21 G90 G0 X0 Y0 Z0", "G1 F200"], [0.0, 0.0, 0.0]
    for _ in range(draw(st.integers(1, 12))):
        if draw(st.booleans()):
            at = [draw(_coord) for _ in range(3)]
            rows.append("G1 X{} Y{} Z{}".format(*at))
            continue
        plane = draw(st.sampled_from(sorted(_PLANES)))
        first, second, letters = _PLANES[plane]
        offset = (draw(_coord) or 1.0, draw(_coord))
        turn = draw(st.integers(0, 7)) * np.pi / 4
        centre = (at[first] + offset[0], at[second] + offset[1])
        cos, sin = np.cos(turn), np.sin(turn)
        end = list(at)
        end[first] = round(centre[0] - offset[0] * cos + offset[1] * sin, 6)
        end[second] = round(centre[1] - offset[0] * sin - offset[1] * cos, 6)
        end[3 - first - second] = draw(_coord) if draw(st.booleans()) else at[3 - first - second]
        g = draw(st.sampled_from(["G2", "G3"]))
        words = " ".join(f"{c}{v}" for c, v in zip("XYZ", end, strict=True))
        rows.append(f"{plane} {g} {words} {letters[0]}{offset[0]} {letters[1]}{offset[1]}")
        at = end
    return "\n".join(rows) + "\nM2\n"


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(arc_programs(), st.sampled_from([1, 3, 1 << 16]), st.sampled_from([1, 200]))
def test_envelope_matches_the_reference_on_any_arcs(monkeypatch, text, block, shown):
    _check(text, monkeypatch, block, shown)
