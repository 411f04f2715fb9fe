"""A hole pattern as a Fanuc parametric program: one subprogram for the hole, a loop
over the holes computing each centre (the paper's section 2: variables, a loop, a
subprogram for what repeats).

``HolePattern`` is the parametric form of a ``kinds.Holes`` (``Move.block`` of its
moves): the centre of hole ``k`` is ``x + r COS[a0 + 360 k / n]`` on a circle, or
``x + k p COS[a]`` in a row (the same formulas ``holes_circle``/``holes_row`` use).
Every hole's moves after the rapid over it are Z moves (and a dwell) at its centre, the
same for all holes: they are the subprogram, called at the current X Y.

- ``fanuc31``: ``WHILE [#110 LT n] DO 1`` ... ``END 1``, ``G65 P<sub>``;
- ``fanuc21``: the same loop by ``IF [...] GOTO`` and ``N`` labels, ``M98 P<sub>``.

The hole index is ``#110``, the centre ``#111``/``#112`` (common variables, apart from
the layer loops' ``#101``-``#106``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .moves import RAPID, Move
from .plain import line_of, num

INDEX, X, Y = "#110", "#111", "#112"


@dataclass(frozen=True)
class HolePattern:
    """``layout``: ("circle", x, y, radius, start_angle) or ("row", x, y, pitch, angle);
    ``count`` holes."""

    layout: tuple
    count: int

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


def holes_program(moves: list[Move], dialect: str, number: int,
                  label: int) -> tuple[list[str], list[str]] | None:
    """(main lines, subprogram lines) of a hole pattern's ``moves`` (its first move the
    rapid over the first hole at the safe height), or None when its holes differ."""
    form: HolePattern = moves[0].block
    parts = _holes(moves)
    template = _template(parts)
    if template is None or len(parts) != form.count:
        return None
    sub = [f"O{number} (one hole at the current X Y)"]
    for m in template:  # Z moves and dwells only (``_template``)
        here = (m.end[0], m.end[1], None)
        sub.append(line_of(m, here, fanuc=True))
    sub.append("M99")
    x, y = form.centre()
    first = parts[0][0].end
    call = f"G65 P{number}" if dialect == "fanuc31" else f"M98 P{number}"
    main = [f"(holes: {form.count} by the loop {INDEX}, each by O{number})",
            f"G00 X{num(first[0])} Y{num(first[1])}", call, f"{INDEX} = 1"]
    body = [f"{X} = {x}", f"{Y} = {y}", f"G00 X{X} Y{Y}", call, f"{INDEX} = {INDEX} + 1"]
    if dialect == "fanuc31":
        main += [f"WHILE [{INDEX} LT {form.count}] DO 1", *body, "END 1"]
    else:
        main += [f"N{label} IF [{INDEX} GE {form.count}] GOTO {label + 1}", *body, f"GOTO {label}",
                 f"N{label + 1} {INDEX} = 0"]
    return main, sub
