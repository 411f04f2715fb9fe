"""The corner geometry of cutter compensation (rs274ngc's convert_straight_comp2 and
convert_arc_comp2): where the held move must end so the tool, of radius ``r`` on
``side``, meets the next move. Pure functions of plane points (mm); a corner the tool
cannot reach raises ``LineError`` with rs274's message.
"""

from __future__ import annotations

import math

from app.i18n import N_, msg

from .errors import LineError

LEFT, RIGHT = 1, -1
HALF_PI, PI = math.pi / 2, math.pi
GOUGE_ARC = N_("Arc move in concave corner cannot be reached by the tool without gouging")
_GOUGE_LINE_ARC = N_("Arc to straight motion makes a corner the compensated tool can't fit in "
                     "without gouging")
_GOUGE_ARCS = N_("Arc to arc motion makes a corner the compensated tool can't fit in without gouging")


def inside(side: int, turn: int) -> bool:
    """True when the tool is inside an arc of ``turn`` (rs274ngc's TOOL_INSIDE_ARC)."""
    return side == LEFT and turn > 0 or side == RIGHT and turn < 0


def find_turn(x1, y1, cx, cy, turn, x2, y2) -> float:
    """rs274ngc's signed sweep (radians) from (x1, y1) to (x2, y2) around (cx, cy)."""
    if turn == 0:
        return 0.0
    alpha = math.atan2(y1 - cy, x1 - cx)
    beta = math.atan2(y2 - cy, x2 - cx)
    if turn > 0:
        if beta <= alpha:
            beta += 2 * PI
        return beta - alpha + (turn - 1) * 2 * PI
    if alpha <= beta:
        alpha += 2 * PI
    return beta - alpha + (turn + 1) * 2 * PI


def arc_to_line(side: int, r: float, prev: dict, px, py, opx, opy):
    """End of the held arc ``prev`` where a line from (opx, opy) to (px, py) starts."""
    pcx, pcy = prev["center"][:2]
    oldrad = math.hypot(pcy - prev["end"][1], pcx - prev["end"][0])
    base = math.atan2(py - opy, px - opx)
    theta = base + HALF_PI if prev["turn"] > 0 else base - HALF_PI
    phi = math.atan2(pcy - opy, pcx - opx)
    tool_inside = inside(side, prev["turn"])
    uncomp = oldrad + r if tool_inside else oldrad - r
    d = uncomp * math.cos(theta - phi)
    ratio = (d - r if tool_inside else d + r) / oldrad
    if not -1.0 <= ratio <= 1.0:
        raise LineError(0, msg(_GOUGE_LINE_ARC))
    sign = 1 if (prev["turn"] > 0) != tool_inside else -1
    angle = sign * math.acos(ratio) + theta + PI
    return pcx + oldrad * math.cos(angle), pcy + oldrad * math.sin(angle)


def line_to_arc(side: int, r: float, turn, arc_radius, beta, theta, ccx, ccy):
    """End of the held line where the compensated arc about (ccx, ccy) starts."""
    cy = arc_radius * math.sin(beta - HALF_PI)
    if inside(side, turn):
        dist = arc_radius - r
        ratio = (cy + r) / dist
        if not -1.0 <= ratio <= 1.0:
            raise LineError(0, msg(GOUGE_ARC))
        angle = theta + math.asin(ratio) if turn > 0 else theta - math.asin(ratio)
    else:
        dist = arc_radius + r
        ratio = (cy - r) / dist
        if not -1.0 <= ratio <= 1.0:
            raise LineError(0, msg(GOUGE_ARC))
        angle = theta + PI - math.asin(ratio) if turn > 0 else theta + PI + math.asin(ratio)
    return ccx + dist * math.cos(angle), ccy + dist * math.sin(angle)


def arc_to_arc(side: int, r: float, prev: dict, turn, arc_radius, ccx, ccy):
    """End of the held arc ``prev`` where the next compensated arc starts."""
    pcx, pcy = prev["center"][:2]
    oldrad = math.hypot(pcy - prev["end"][1], pcx - prev["end"][0])
    newrad = arc_radius - r if inside(side, turn) else arc_radius + r
    arc_cc = math.hypot(pcy - ccy, pcx - ccx)
    if oldrad == 0 or arc_cc == 0:
        raise LineError(0, msg("Arc to arc motion is invalid because the arcs have the same center"))
    a = (oldrad ** 2 + arc_cc ** 2 - newrad ** 2) / (2 * oldrad * arc_cc)
    if not -1.0 <= a <= 1.0:
        raise LineError(0, msg(_GOUGE_ARCS))
    pullback = math.acos(a)
    cc_dir = math.atan2(ccy - pcy, ccx - pcx)
    plus = (turn > 0) == inside(side, prev["turn"])
    direction = cc_dir + pullback if plus else cc_dir - pullback
    return pcx + oldrad * math.cos(direction), pcy + oldrad * math.sin(direction)
