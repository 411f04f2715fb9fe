"""The paper's profile program (section 4.3, figure 6): the control computes the rings.

The contour is written once, from point 3 (the middle of its first segment) round to
point 3 again, in the direction that keeps the tool on the cutting side (G41 for climb
milling, G42 for conventional). Each ring sets the radius register to its offset
(``G10 L12 P<register> R<H>``), comes from point 1 to point 2 with compensation on,
arcs tangentially onto point 3 (centre point 4), laps the contour, arcs off to point 5
and leaves with G40 back to point 1 (equations 2-6, on the tool's side of the first
segment). The lead arc of the programmed path has radius ``R + H`` so the tool centre
arcs with the finishing clearance ``R`` (rs274 refuses a lead arc not larger than the
offset). Point 1 is the paper's (``2(R + H)`` out on the normal at point 3) or, where
rs274 cannot join that entry line to a small lead arc, straight out from point 2 (the
entry then meets the arc tangentially). A phase is a list of depth levels and the ring
offsets cut on every level; the tool goes down at the descent point beyond point 1 of
the first ring.

``reference(form)`` is that program unrolled (numbers only); ``form_moves(form)``
reads it back through the project's loader, so the moves are exactly what the
interpreter's cutter compensation makes of it (arcs about convex corners,
intersections at concave ones).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from app.i18n import msg

from .contour import Segment
from .cutting import Cutting
from .entry import GAP
from .errors import FeatureError
from .moves import ARC, FEED, RAPID, Move

BEYOND = 0.1  # mm from point 1 of the first ring to the descent point


def fmt(value: float) -> str:
    """A number with at most 6 decimals and no trailing zeros (``-0`` is ``0``)."""
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


@dataclass(frozen=True)
class Phase:
    """Depth ``levels`` (top down), each cut with rings at ``offsets`` (outside in)."""

    levels: tuple[float, ...]
    offsets: tuple[float, ...]
    note: str  # "layer" (roughing) or "<name> finish wall layer"

    @property
    def far(self) -> float:
        """The first ring's offset H_1 (the descent point lies beyond that ring's point 1)."""
        return self.offsets[0]


@dataclass(frozen=True, eq=False)
class PaperForm:
    """One profile feature as the paper programs it (see the module docstring)."""

    name: str  # the contour's file
    path: tuple[Segment, ...]  # the contour from point 3 round to point 3
    t: tuple[float, float]  # direction of the contour at point 3
    n: tuple[float, float]  # unit normal towards the tool's side
    left: bool  # G41 (else G42)
    register: int
    lead: float  # R: the tool centre's lead arc radius
    open_at: float  # the descent point is at least this far from point 3
    shift: float  # point 1 is point 3 + (shift·t + 2n)·(R + H): 0 the paper's, -1 over point 2
    phases: tuple[Phase, ...]
    cut: Cutting

    @property
    def p3(self) -> tuple[float, float]:
        return self.path[0].start

    def at(self, a: float, b: float) -> tuple[float, float]:
        """Point 3 + a·t + b·n."""
        (x, y), (tx, ty), (nx, ny) = self.p3, self.t, self.n
        return x + a * tx + b * nx, y + a * ty + b * ny

    def descent(self, phase: Phase) -> tuple[float, float]:
        """Where the tool goes down for ``phase``: ``BEYOND`` past point 1 of its first
        ring (a ring starts with a move to its point 1), and beyond ``open_at``."""
        return self.at(0.0, max(2 * (self.lead + phase.far) + BEYOND, self.open_at))

    def lead_arc(self) -> str:
        return "G03" if self.left else "G02"

    def comp(self) -> str:
        return "G41" if self.left else "G42"


def contour_lines(form: PaperForm) -> list[str]:
    """The contour from point 3 round to point 3 (numbers, no feed)."""
    out = []
    for seg in form.path:
        x, y = seg.end
        if seg.center is None:
            out.append(f"G01 X{fmt(x)} Y{fmt(y)}")
        else:
            i, j = seg.center[0] - seg.start[0], seg.center[1] - seg.start[1]
            out.append(f"{'G02' if seg.cw else 'G03'} X{fmt(x)} Y{fmt(y)} I{fmt(i)} J{fmt(j)}")
    return out


def _xy(p) -> str:
    return f"X{fmt(p[0])} Y{fmt(p[1])}"


def _ring(form: PaperForm, h: float) -> list[str]:
    rho, cut = form.lead + h, form.cut
    tx, ty = form.t
    nx, ny = form.n
    return [f"G10 L12 P{form.register} R{fmt(h)}",
            f"G01 {_xy(form.at(form.shift * rho, 2 * rho))} F{fmt(cut.feed)}",
            f"{form.comp()} D{form.register}",
            f"G01 {_xy(form.at(-rho, rho))}",
            f"{form.lead_arc()} {_xy(form.p3)} I{fmt(rho * tx)} J{fmt(rho * ty)}",
            *contour_lines(form),
            f"{form.lead_arc()} {_xy(form.at(rho, rho))} I{fmt(rho * nx)} J{fmt(rho * ny)}",
            "G40",
            f"G01 {_xy(form.at(form.shift * rho, 2 * rho))}"]


def phase_start(form: PaperForm, phase: Phase, at_safe: bool) -> list[str]:
    """From anywhere (at the safe height when ``at_safe``) to just above the first level
    (or the stock top, when that is higher) at the descent point."""
    cut = form.cut
    out = [] if at_safe else [f"G00 Z{fmt(cut.safe_z)}"]
    out.append(f"G00 {_xy(form.descent(phase))} Z{fmt(cut.safe_z)}")
    down = min(cut.safe_z, max(phase.levels[0], cut.top) + GAP)  # no rapid below the top
    if down < cut.safe_z - 1e-9:
        out.append(f"G00 Z{fmt(down)}")
    return out


def reference(form: PaperForm, notes: list[str]) -> str:
    """The program unrolled, from the safe height; ``notes`` gets each line's note."""
    cut = form.cut
    lines: list[str] = []

    def add(new: list[str], note: str) -> None:
        lines.extend(new)
        notes.extend([note] * len(new))

    add(["G21 G90 G17"], "")
    for p, phase in enumerate(form.phases):
        add(phase_start(form, phase, p == 0), "")
        count = len(phase.levels)
        for k, z in enumerate(phase.levels):
            note = f"{phase.note} {k + 1}/{count} z {z:.3f}"
            add([f"G01 Z{fmt(z)} F{fmt(cut.plunge_feed)}"], note)
            for h in phase.offsets:
                add(_ring(form, h), note)
            add([f"G01 {_xy(form.descent(phase))} F{fmt(cut.feed)}"], note)
    add([f"G00 Z{fmt(cut.safe_z)}", "M30"], "")
    return "\n".join(lines) + "\n"


def _move(row: dict, note: str, form: PaperForm) -> Move:
    kind = {"rapid": RAPID, "feed": FEED, "arc": ARC}[row["kind"]]
    end = tuple(float(v) for v in row["end"][:3])
    if kind == ARC:
        return Move(ARC, end, row["feed"], tuple(float(v) for v in row["center"][:2]), row["turn"] < 0,
                    note=note, block=form)
    return Move(kind, end, row.get("feed", 0.0) if kind == FEED else 0.0, note=note, block=form)


def form_moves(form: PaperForm) -> list[Move]:
    """The moves of ``form`` as the loader's compensation computes them, from the rapid
    over the first descent point on (``FeatureError`` with the loader's message)."""
    from app.gcode import load_text
    from app.gcode.tools import Tool

    notes: list[str] = []
    text = reference(form, notes)
    program = load_text(text, "profile", tools={form.register: Tool(form.register, form.cut.tool_diameter)})
    if program.errors:
        raise _refused(form, text.splitlines(), program.errors[0])
    rows = [r for r in program.moves if r["kind"] in ("rapid", "feed", "arc")]
    return [_move(r, notes[r["line"] - 1], form) for r in rows]


def _refused(form: PaperForm, lines: list[str], error) -> FeatureError:
    """The loader's refusal, naming the contour's line (or the lead) and the offset."""
    settings = [ln for ln in lines[:error.line] if ln.startswith("G10 L12")]
    offset = settings[-1].split(" R")[-1] if settings else "?"
    bad, contour = lines[error.line - 1], contour_lines(form)
    if bad in contour:
        where = msg("{name}, line {line}", name=form.name, line=form.path[contour.index(bad)].line)
    else:
        where = msg("{name}: the lead onto the first segment ({block})", name=form.name, block=bad)
    return FeatureError("contour", msg("{where}: cutter compensation at offset H = {offset} mm refuses it: "
                                       "{reason}", where=where, offset=offset, reason=error.message))


def oriented(segments, ccw: bool) -> list[Segment]:
    """The closed contour's segments in the direction asked (reversed if needed; the
    first segment stays first, run backwards)."""
    area = sum((s.start[0] * s.end[1] - s.end[0] * s.start[1]) for s in _chords(segments))
    if (area > 0) == ccw:
        return list(segments)
    back = [Segment(s.end, s.start, s.center, not s.cw, s.line) for s in reversed(segments)]
    return back[-1:] + back[:-1]  # the first segment stays first


def _chords(segments):
    for s in segments:
        pts = [s.start] + s.points()
        for a, b in zip(pts, pts[1:], strict=False):
            yield Segment(a, b)


def split_first(segments: list[Segment]) -> tuple[list[Segment], tuple[float, float]]:
    """The contour from the middle of its first segment round to it, and the direction
    of travel there."""
    first = segments[0]
    if first.center is None:
        mid = ((first.start[0] + first.end[0]) / 2, (first.start[1] + first.end[1]) / 2)
        dx, dy = first.end[0] - first.start[0], first.end[1] - first.start[1]
    else:
        from .contour import sweep_angle

        cx, cy = first.center
        radius = math.dist(first.start, first.center)
        a = math.atan2(first.start[1] - cy, first.start[0] - cx)
        a += sweep_angle(first.start, first.end, first.center, first.cw) / 2
        mid = (cx + radius * math.cos(a), cy + radius * math.sin(a))
        dx, dy = (math.sin(a), -math.cos(a)) if first.cw else (-math.sin(a), math.cos(a))
    norm = math.hypot(dx, dy)
    head = Segment(mid, first.end, first.center, first.cw, first.line)
    tail = Segment(first.start, mid, first.center, first.cw, first.line)
    return [head, *segments[1:], tail], (dx / norm, dy / norm)
