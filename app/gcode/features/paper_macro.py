"""The paper's profile program (``paper.PaperForm``) in Fanuc 21 / Fanuc 31 macro form.

Two subprograms: ``O<c>`` the contour from point 3 round to point 3, written once, and
``O<c+1>`` one ring: the radius register set to the offset ``H`` (``G10 L12``), points
1, 2 and 5 computed from ``H`` and the lead radius, G41/G42 on, the lead-in arc, the
contour (``M98 P<c>``), the lead-out arc, G40 back to point 1. The main program loops
over the depth levels and, on each, over the rings: ``H`` starts at H_1 = M - D/2 and
drops by the stepover B·D/100 for as many rings as the generator counted, then the
last ring at D/2 + U (the paper's figure 6); the finish phase runs one ring at D/2.

- ``fanuc31``: WHILE/DO/END loops, ``G65 P<c+1> H<offset>`` (``H`` arrives as ``#11``).
- ``fanuc21``: IF/GOTO loops, ``M98 P<c+1>`` with the offset in the common ``#105``
  (no WHILE, no G65: the paper's table 1).

The depth is ``#101``, the layer count ``#102``, the ring offset and count ``#103``
(``#105`` on Fanuc 21) and ``#104``.
"""

from __future__ import annotations

from .paper import PaperForm, Phase, contour_lines, fmt, phase_start

DEPTH, LAYER, RING = "#101", "#102", "#104"


def _lin(base: float, factor: float, var: str) -> str:
    """``[base + factor*var]`` with the sign written as an operator."""
    sign = "-" if factor < 0 else "+"
    return f"[{fmt(base)} {sign} {fmt(abs(factor))}*{var}]"


def _point(form: PaperForm, a: float, b: float, var: str) -> str:
    """X and Y of point 3 + (a·t + b·n)·var."""
    (x, y), (tx, ty), (nx, ny) = form.p3, form.t, form.n
    return f"X{_lin(x, a * tx + b * nx, var)} Y{_lin(y, a * ty + b * ny, var)}"


def ring_program(form: PaperForm, number: int, contour: int, h: str, rho: str) -> list[str]:
    """``O<number>``: one ring at the offset in ``h`` (``rho``: a free variable)."""
    tx, ty = form.t
    nx, ny = form.n
    arc, reg = form.lead_arc(), form.register
    return [f"O{number} (one ring: register {reg} = H {h}, lead-in on the first segment)",
            f"{rho} = [{fmt(form.lead)} + {h}]",
            f"G10 L12 P{reg} R{h}",
            f"G01 {_point(form, form.shift, 2, rho)} F{fmt(form.cut.feed)}",
            f"{form.comp()} D{reg}",
            f"G01 {_point(form, -1, 1, rho)}",
            f"{arc} X{fmt(form.p3[0])} Y{fmt(form.p3[1])} I[{fmt(tx)}*{rho}] J[{fmt(ty)}*{rho}]",
            f"M98 P{contour}",
            f"{arc} {_point(form, 1, 1, rho)} I[{fmt(nx)}*{rho}] J[{fmt(ny)}*{rho}]",
            "G40",
            f"G01 {_point(form, form.shift, 2, rho)}",
            "M99"]


def _runs(form: PaperForm, levels) -> list[tuple[float, int]]:
    """The levels as runs ``(span, count)``: level k of a run (1..count) is
    ``top - span·k/count``, as ``Cutting.layers`` computes them; a level after the
    first run (the floor pass) is a run of one."""
    levels, top = list(levels), form.cut.top
    for n in range(len(levels), 0, -1):
        if form.cut.layers(levels[n - 1]) == levels[:n]:
            return [(top - levels[n - 1], n)] + [(top - z, 1) for z in levels[n:]]
    return [(top - z, 1) for z in levels]


def _rings(form: PaperForm, phase: Phase, dialect: str, ring: int, label: int) -> list[str]:
    """Every ring of one level."""
    offsets, cut = phase.offsets, form.cut
    loop = len(offsets) - 1
    if dialect == "fanuc31":
        out = []
        if loop:
            out += [f"#103 = {fmt(offsets[0])}", f"{RING} = 1", f"WHILE [{RING} LE {loop}] DO 2",
                    f"G65 P{ring} H#103", f"#103 = [#103 - {fmt(cut.step)}]", f"{RING} = [{RING} + 1]",
                    "END 2"]
        return out + [f"G65 P{ring} H{fmt(offsets[-1])}"]
    out = []
    if loop:
        out += [f"#105 = {fmt(offsets[0])}", f"{RING} = 1",
                f"N{label} IF [{RING} GT {loop}] GOTO {label + 1}", f"M98 P{ring}",
                f"#105 = [#105 - {fmt(cut.step)}]", f"{RING} = [{RING} + 1]", f"GOTO {label}",
                f"N{label + 1} #105 = {fmt(offsets[-1])}"]
    else:
        out.append(f"#105 = {fmt(offsets[-1])}")
    return out + [f"M98 P{ring}"]


def _layers(form: PaperForm, phase: Phase, dialect: str, ring: int, label: int) -> list[str]:
    """The loops over the levels of one phase."""
    cut = form.cut
    d = form.descent(phase)
    out = []
    for k, (span, count) in enumerate(_runs(form, phase.levels)):
        base = label + 10 * k
        body = [f"{DEPTH} = [{fmt(cut.top)} - {fmt(span)}*{LAYER}/{count}]",
                f"G01 Z{DEPTH} F{fmt(cut.plunge_feed)}", *_rings(form, phase, dialect, ring, base + 2),
                f"G01 X{fmt(d[0])} Y{fmt(d[1])} F{fmt(cut.feed)}", f"{LAYER} = [{LAYER} + 1]"]
        head = [f"({phase.note}s: {count} down to Z{fmt(cut.top - span)})", f"{LAYER} = 1"]
        if dialect == "fanuc31":
            out += head + [f"WHILE [{LAYER} LE {count}] DO 1", *body, "END 1"]
        else:
            out += head + [f"N{base} IF [{LAYER} GT {count}] GOTO {base + 1}", *body, f"GOTO {base}",
                           f"N{base + 1} {LAYER} = 0"]
    return out


def paper_program(form: PaperForm, dialect: str, contour: int, label: int) -> tuple[list[str], list[str]]:
    """(main program lines, subprograms) of ``form``; subprograms ``O<contour>`` and
    ``O<contour+1>``, block labels from ``label`` up (Fanuc 21)."""
    ring = contour + 1
    main = [f"(profile: the paper's rings by cutter compensation; contour O{contour}, ring O{ring})"]
    for p, phase in enumerate(form.phases):
        main += phase_start(form, phase, p == 0)
        main += _layers(form, phase, dialect, ring, label + 50 * p)
    main.append(f"G00 Z{fmt(form.cut.safe_z)}")
    h, rho = ("#11", "#30") if dialect == "fanuc31" else ("#105", "#106")
    subs = [f"O{contour} (the contour from the middle of its first segment round to it)",
            *contour_lines(form), "M99", *ring_program(form, ring, contour, h, rho)]
    return main, subs
