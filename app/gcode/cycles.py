"""Canned cycles G73 G81 G82 G83 G85 G89 in the XY, XZ and YZ planes (G17, G18, G19),
expanded to rapid, feed and dwell rows exactly as rs274ngc's ``convert_cycle_xy``,
``_zx`` and ``_yz`` move (LinuxCNC 2.9): in G18 the holes are drilled along Y, in G19
along X, and the depth word is that axis's (below: "Z" is the drilling axis).

R (retract plane), Z (bottom), P (dwell), Q (peck) are sticky while the same cycle
stays in force; L repeats (in G91 each repeat moves by X Y again). The initial level
is the Z where a run of cycle blocks started (kept until another motion mode); G98
retracts to it when it is above R, G99 to R. In G91, R is an increment from the
initial level and Z from R. A cycle below R first rises to R. Values are computed in
program coordinates (program units) and leave here in the frame's millimetres.
"""

from __future__ import annotations

import math

from app.i18n import msg

from .errors import LineError
from .limits import dwell_problem
from .ops import DWELL, FEED, RAPID, OpBuffer

PECK_CLEARANCE_INCH = 0.010  # G73 retract / G83 re-entry clearance of rs274 2.9 (no ini)


def _sticky(state, params, code: int, letter: str, name: str, message: str):
    if letter in params:
        return params[letter].value
    if state.motion != code:
        raise LineError(0, message)
    return getattr(state.cycle, name)


def _polar_words(params) -> tuple[float, float]:
    """(radius, angle in radians) increments of @ and ^ (used in G91)."""
    return (params["@"].value if "@" in params else 0.0,
            math.radians(params["^"].value) if "^" in params else 0.0)


def _polar_step(x: float, y: float, d_radius: float, d_theta: float) -> tuple[float, float]:
    """One G91 repeat's polar increments about the program origin (rs274ngc's CYCLE_MACRO)."""
    for grow, turn in ((d_radius, 0.0), (0.0, d_theta)):
        if grow or turn:
            if x == 0 and y == 0:
                raise LineError(0, msg("Incremental motion with polar coordinates is indeterminate "
                                       "when at the origin"))
            theta, radius = math.atan2(y, x) + turn, math.hypot(y, x) + grow
            x, y = radius * math.cos(theta), radius * math.sin(theta)
    return x, y


# Per plane (G17, G18, G19): the two axes of the hole's position and the drilling axis,
# as indices (X 0, Y 1, Z 2), as rs274ngc's convert_cycle_xy / _zx / _yz use them.
PLANE_AXES = ((0, 1, 2), (0, 2, 1), (1, 2, 0))
PLANE_NAMES = ("XY", "XZ", "YZ")


class _Emitter:
    """Rows of one cycle block, from program coordinates (program units): ``x``, ``y``
    are the hole's position in the plane, ``z`` the drilling axis (``PLANE_AXES``)."""

    def __init__(self, state, line_no: int, ops: OpBuffer):
        self.state, self.line_no, self.ops = state, line_no, ops
        self.k = state.scale
        self.offsets = state.offsets
        self.axes = PLANE_AXES[state.plane]

    def point(self, x, y, z):
        k, (iu, iv, iw) = self.k, self.axes
        p = [0.0, 0.0, 0.0]
        p[iu], p[iv], p[iw] = x * k, y * k, z * k
        return self.offsets.to_frame(p)

    def rapid(self, x, y, z):
        self.ops.add(self.line_no, RAPID, self.point(x, y, z), value=self.state.feed)

    def feed(self, x, y, z):
        self.ops.add(self.line_no, FEED, self.point(x, y, z), value=self.state.feed)

    def dwell(self, seconds, x, y, z):
        self.ops.add(self.line_no, DWELL, self.point(x, y, z), value=seconds)


def _drill(e: _Emitter, code, x, y, r, clear, bottom, p, q) -> None:
    """One hole at (x, y): the cycle-specific moves after reaching R."""
    if code in (73, 83):
        if q <= 0:
            raise LineError(0, msg("negative or zero Q value used"))
        clearance = PECK_CLEARANCE_INCH * 25.4 / e.k
        depth = r - q
        while depth > bottom:
            e.feed(x, y, depth)
            if code == 83:
                e.rapid(x, y, r)
            e.rapid(x, y, depth + clearance)
            depth -= q
    e.feed(x, y, bottom)
    if code in (82, 89):
        e.dwell(p, x, y, bottom)
    if code in (85, 89):
        e.feed(x, y, r if code == 85 else clear)
        if code == 85:
            e.rapid(x, y, clear)
    else:
        e.rapid(x, y, clear)


def _spend(state, code: int, line_no: int, repeats: int, rr: float, bottom: float, q: float) -> None:
    """Count the moves of the block before making any (``limits.Budget``): a hole is at
    most 5 moves and each peck 3 (G83) or 2 (G73)."""
    pecks = 0
    if code in (73, 83) and q > 0:
        pecks = max(0, math.ceil(min((rr - bottom) / q, 1e15)) - 1)
    moves = repeats * (5 + pecks * (3 if code == 83 else 2))
    what = msg("{pecks:,} pecks", pecks=repeats * pecks) if pecks else (
        msg("{repeats:,} repeats", repeats=repeats) if repeats > 1 else "")
    try:
        state.budget.spend(moves, f"G{code}", line_no, what)
    except ValueError as exc:
        raise LineError(0, exc.args[0]) from None


def run_cycle(state, code: int, params, line_no: int, ops: OpBuffer) -> None:
    """Expand one cycle block (``state.motion`` is still the mode before this line), in
    the XY, XZ or YZ plane: the same moves with the axes of ``PLANE_AXES``."""
    iu, iv, iw = PLANE_AXES[state.plane]
    u, v, w = ("XYZ"[iu], "XYZ"[iv], "XYZ"[iw])
    plane = PLANE_NAMES[state.plane]
    if state.plane != 0 and ("@" in params or "^" in params):
        raise LineError(0, msg("polar coordinates in a canned cycle need the XY plane (G17)"))
    if state.feed == 0:
        raise LineError(0, msg("Cannot feed with zero feed rate"))
    if state.comp is not None:
        raise LineError(0, msg("Cannot use canned cycles with cutter compensation on"))
    c = state.cycle
    r = _sticky(state, params, code, "R", "r", msg("R clearance plane unspecified in cycle"))
    z = _sticky(state, params, code, w, "z", msg("{axis} value unspecified in {plane} plane canned cycle",
                                                 axis=w, plane=plane))
    p = q = 0.0
    if code in (82, 89):
        missing = msg("Dwell time P word missing with {code}", code=f"G{code}")
        p = _sticky(state, params, code, "P", "p", missing)
        problem = dwell_problem(p)
        if problem:
            raise LineError(params["P"].column if "P" in params else 0, problem)
    if code in (73, 83):
        q = _sticky(state, params, code, "Q", "q", msg("Q word missing with {code}", code=f"G{code}"))
    repeats = 1
    if "L" in params:
        value = params["L"].value
        if value != int(value) or value < 0:
            raise LineError(params["L"].column, msg("{word} is not a number of repeats", word=f"L{value:g}"))
        if value == 0:
            raise LineError(params["L"].column, msg("Cannot do zero repeats of cycle"))
        repeats = int(value)
    k = state.scale
    prog = [value / k for value in state.program_pos()]
    current = prog[iw]
    initial = current if c.initial is None else (c.initial - state.offsets.total()[iw]) / k
    kept = initial
    dx = dy = 0.0
    polar = _polar_words(params)
    if state.absolute:
        rr, bottom = r, z
        x = params[u].value if u in params else prog[iu]
        y = params[v].value if v in params else prog[iv]
        if "@" in params or "^" in params:
            radius = params["@"].value if "@" in params else math.hypot(prog[1], prog[0])
            theta = math.radians(params["^"].value) if "^" in params else math.atan2(prog[1], prog[0])
            x, y = radius * math.cos(theta), radius * math.sin(theta)
        polar = (0.0, 0.0)
    else:
        dx = params[u].value if u in params else 0.0
        dy = params[v].value if v in params else 0.0
        rr = r + initial
        bottom = rr + z
        x, y = prog[iu], prog[iv]
    if rr < bottom:
        column = params["R"].column if "R" in params else 0
        raise LineError(column, msg("R less than {axis} in cycle in {plane} plane", axis=w, plane=plane))
    _spend(state, code, line_no, repeats, rr, bottom, q)
    e = _Emitter(state, line_no, ops)
    if initial < rr:
        e.rapid(prog[iu], prog[iv], rr)
        initial = current = rr
    clear = rr if state.retract_r else initial
    for n in range(repeats):
        x, y = _polar_step(x + dx, y + dy, *polar)
        if n == 0 and current > rr:
            e.rapid(x, y, current)
            e.rapid(x, y, rr)
        else:
            e.rapid(x, y, clear)
            if clear > rr:
                e.rapid(x, y, rr)
        _drill(e, code, x, y, rr, clear, bottom, p, q)
    c.r, c.z, c.p, c.q = r, z, p, q
    c.initial = kept * k + state.offsets.total()[iw]
    state.pos = e.point(x, y, clear)
