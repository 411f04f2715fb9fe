"""Facing as a parametric program: rows computed from their index.

``FaceForm`` is one face: ``count`` rows ``y0 + span·j/(count - 1)`` fed alternately
from ``left`` to ``right`` and back, on every layer down to the floor + W and on a floor
pass; each layer starts and ends at the safe height over (``left``, ``y0``), so all
layers are the same moves at their depth. ``moves()`` are its moves (the plain program);
``face_program`` writes them for Fanuc 21 / 31: the layer loop (``macro_text``) calling
``O<n>``, one layer: down outside the stock, the first row, then a loop over pairs of
rows (``#141``: rows 2k-1 and 2k, each ``Y`` computed), the last row when the count of
the others is odd.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from . import entry
from .cutting import Cutting
from .kinds import Face
from .macro_text import MacroText, levels_of
from .moves import RAPID, Move, Path
from .plain import num

PAIR = "#141"


@dataclass(frozen=True)
class FaceForm:
    """One face's rows and layers (see the module docstring)."""

    cut: Cutting
    left: float
    right: float
    y0: float
    span: float  # from the first row to the last
    count: int  # rows

    def row(self, j: int) -> float:
        return self.y0 + self.span * j / (self.count - 1) if self.count > 1 else self.y0

    def moves(self) -> list[Move]:
        cut = self.cut
        path = Path((self.left, self.y0, cut.safe_z))
        path.moves.append(Move(RAPID, path.pos))
        levels = cut.layers(cut.floor + cut.finish_z) + ([cut.floor] if cut.finish_z > 0 else [])
        for k, z in enumerate(levels):
            path.note = f"layer {k + 1}/{len(levels)} z {z:.3f}"
            entry.approach(path, cut, (self.left, self.y0), z)
            for j in range(self.count):
                path.feed(y=self.row(j), f=cut.feed)
                path.feed(self.right if j % 2 == 0 else self.left, f=cut.feed)
            entry.retract(path, cut)  # every layer the same moves at its depth: back over the start
            path.rapid(self.left, self.y0)
        path.note = ""
        return [Move(m.kind, m.end, m.feed, m.center, m.cw, m.value, m.note, self) for m in path.moves]


def face_form(feature: Face) -> FaceForm:
    """The rows of ``feature``: one in the middle when the tool covers its height, else
    as few as the stepover allows from one edge to the other."""
    cut = feature.cut
    r = cut.radius
    left, right = feature.x - r - 1.0, feature.x + feature.width + r + 1.0
    if feature.height <= cut.tool_diameter:
        return FaceForm(cut, left, right, feature.y + feature.height / 2, 0.0, 1)
    span = feature.height - cut.tool_diameter
    count = math.ceil(span / cut.step - 1e-9) + 1
    return FaceForm(cut, left, right, feature.y + r, span, count)


def face_program(form: FaceForm, dialect: str, number: int, label: int) -> tuple[list[str], list[str]]:
    """(main program lines, the layer subprogram ``O<number>``) of ``form``; block labels
    from ``label`` up (Fanuc 21)."""
    cut = form.cut
    text = MacroText(dialect, cut.top)
    feed = num(cut.feed)
    main = [f"(face: {form.count} rows a layer)", f"G00 X{num(form.left)} Y{num(form.y0)} Z{num(cut.safe_z)}",
            *text.layers(levels_of(cut, cut.floor + cut.finish_z), number, label)]
    if cut.finish_z > 0:
        main += ["(the floor pass)", *text.call(number, num(cut.floor))]
    sub = [f"O{number} (one facing layer at Z{text.depth}: rows alternately to X{num(form.right)} "
           f"and back to X{num(form.left)})"]
    low = min(cut.safe_z, cut.top + entry.GAP)
    if cut.safe_z > low + 1e-9:
        sub.append(f"G00 Z{num(low)}")
    sub += [f"G01 Z{text.depth} F{num(cut.plunge_feed)}", f"G01 X{num(form.right)} F{feed}"]
    if form.count > 1:
        gaps = num(form.count - 1)

        def row(index: str) -> str:
            return f"G01 Y[{num(form.y0)} + {num(form.span)}*{index}/{gaps}] F{feed}"

        body = [row(f"[2*{PAIR} - 1]"), f"G01 X{num(form.left)} F{feed}", row(f"[2*{PAIR}]"),
                f"G01 X{num(form.right)} F{feed}"]
        pairs = (form.count - 1) // 2
        if pairs:
            sub += text.loop(PAIR, "1", "LE", str(pairs), body, 2, label + 10)
        if (form.count - 1) % 2:
            sub += [f"G01 Y{num(form.row(form.count - 1))} F{feed}", f"G01 X{num(form.left)} F{feed}"]
    sub += [f"G00 Z{num(cut.safe_z)}", f"G00 X{num(form.left)} Y{num(form.y0)}", "M99"]
    return main, sub
