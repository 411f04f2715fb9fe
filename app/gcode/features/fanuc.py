"""The Fanuc macro writers: the same moves as ``plain.py`` as a parametric program.

Layers that repeat (``folding.py``) become one subprogram whose Z words are the layer's
depth plus a constant, called once per layer from a loop:

- ``fanuc31``: ``WHILE [#102 LE n] DO 1`` ... ``END 1`` around ``G65 P1001 Z#101`` (the
  depth arrives in the subprogram as its argument ``#26``);
- ``fanuc21``: no WHILE and no G65 (the paper's table 1): an ``IF [...] GOTO`` loop
  around ``M98 P1001``, the depth in the common variable ``#101``.

Layers of uneven depth (a finishing floor after even roughing layers) loop over the even
ones and call the rest one by one. Hole patterns are a loop over the holes
(``holes_macro.py``), profiles the paper's program (``paper_macro.py``), rectangular and
round pockets and slots loops over layers and rings computed from their sizes
(``round_macro.py``), faces loops over layers and rows (``face_macro.py``). Everything
else (an exact slot, a pocket of a contour's shape: rings of offset outlines that no
formula gives) is written as in the plain program, its layers folded into a loop.
Subprograms follow ``M30``; the file is wrapped in ``%`` lines. The loader's expander
(issue 9) must give back exactly the plain program's moves.
"""

from __future__ import annotations

from .face_macro import FaceForm, face_program
from .folding import Inline, Repeat, fold
from .holes_macro import HolePattern, holes_program
from .moves import ARC, FEED, RAPID, Move
from .paper_macro import paper_program
from .plain import line_of, num
from .round_macro import NUMBERS as POCKET_NUMBERS
from .round_macro import pocket_program
from .round_pocket import PocketForm

DIALECTS = ("fanuc21", "fanuc31")
FIRST_SUB = 1001
DEPTH, COUNT = "#101", "#102"


def _z(term: tuple[bool, float], var: str) -> str:
    shifts, value = term
    if not shifts:
        return f"Z{num(value)}"
    if abs(value) < 5e-5:
        return f"Z{var}"
    return f"Z[{var}{'+' if value > 0 else '-'}{num(abs(value))}]"


def _sub_line(m: Move, previous_xy, term, var: str) -> str:
    xy = f"X{num(m.end[0])} Y{num(m.end[1])}"
    z = _z(term, var)
    if m.kind == RAPID:
        return f"G00 {xy} {z}"
    if m.kind == FEED:
        return f"G01 {xy} {z} F{num(m.feed)}"
    i, j = m.center[0] - previous_xy[0], m.center[1] - previous_xy[1]
    return f"{'G02' if m.cw else 'G03'} {xy} {z} I{num(i)} J{num(j)} F{num(m.feed)}"


def _subprogram(number: int, item: Repeat, previous_xy, var: str) -> list[str]:
    out = [f"O{number} (one layer; Z = the layer depth {var} plus a constant)"]
    note = None
    for m, term in zip(item.template, item.z_terms, strict=True):
        if m.note and m.note != note:
            out.append(f"({m.note.split(' z ')[0]})")
            note = m.note
        out.append(_sub_line(m, previous_xy, term, var))
        previous_xy = m.end[:2]
    return out + ["M99"]


def _uniform_step(depths: list[float]) -> float | None:
    if len(depths) < 2:
        return None
    steps = [b - a for a, b in zip(depths, depths[1:], strict=False)]
    return steps[0] if all(abs(s - steps[0]) < 1e-9 for s in steps) else None


def _loop(dialect: str, number: int, depths: list[float], label: int) -> list[str]:
    step = _uniform_step(depths)
    call = f"G65 P{number} Z{DEPTH}" if dialect == "fanuc31" else f"M98 P{number}"
    if step is None:  # uneven layers: a loop over the even ones (a finishing floor after them)
        even = next((n for n in range(len(depths) - 1, 1, -1) if _uniform_step(depths[:n]) is not None), 0)
        if even:
            rest = _loop(dialect, number, depths[even:], label + 2)  # its own labels on Fanuc 21
            return _loop(dialect, number, depths[:even], label) + rest
        if dialect == "fanuc31":
            return [f"G65 P{number} Z{num(d)}" for d in depths]
        return [line for d in depths for line in (f"{DEPTH} = {num(d)}", call)]
    n, span = len(depths), depths[-1] - depths[0]
    head = [f"({n} layers from Z{num(depths[0])} to Z{num(depths[-1])})", f"{COUNT} = 1"]
    sign = "-" if span < 0 else "+"
    depth = f"{DEPTH} = [{num(depths[0])} {sign} {num(abs(span))}*[{COUNT} - 1]/{n - 1}]"  # not a sum
    advance = [f"{COUNT} = {COUNT} + 1"]
    if dialect == "fanuc31":
        return head + [f"WHILE [{COUNT} LE {n}] DO 1", depth, call, *advance, "END 1"]
    return head + [f"N{label} IF [{COUNT} GT {n}] GOTO {label + 1}", depth, call, *advance,
                   f"GOTO {label}", f"N{label + 1} {COUNT} = 0"]


def write_fanuc(moves: list[Move], dialect: str, title: str = "") -> str:
    """The program text of ``moves`` in ``dialect`` (see the module docstring)."""
    if dialect not in DIALECTS:
        raise ValueError(f"unknown dialect {dialect!r}: one of {', '.join(DIALECTS)}")
    var = "#26" if dialect == "fanuc31" else DEPTH
    main = ["%", f"O0001 ({title or 'machining features'}; {dialect.replace('fanuc', 'Fanuc ')})",
            "G21 G90 G17"]
    subs: list[str] = []
    end, note, number = (None, None, None), None, FIRST_SUB
    first = next((m for m in moves if m.kind in (RAPID, FEED, ARC)), None)
    if first is not None and first.kind == RAPID:  # up to the safe height first, as plain.py
        main.append(f"G00 Z{num(first.end[2])}")
        end = (None, None, first.end[2])
    for run in _runs(moves):
        written = _parametric(run, dialect, number)
        if written is not None:
            main += written[0]
            subs += written[1]
            end, note, number = run[-1].end, None, number + written[2]
            continue
        end, note, number = _folded(run, dialect, var, main, subs, end, note, number)
    return "\n".join(main + ["M05", "M30"] + subs + ["%"]) + "\n"


def _parametric(run: list[Move], dialect: str, number: int):
    """(main lines, subprograms, subprogram numbers taken) of a run of one parametric form
    (holes, face, pocket, the paper's profile), its programs numbered from ``number``;
    None for moves of no form (or holes that differ)."""
    form, k = run[0].block, number - FIRST_SUB
    if form is None:
        return None
    if isinstance(form, HolePattern):
        written = holes_program(run, dialect, number, 7000 + 10 * k)
        return None if written is None else (*written, 1)
    if isinstance(form, FaceForm):
        return (*face_program(form, dialect, number, 3000 + 100 * k), 1)
    if isinstance(form, PocketForm):
        return (*pocket_program(form, dialect, number, 3000 + 100 * k), POCKET_NUMBERS)
    return (*paper_program(form, dialect, number, 5000 + 100 * k), 2)


def _runs(moves: list[Move]) -> list[list[Move]]:
    """Consecutive moves of one parametric form (``Move.block``), or of none."""
    runs: list[list[Move]] = []
    for m in moves:
        if runs and runs[-1][0].block is m.block:
            runs[-1].append(m)
        else:
            runs.append([m])
    return runs


def _folded(moves, dialect, var, main, subs, end, note, number):
    """Append ``moves`` as inline lines and looped layers; the new (end, note, number)."""
    for item in fold(moves):
        if isinstance(item, Inline):
            for m in item.moves:
                if m.note and m.note != note:
                    main.append(f"({m.note})")
                    note = m.note
                main.append(line_of(m, end, fanuc=True))
                if m.kind in (RAPID, FEED, ARC):
                    end = m.end
            continue
        subs += _subprogram(number, item, end[:2], var)
        main += _loop(dialect, number, item.depths, 10 * (number - FIRST_SUB + 1))
        last = item.template[-1]
        end = (last.end[0], last.end[1], None)
        number += 1
    return end, note, number
