"""Cutter radius compensation G41/G42/G40 (and G41.1/G42.1 D<diameter>) in the XY
plane, as LinuxCNC's rs274ngc computes it (interp_convert.cc, interp_queue.cc).

The compensated path is what the rows hold. Like rs274ngc, the last compensated
move is held back (``Comp.queue``) until the next XY move says where it must end:
at a concave corner its end moves back to where the tool fits (a gouge is refused),
at a convex corner an arc around the programmed corner is inserted. Z-only moves and
events (spindle, dwell, pause) wait in the queue behind it. The queue is written at
the next corner, at G40, at a program stop and at the end of the program
(``flush``). The first move after G41/G42 is the entry move (its end offset
perpendicular to it); the first move after G40 is the straight exit move.
Geometry is in the frame's millimetres: offsets cannot change while compensation is
on, so the frame is the program's coordinates shifted.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from app.i18n import N_, msg

from .comp_corners import GOUGE_ARC, HALF_PI, LEFT, PI, RIGHT, arc_to_arc, arc_to_line, find_turn, line_to_arc
from .comp_corners import inside as _inside
from .errors import LineError
from .motion import arc_geometry
from .ops import ARC_CCW, ARC_CW, FEED, RAPID, XY

SMALL = 0.05  # TOLERANCE_CONCAVE_CORNER, radians
EQUAL = 1e-6
_TOO_SMALL = N_("Tool radius not less than arc radius with comp")
_GOUGE_STRAIGHT = {
    "rapid": N_("Straight traverse in concave corner cannot be reached by the tool without gouging"),
    "feed": N_("Straight feed in concave corner cannot be reached by the tool without gouging"),
}


@dataclass
class Comp:
    """Compensation in force: side, radius (mm) and the held moves."""

    side: int
    radius: float
    first: bool = True
    current: list[float] = field(default_factory=list)  # the tool's point (frame)
    programmed: list[float] = field(default_factory=list)  # the programmed point
    queue: list[dict] = field(default_factory=list)
    endpoint: tuple[float, float] | None = None  # start of the held move (valid) or None

    def copy(self) -> Comp:
        queue = [dict(e, end=list(e["end"])) if "end" in e else dict(e) for e in self.queue]
        return Comp(self.side, self.radius, self.first, list(self.current), list(self.programmed),
                    queue, self.endpoint)

    # --- the queue ------------------------------------------------------------------

    def _enqueue_line(self, kind, line, direction, end, feed) -> None:
        self.queue.append({"kind": kind, "line": line, "dir": direction, "end": list(end), "feed": feed})

    def _enqueue_arc(self, line, sweep, end, center, turn, feed) -> None:
        self.queue.append({"kind": "arc", "line": line, "sweep": sweep, "end": list(end),
                           "center": list(center), "turn": turn, "feed": feed})

    def dequeue(self, ops) -> None:
        """Write the held rows (moves, then the events behind them) to ``ops``."""
        add = getattr(ops, "add_direct", ops.add)
        pos = self.current
        for e in self.queue:
            if e["kind"] == "event":
                args, kw = e["args"], e["kw"]
                add(args[0], args[1], list(pos), *args[3:], **kw)
                continue
            pos = e["end"]
            if e["kind"] == "arc":
                kind = ARC_CCW if e["turn"] > 0 else ARC_CW
                add(e["line"], kind, pos, e["center"], XY, e["turn"], e["feed"])
            else:
                add(e["line"], RAPID if e["kind"] == "rapid" else FEED, pos, value=e["feed"])
        self.queue = []
        self.endpoint = None

    def move_endpoint_and_flush(self, ops, x: float, y: float, inch: bool) -> None:
        """The held moves end at (x, y) instead; refuse if that reverses one (a gouge)."""
        if not self.queue:
            return
        for e in self.queue:
            if e["kind"] == "arc":
                sweep = e["sweep"]
                e["end"][0], e["end"][1] = x, y
                if self.endpoint is not None and sweep != 0.0:
                    new = find_turn(*self.endpoint, *e["center"][:2], e["turn"], x, y)
                    if abs(new) > abs(sweep) + (0.001 if inch else 0.0254):
                        raise LineError(0, msg(GOUGE_ARC))
            elif e["kind"] in ("rapid", "feed"):
                if self.endpoint is not None:
                    dot = e["dir"][0] * (x - self.endpoint[0]) + e["dir"][1] * (y - self.endpoint[1])
                    if dot < 0:
                        gouge = _GOUGE_STRAIGHT[e["kind"]]
                        raise LineError(0, msg(gouge))
                e["end"][0], e["end"][1] = x, y
        self.dequeue(ops)
        self.endpoint = (x, y)

    # --- moves ----------------------------------------------------------------------

    def move(self, state, motion: int, params, target, line_no: int, ops) -> None:
        """One G0/G1/G2/G3 with compensation on (the held queue is updated)."""
        if not self.current:
            self.current, self.programmed = list(state.pos), list(state.pos)
        if motion in (2, 3):
            center, turn = arc_geometry(state, params, state.pos, target, motion == 2)
            if self.first:
                self._arc_entry(state, params, motion, center, turn, target, line_no)
            else:
                self._arc(state, motion, center, turn, target, line_no, ops)
        elif self.first:
            self._line_entry(motion, target, line_no, state.feed)
        else:
            self._line(state, motion, target, line_no, ops)
        self.programmed = list(target)

    def _line_entry(self, motion, target, line_no, feed) -> None:
        cx, cy = self.current[:2]
        px, py = target[:2]
        if math.hypot(px - cx, py - cy) <= self.radius:
            raise LineError(0, msg("Length of cutter compensation entry move is not greater "
                                   "than the tool radius"))
        alpha = math.atan2(py - cy, px - cx) + (HALF_PI if self.side == LEFT else -HALF_PI)
        end = (px + self.radius * math.cos(alpha), py + self.radius * math.sin(alpha), target[2])
        self.endpoint = (cx, cy)
        self._enqueue_line("rapid" if motion == 0 else "feed", line_no,
                           (math.cos(alpha), math.sin(alpha)), end, feed)
        self.first = False
        self.current = list(end)

    def _line(self, state, motion, target, line_no, ops) -> None:
        cx, cy, cz = self.current
        opx, opy = self.programmed[:2]
        px, py, pz = target
        kind = "rapid" if motion == 0 else "feed"
        if px == opx and py == opy:
            self._enqueue_line(kind, line_no, (0.0, 0.0), (cx, cy, pz), state.feed)
            self.current = [cx, cy, pz]
            return
        side, r = self.side, self.radius
        theta = math.atan2(cy - opy, cx - opx)
        alpha = math.atan2(py - opy, px - opx)
        if side == LEFT:
            if theta < alpha:
                theta += 2 * PI
            beta, gamma = theta - alpha - HALF_PI, HALF_PI
        else:
            if alpha < theta:
                alpha += 2 * PI
            beta, gamma = alpha - theta - HALF_PI, -HALF_PI
        end = (px + r * math.cos(alpha + gamma), py + r * math.sin(alpha + gamma), pz)
        mid = (opx + r * math.cos(alpha + gamma), opy + r * math.sin(alpha + gamma))
        front = self.queue[0] if self.queue else None
        concave = beta < -SMALL or beta > PI + SMALL or (
            beta > PI - SMALL and front is not None and front["kind"] == "arc"
            and (side == RIGHT and front["turn"] > 0 or side == LEFT and front["turn"] < 0))
        if not concave and beta > SMALL:  # convex: around the corner
            self.move_endpoint_and_flush(ops, cx, cy, state.inch)
            if motion == 1:
                turn = -1 if side == LEFT else 1
                self._enqueue_arc(line_no, 0.0, (*mid, cz), (opx, opy, cz), turn, state.feed)
            else:
                self._enqueue_line("rapid", line_no, (0.0, 0.0), (*mid, cz), state.feed)
            self.dequeue(ops)
            self.endpoint = mid
        elif concave:
            if front is None or front["kind"] != "arc":
                halfcorner = (beta + PI) / 2.0
                if halfcorner == 0.0:
                    raise LineError(0, msg("Zero degree inside corner is invalid for cutter compensation"))
                retreat = r / math.tan(halfcorner)
                mx = cx + retreat * math.cos(theta + gamma)
                my = cy + retreat * math.sin(theta + gamma)
            else:
                mx, my = arc_to_line(side, r, front, px, py, opx, opy)
            self.move_endpoint_and_flush(ops, mx, my, state.inch)
        else:
            self.dequeue(ops)
            self.endpoint = (cx, cy)
        self._enqueue_line(kind, line_no, (px - opx, py - opy), end, state.feed)
        self.current = list(end)

    def _arc_entry(self, state, params, motion, center, turn, target, line_no) -> None:
        cx, cy = self.current[:2]
        ex, ey, ez = target
        r = self.radius
        if math.hypot(ex - cx, ey - cy) <= r:
            raise LineError(0, msg("Radius of cutter compensation entry arc is not greater "
                                   "than the tool radius"))
        arc_radius = math.hypot(center[0] - cx, center[1] - cy)
        if arc_radius <= r and (self.side == LEFT and motion == 3 or self.side == RIGHT and motion == 2):
            raise LineError(0, msg(_TOO_SMALL))
        if _inside(self.side, turn):
            gamma = math.atan2(center[1] - ey, center[0] - ex)
        else:
            gamma = math.atan2(ey - center[1], ex - center[0])
        ex, ey = ex + r * math.cos(gamma), ey + r * math.sin(gamma)
        b_len = math.hypot(cy - ey, cx - ex) / 2.0
        ab = math.atan2(center[1] - ey, center[0] - ex)
        a_ang = math.atan2(cy - ey, cx - ex) - ab
        if abs(math.cos(a_ang)) < EQUAL:
            raise LineError(0, msg(_TOO_SMALL))
        c_len = b_len / math.cos(a_ang)
        ncx, ncy = ex + c_len * math.cos(ab), ey + c_len * math.sin(ab)
        sweep = find_turn(cx, cy, ncx, ncy, turn, ex, ey)
        self._enqueue_arc(line_no, sweep, (ex, ey, ez), (ncx, ncy, self.current[2]), turn, state.feed)
        self.first = False
        self.current = [ex, ey, ez]

    def _arc(self, state, motion, center, turn, target, line_no, ops) -> None:
        side, r = self.side, self.radius
        opx, opy = self.programmed[:2]
        cx, cy, cz = self.current
        ex, ey, ez = target
        ccx, ccy = center[:2]
        arc_radius = math.hypot(ccx - ex, ccy - ey)
        theta = math.atan2(cy - opy, cx - opx) + (-HALF_PI if side == LEFT else HALF_PI)
        delta = math.atan2(ccy - opy, ccx - opx)
        alpha = delta - HALF_PI if motion == 3 else delta + HALF_PI
        beta = theta - alpha if side == LEFT else alpha - theta
        if beta > 1.5 * PI:
            beta -= 2 * PI
        elif beta < -HALF_PI:
            beta += 2 * PI
        if side == LEFT and motion == 3 or side == RIGHT and motion == 2:
            gamma = math.atan2(ccy - ey, ccx - ex)
            if arc_radius <= r:
                raise LineError(0, msg(_TOO_SMALL))
        else:
            gamma = math.atan2(ey - ccy, ex - ccx)
            delta += PI
        new_end = (ex + r * math.cos(gamma), ey + r * math.sin(gamma), ez)
        sweep = find_turn(opx, opy, ccx, ccy, turn, ex, ey)
        arc_center = (ccx, ccy, cz)
        if beta < -SMALL or beta > PI + SMALL or (abs(beta - PI) < SMALL and not _inside(side, turn)):
            front = self.queue[0] if self.queue else None
            if front is None or front["kind"] != "arc":
                mid = line_to_arc(side, r, turn, arc_radius, beta, theta, ccx, ccy)
            else:
                mid = arc_to_arc(side, r, front, turn, arc_radius, ccx, ccy)
            self.move_endpoint_and_flush(ops, *mid, state.inch)
        elif beta > SMALL:  # convex: an arc around the corner first
            mid = (opx + r * math.cos(delta), opy + r * math.sin(delta))
            self.dequeue(ops)
            self._enqueue_arc(line_no, 0.0, (*mid, cz), (opx, opy, cz), -1 if side == LEFT else 1, state.feed)
            self.dequeue(ops)
            self.endpoint = mid
        else:
            self.dequeue(ops)
            self.endpoint = (cx, cy)
        self._enqueue_arc(line_no, sweep, new_end, arc_center, turn, state.feed)
        self.current = list(new_end)


def _radius(state, code: float, params, column: int) -> float:
    name = f"G{code:g}"
    if code in (41.1, 42.1):
        if "D" not in params:
            raise LineError(column, msg("{code} with no D word", code=name))
        return params["D"].value * state.scale / 2.0
    if "D" not in params:
        number = state.tool
    else:
        d = params["D"]
        if d.value != round(d.value):
            raise LineError(d.column, msg("{code} requires D word to be a whole number", code=name))
        if d.value < 0:
            raise LineError(d.column, msg("Negative D word tool radius index used"))
        number = int(round(d.value)) or state.tool  # D0: the tool in the spindle, as rs274ngc
    if number == 0:
        return 0.0
    tool = state.tools.get(number)
    if tool is None and state.fanuc and "D" in params:
        return 0.0  # a Fanuc offset register never written reads 0 (G10 L12 writes it)
    if tool is None:
        raise LineError(params["D"].column if "D" in params else column,
                        msg("Requested tool {number} not found in the tool table", number=number))
    return tool.diameter / 2.0


def select(state, code: float, params, column: int, ops) -> None:
    """G40 (off: the held moves are written), G41/G42 (D = tool number, default the
    tool in the spindle), G41.1/G42.1 (D = diameter)."""
    if code == 40:
        comp = state.comp
        if comp is not None and comp.radius > 0 and not comp.first:
            comp.move_endpoint_and_flush(ops, *comp.current[:2], state.inch)
            state.arc_not_allowed = True
        state.comp = None
        return
    if state.plane != 0:
        raise LineError(column, msg("Cutter radius compensation allowed only in XY plane on this machine"))
    if state.comp is not None:
        raise LineError(column, msg("Cannot turn cutter radius comp on when on"))
    radius = _radius(state, code, params, column)
    side = LEFT if code in (41, 41.1) else RIGHT
    if radius < 0:
        radius, side = -radius, -side
    state.comp = Comp(side, radius, current=list(state.pos), programmed=list(state.pos))


def flush(state, ops) -> None:
    """Write the held moves as they are (a program stop or the end of the program)."""
    if state.comp is not None and state.comp.queue:
        state.comp.dequeue(ops)
