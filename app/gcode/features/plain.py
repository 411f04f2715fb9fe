"""The plain G-code writer: moves -> text any controller (and our loader) runs.

Absolute millimetres, XY plane; arcs as G02/G03 with I J (helical with Z); a move's
note becomes a comment when it changes; tool changes ``M06 Tn`` (the job pauses),
spindle ``M03 Sn`` / ``M05``; the program ends ``M05`` and ``M30``. Only the axes a
move changes are written; the first rapid goes up to its height before it moves over.
"""

from __future__ import annotations

from .moves import ARC, DWELL, FEED, RAPID, SPINDLE, TOOL, Move


def num(value: float) -> str:
    """A coordinate with at most 4 decimals and no trailing zeros (``-0`` is ``0``)."""
    text = f"{value:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _xyz(m: Move, previous_end, always: str = "") -> str:
    """The axes whose written value changes (all of them after an unknown position)."""
    words = [f"{a}{num(v)}" for a, v, old in zip("XYZ", m.end, previous_end, strict=True)
             if a in always or old is None or num(v) != num(old)]
    return " ".join(words)


def line_of(m: Move, previous_end, fanuc: bool = False) -> str:
    """One move as a G-code line (``previous_end`` items None where unknown; ``fanuc``:
    the dwell as Fanuc writes it, ``G04 X`` seconds, since Fanuc's ``P`` is milliseconds)."""
    if m.kind == RAPID:
        return f"G00 {_xyz(m, previous_end)}"
    if m.kind == FEED:
        return f"G01 {_xyz(m, previous_end)} F{num(m.feed)}"
    if m.kind == ARC:
        i, j = m.center[0] - previous_end[0], m.center[1] - previous_end[1]
        return f"{'G02' if m.cw else 'G03'} {_xyz(m, previous_end, 'XY')} I{num(i)} J{num(j)} F{num(m.feed)}"
    if m.kind == DWELL:
        return f"G04 {'X' if fanuc else 'P'}{num(m.value)}"
    if m.kind == TOOL:
        return f"M06 T{int(m.value)}"
    if m.kind == SPINDLE:
        return f"M03 S{num(m.value)}" if m.value > 0 else "M05"
    raise ValueError(f"unknown move kind {m.kind!r}")


def write_plain(moves: list[Move], title: str = "") -> str:
    """The program text of ``moves`` (see the module docstring)."""
    out = [f"({title})"] if title else []
    out.append("G21 G90 G17")
    note, end = None, (None, None, None)
    first = next((m for m in moves if m.kind in (RAPID, FEED, ARC)), None)
    if first is not None and first.kind == RAPID:  # up to the safe height before moving over
        out.append(f"G00 Z{num(first.end[2])}")
        end = (None, None, first.end[2])
    for m in moves:
        if m.note and m.note != note:
            out.append(f"({m.note})")
            note = m.note
        out.append(line_of(m, end))
        if m.kind in (RAPID, FEED, ARC):
            end = m.end
    out += ["M05", "M30"]
    return "\n".join(out) + "\n"
