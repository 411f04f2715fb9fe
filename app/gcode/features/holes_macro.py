"""A hole pattern as a Fanuc parametric program: one subprogram for the hole, a loop
over the holes computing each centre (the paper's section 2: variables, a loop, a
subprogram for what repeats).

``HolePattern`` is the parametric form of a ``kinds.Holes`` (``Move.block`` of its
moves): the centre of hole ``k`` is ``x + r COS[a0 + 360 k / n]`` on a circle, or
``x + k p COS[a]`` in a row (the same formulas ``holes_circle``/``holes_row`` use).
Every hole's moves after the rapid over it are Z moves (and a dwell) at its centre, the
same for all holes: they are the subprogram, called at the current X Y; its pecks after
the first, down to the last, are a loop over the peck ``#113`` computing each depth.

- ``fanuc31``: ``WHILE [#110 LT n] DO 1`` ... ``END 1``, ``G65 P<sub>``;
- ``fanuc21``: the same loop by ``IF [...] GOTO`` and ``N`` labels, ``M98 P<sub>``.

The hole index is ``#110``, the centre ``#111``/``#112``, the peck ``#113`` (common
variables, apart from the layer loops' ``#101``-``#106``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .macro_text import MacroText
from .moves import FEED, RAPID, Move
from .plain import line_of, num

INDEX, X, Y, PECK = "#110", "#111", "#112", "#113"


def peck_depths(cut, peck: float) -> list[float]:
    """The depths a hole is fed to: ``top - k·peck`` (k = 1, 2, ...) down to the floor, or
    the floor at once without pecks."""
    if peck <= 0:
        return [cut.floor]
    depths, k = [], 1
    while not depths or depths[-1] > cut.floor + 1e-9:
        depths.append(max(cut.floor, cut.top - k * peck))
        k += 1
    return depths


@dataclass(frozen=True)
class HolePattern:
    """``layout``: ("circle", x, y, radius, start_angle) or ("row", x, y, pitch, angle);
    ``count`` holes; ``peck``: the depth of each peck (0: none)."""

    layout: tuple
    count: int
    peck: float = 0.0

    def centre(self) -> tuple[str, str]:
        """The expressions of hole ``#110``'s centre."""
        kind, x, y, size, angle = self.layout
        if kind == "circle":
            a = f"[{num(angle)} + 360 * {INDEX} / {self.count}]"
            return f"[{num(x)} + {num(size)} * COS{a}]", f"[{num(y)} + {num(size)} * SIN{a}]"
        return (f"[{num(x)} + {INDEX} * {num(size)} * COS[{num(angle)}]]",
                f"[{num(y)} + {INDEX} * {num(size)} * SIN[{num(angle)}]]")

    def centres(self) -> list[tuple[float, float]]:
        """The centres as the expressions give them (for checking the template)."""
        kind, x, y, size, angle = self.layout
        if kind == "circle":
            angles = [math.radians(angle + 360.0 * k / self.count) for k in range(self.count)]
            return [(x + size * math.cos(a), y + size * math.sin(a)) for a in angles]
        a = math.radians(angle)
        return [(x + k * size * math.cos(a), y + k * size * math.sin(a)) for k in range(self.count)]


def _holes(moves: list[Move]) -> list[list[Move]]:
    """The moves split per hole: each part starts with the rapid over its centre."""
    parts: list[list[Move]] = []
    for m in moves:
        if m.kind == RAPID and (not parts or m.end[:2] != parts[-1][0].end[:2]):
            parts.append([m])
        else:
            parts[-1].append(m)
    return parts


def _template(parts: list[list[Move]]) -> list[Move] | None:
    """The Z moves every hole makes after the rapid over it, or None if they differ."""
    first = parts[0][1:]
    for part in parts:
        rest = part[1:]
        if len(rest) != len(first) or any(
                a.kind != b.kind or a.end[2] != b.end[2] or a.feed != b.feed or a.value != b.value
                or a.end[:2] != part[0].end[:2] for a, b in zip(rest, first, strict=True)):
            return None
    return first


def _hole_lines(template: list[Move], peck: float, text: MacroText, label: int) -> list[str]:
    """One hole's Z moves: as they are, or with the pecks between the first and the last
    as a loop computing each depth (``top - #113·peck``)."""
    lines = [line_of(m, (m.end[0], m.end[1], None), fanuc=True) for m in template]
    feeds = [k for k, m in enumerate(template) if m.kind == FEED]
    top = template[feeds[0]].end[2] if feeds else 0.0
    depths = [template[k].end[2] for k in feeds[1:]]
    middle = list(enumerate(depths[1:-1], start=2))
    if peck <= 0 or not middle or any(abs(z - (top - k * peck)) > 1e-9 for k, z in middle):
        return lines
    first, last = feeds[1], feeds[-1]  # the first peck is written, the pecks after it up to the last loop
    feed = num(template[last].feed)
    body = [lines[first + 1], f"G01 Z[{num(top)} - {PECK}*{num(peck)}] F{feed}"]  # out above the top, down
    loop = text.loop(PECK, "2", "LT", str(len(depths)), body, 2, label)
    return lines[:first + 1] + loop + lines[last - 1:]


def holes_program(moves: list[Move], dialect: str, number: int,
                  label: int) -> tuple[list[str], list[str]] | None:
    """(main lines, subprogram lines) of a hole pattern's ``moves`` (its first move the
    rapid over the first hole at the safe height), or None when its holes differ."""
    form: HolePattern = moves[0].block
    parts = _holes(moves)
    template = _template(parts)
    if template is None or len(parts) != form.count:
        return None
    text = MacroText(dialect, 0.0)
    lines = _hole_lines(template, form.peck, text, label + 2)
    sub = [f"O{number} (one hole at the current X Y)", *lines, "M99"]
    x, y = form.centre()
    first = parts[0][0].end
    call = text.call(number)
    main = [f"(holes: {form.count} by the loop {INDEX}, each by O{number})",
            f"G00 X{num(first[0])} Y{num(first[1])}", *call]
    body = [f"{X} = {x}", f"{Y} = {y}", f"G00 X{X} Y{Y}", *call]
    return main + text.loop(INDEX, "1", "LT", str(form.count), body, 1, label), sub
