"""A pocket of a rounded rectangle (``round_pocket.PocketForm``) as a Fanuc 21 / 31
parametric program: variables, a loop over the layers, in each a helix and a loop over
the rings computing each ring from its index, one subprogram for the ring.

- ``O<n>`` one roughing layer at the depth it is given (``#26`` from ``G65 P<n> Z#101``
  on Fanuc 31, the common ``#101`` after ``M98 P<n>`` on Fanuc 21), from the level above
  in ``#103``: down at the centre, a helix of ``#138`` turns, then the rings ``#134`` =
  0, 1, ... (inside out), ring ``j`` of half sizes ``#135 = A - H - (n-1-j)·#128`` and
  ``#136`` (B likewise), corner radius ``#137`` (rc likewise), ``#128`` the spacing, each
  cut by the ring subprogram; back up over the centre.
- ``O<n+1>`` a ring with sharp corners, ``O<n+2>`` one with round corners (radius
  ``#137``): from (``#135``, 0) round to it, in the shape's axes (``RoundRect``) turned by
  ``#132``/``#133`` (``COS``/``SIN`` of its angle) about its centre (``#130``, ``#131``).
  Only the ones used are written.
- ``O<n+3>`` one finishing lap at the given depth: down at point 1, the lead-in, the
  wall (the ring subprogram at the wall's half sizes), the lead-out.

The dialects' loops and calls are ``macro_text.MacroText``'s.
"""

from __future__ import annotations

import math

from .macro_text import DEPTH, MacroText
from .plain import num
from .round_pocket import PocketForm, ring_steps

FROM = "#103"
SPACING, CX, CY, COS, SIN = "#128", "#130", "#131", "#132", "#133"
RING, A, B, R, TURNS, TURN = "#134", "#135", "#136", "#137", "#138", "#139"
NUMBERS = 4  # subprogram numbers a pocket takes


class Expr(str):
    """A term of the program text; unary minus writes it negated (a leading ``-``)."""

    def __neg__(self) -> Expr:
        return Expr(self[1:] if self.startswith("-") else self if self == "0" else "-" + self)


def _sum(*terms: tuple[int, str]) -> str:
    """``[t1 + t2 - t3]`` of (sign, term) pairs, zeros left out, a term's leading ``-``
    taken into its sign; ``0`` when nothing is left."""
    out = ""
    for sign, text in terms:
        if text == "0":
            continue
        if text.startswith("-"):
            sign, text = -sign, text[1:]
        out += (" + " if sign > 0 else " - ") if out else ("" if sign > 0 else "-")
        out += text
    return f"[{out}]" if out else "0"


def _mul(term: str, var: str) -> str:
    return "0" if term == "0" else f"{term}*{var}"


def _diff(a: str, b: str) -> str:
    return "0" if a == b else _sum((1, a), (-1, b))


def _xy(x: str, y: str) -> str:
    """The X and Y words of the point (``x``, ``y``) in the shape's axes."""
    return (f"X{_sum((1, CX), (1, _mul(x, COS)), (-1, _mul(y, SIN)))} "
            f"Y{_sum((1, CY), (1, _mul(x, SIN)), (1, _mul(y, COS)))}")


def _ij(x: str, y: str) -> str:
    """The I and J words of the vector (``x``, ``y``) in the shape's axes."""
    return f"I{_sum((1, _mul(x, COS)), (-1, _mul(y, SIN)))} J{_sum((1, _mul(x, SIN)), (1, _mul(y, COS)))}"


def ring_program(form: PocketForm, number: int, rounded: bool) -> list[str]:
    """``O<number>``: one ring of half sizes ``#135`` x ``#136`` (round corners of radius
    ``#137`` when ``rounded``), the steps of ``round_pocket.ring_steps``."""
    shape, feed = form.shape, num(form.cut.feed)
    a, b = Expr(A), Expr(B)
    if rounded:  # the corner centres are constants: A - rc, B - rc
        ka, kb = shape.a - shape.rc, shape.b - shape.rc
        sides = (kb > 1e-9, ka > 1e-9)
        steps = ring_steps(a, b, Expr(num(ka)), Expr(num(kb)), True, sides, form.ccw, Expr("0"))
    else:
        steps = ring_steps(a, b, a, b, False, (True, True), form.ccw, Expr("0"))
    arc = "G03" if form.ccw else "G02"
    said = f", corners of radius {R}" if rounded else ", sharp corners"
    out = [f"O{number} (one ring from X+ of the centre: half sizes {A} x {B}{said})"]
    last = (a, Expr("0"))
    for step in steps:
        if step[0] == "line":
            out.append(f"G01 {_xy(step[1], step[2])} F{feed}")
        else:
            i, j = _diff(step[3], last[0]), _diff(step[4], last[1])
            out.append(f"{arc} {_xy(step[1], step[2])} {_ij(i, j)} F{feed}")
        last = (step[1], step[2])
    return out + ["M99"]


class Writer(MacroText):
    """The program text of one ``PocketForm`` in one dialect (see the module docstring)."""

    def __init__(self, form: PocketForm, dialect: str, number: int, label: int) -> None:
        super().__init__(dialect, form.cut.top)
        self.form = form
        self.layer, self.sharp, self.round, self.wall = (number + k for k in range(NUMBERS))
        self.label = label

    def main(self) -> list[str]:
        form, cut = self.form, self.form.cut
        shape, low = form.shape, form.low
        reach = min(shape.a, shape.b) - form.h_out
        out = [f"(pocket: {form.n} rings a layer about the centre, from the inside out)",
               f"{CX} = {num(shape.cx)}", f"{CY} = {num(shape.cy)}", f"{COS} = COS[{num(shape.angle)}]",
               f"{SIN} = SIN[{num(shape.angle)}]", f"{SPACING} = [{num(reach)}/{num(form.n - 0.5)}]",
               f"G00 X{num(shape.cx)} Y{num(shape.cy)} Z{num(cut.safe_z)}", f"{FROM} = {num(cut.top)}",
               f"{TURNS} = {form.pairs(form.rough.span / form.rough.count)}"]
        out += self.layers(form.rough, self.layer, self.label, [f"{FROM} = {DEPTH}"])
        if cut.finish_z > 0:
            out += ["(the floor pass)", f"{TURNS} = {form.pairs(cut.finish_z)}",
                    *self.call(self.layer, num(cut.floor))]
        wall = shape.corner(cut.radius)
        out += ["(the wall at the tool radius on every layer)", f"{A} = {num(shape.a - cut.radius)}",
                f"{B} = {num(shape.b - cut.radius)}"] + ([f"{R} = {num(wall)}"] if wall > 0 else [])
        start = form.lead.p1 if form.lead else form.wall_start()
        if math.dist(start, (shape.cx, shape.cy)) > 1e-9:  # from over the centre (a move of no length: none)
            out.append(f"G00 X{num(start[0])} Y{num(start[1])}")
        if cut.safe_z > low + 1e-9:
            out.append(f"G00 Z{num(low)}")
        out += self.layers(form.walls, self.wall, self.label + 4, [])
        return out + [f"G00 Z{num(cut.safe_z)}"]

    def layer_program(self) -> list[str]:
        form, cut = self.form, self.form.cut
        z, plunge, feed = self.depth, num(cut.plunge_feed), num(cut.feed)
        arc = "G03" if form.ccw else "G02"
        rho = Expr(num(form.rho))
        back = -rho
        out = [f"O{self.layer} (one roughing layer at Z{z} from Z{FROM}: a helix, then the rings)"]
        if cut.safe_z > form.low + 1e-9:
            out.append(f"G00 Z{num(form.low)}")
        out += [f"G01 Z{FROM} F{plunge}", f"G01 {_xy(rho, '0')} F{plunge}"]
        drop = f"[{FROM} - {z}]"
        over, home = f"{_xy(back, '0')}", f"{_xy(rho, '0')}"
        turn = [f"{arc} {over} Z[{FROM} - {drop}*[2*{TURN} - 1]/[2*{TURNS}]] {_ij(back, '0')} F{plunge}",
                f"{arc} {home} Z[{FROM} - {drop}*{TURN}/{TURNS}] {_ij(rho, '0')} F{plunge}"]
        out += self.loop(TURN, "1", "LE", TURNS, turn, 2, self.label + 10)
        out += [f"{arc} {over} {_ij(back, '0')} F{feed}", f"{arc} {home} {_ij(rho, '0')} F{feed}"]
        first_round = form.first_round()
        for k, (j0, j1, rounded) in enumerate(((0, first_round, False), (first_round, form.n, True))):
            if j0 == 0 < j1 and abs(form.shape.a - form.offset(0) - form.rho) < 1e-9:
                # the helix ends where the first ring starts: no feed over (a move of no length)
                out += [f"{RING} = 0", *self.ring_body(rounded, feed=False)]
                j0 = 1
            if j1 > j0:
                body = self.ring_body(rounded)
                out += self.loop(RING, str(j0), "LT", str(j1), body, 3, self.label + 12 + 2 * k)
        return out + [f"G00 Z{num(cut.safe_z)}", f"G00 X{num(form.shape.cx)} Y{num(form.shape.cy)}", "M99"]

    def ring_body(self, rounded: bool, feed: bool = True) -> list[str]:
        """Ring ``#134``'s sizes, the feed over to its start (``feed``), the call of its
        subprogram."""
        form = self.form
        shape, outer, n = form.shape, form.h_out, form.n
        inward = f"[{n - 1} - {RING}]*{SPACING}"
        body = [f"{A} = [{num(shape.a - outer)} - {inward}]", f"{B} = [{num(shape.b - outer)} - {inward}]"]
        if rounded:
            body.append(f"{R} = [{num(shape.rc - outer)} - {inward}]")
        if feed:
            body.append(f"G01 {_xy(A, '0')} F{num(form.cut.feed)}")
        return body + self.call(self.round if rounded else self.sharp)

    def wall_program(self) -> list[str]:
        form, cut = self.form, self.form.cut
        lead, feed = form.lead, num(cut.feed)
        out = [f"O{self.wall} (one finishing lap of the wall at Z{self.depth})",
               f"G01 Z{self.depth} F{num(cut.plunge_feed)}"]
        ring = self.round if form.shape.corner(cut.radius) > 0 else self.sharp
        if lead is None:
            return out + self.call(ring) + ["M99"]
        arc = "G02" if lead.cw else "G03"
        def arc_to(end, start) -> str:
            centre = lead.p4
            return (f"{arc} X{num(end[0])} Y{num(end[1])} I{num(centre[0] - start[0])} "
                    f"J{num(centre[1] - start[1])} F{feed}")

        return out + [f"G01 X{num(lead.p2[0])} Y{num(lead.p2[1])} F{feed}", arc_to(lead.p3, lead.p2),
                      *self.call(ring), arc_to(lead.p5, lead.p3),
                      f"G01 X{num(lead.p1[0])} Y{num(lead.p1[1])} F{feed}", "M99"]

    def subprograms(self) -> list[str]:
        form, cut = self.form, self.form.cut
        first_round = form.first_round()
        wall_round = form.shape.corner(cut.radius) > 0
        out = self.layer_program()
        if first_round > 0 or not wall_round:
            out += ring_program(form, self.sharp, False)
        if first_round < form.n or wall_round:
            out += ring_program(form, self.round, True)
        return out + self.wall_program()


def pocket_program(form: PocketForm, dialect: str, number: int, label: int) -> tuple[list[str], list[str]]:
    """(main program lines, subprograms ``O<number>``..``O<number+3>``) of ``form``; block
    labels from ``label`` up (Fanuc 21)."""
    writer = Writer(form, dialect, number, label)
    return writer.main(), writer.subprograms()
