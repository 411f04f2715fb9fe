"""Finding the layers of a toolpath that repeat: the same moves at a lower Z.

A feature cuts layer after layer with the same XY path; every Z of a layer is either
the same in all of them (the safe height) or the layer's own depth plus a fixed amount.
``fold(moves)`` groups the moves into ``Inline`` runs and ``Repeat`` runs (a template
layer, each Z as ``(shifts, value)``: a shifting Z is ``layer depth + value``, and the
depth of every layer), so a macro writer can print the template once and loop over it.
Layers are told apart by the generators' notes (``layer 2/5 ...``). A first layer that
begins with moves the others lack (the finishing pass's way over to the wall) has them
written inline and folds with the rest; the generators end each roughing and facing
layer over where the next begins, so layer 1 is the same moves as the others.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .moves import ARC, FEED, RAPID, Move

_LAYER = re.compile(r"layer (\d+)")
_NUMBERS = re.compile(r"-?\d+(\.\d+)?(/\d+)?")
TOL = 1e-7


@dataclass
class Inline:
    moves: list[Move]


@dataclass
class Repeat:
    template: list[Move]
    z_terms: list[tuple[bool, float]]  # per move: (shifts with the layer, constant or offset)
    depths: list[float]  # the depth of each layer (the first: the template's)


def _blocks(moves: list[Move]) -> list[tuple[str, list[Move]]]:
    """Consecutive runs of one layer (family, moves); moves without a layer note alone."""
    out: list[tuple[str, list[Move]]] = []
    key = None
    for m in moves:
        found = _LAYER.search(m.note)
        this = (_NUMBERS.sub("#", m.note), found.group(1)) if found else None
        if this is not None and this == key:
            out[-1][1].append(m)
        else:
            out.append((this[0] if this else "", [m]))
        key = this
    return out


def _depth(block: list[Move]) -> float:
    return min(m.end[2] for m in block)


def _same_shape(a: Move, b: Move) -> bool:
    return (a.kind == b.kind and a.feed == b.feed and a.cw == b.cw and a.value == b.value
            and abs(a.end[0] - b.end[0]) < TOL and abs(a.end[1] - b.end[1]) < TOL
            and (a.center is None) == (b.center is None)
            and (a.center is None or max(abs(p - q) for p, q in zip(a.center, b.center, strict=True)) < TOL))


def _terms(blocks: list[list[Move]]) -> list[tuple[bool, float]] | None:
    """The Z terms that make every block from the first, or None."""
    first, base = blocks[0], _depth(blocks[0])
    if any(len(b) != len(first) for b in blocks):
        return None
    terms = []
    for j, m in enumerate(first):
        if any(not _same_shape(m, b[j]) for b in blocks) or m.kind not in (RAPID, FEED, ARC):
            return None
        zs = [b[j].end[2] for b in blocks]
        if all(abs(z - zs[0]) < TOL for z in zs):
            terms.append((False, zs[0]))
        elif all(abs((z - _depth(b)) - (zs[0] - base)) < TOL for z, b in zip(zs, blocks, strict=True)):
            terms.append((True, zs[0] - base))
        else:
            return None
    return terms


def fold(moves: list[Move]) -> list[Inline | Repeat]:
    """The moves as inline runs and repeated layers (see the module docstring)."""
    items: list[Inline | Repeat] = []
    blocks = _blocks(moves)
    i = 0
    while i < len(blocks):
        family, block = blocks[i]
        j = i + 1
        while family and j < len(blocks) and blocks[j][0] == family:
            j += 1
        run = [b for _, b in blocks[i:j]]
        start = 0
        while start < len(run):  # the longest foldable stretch from here (layer 1 may differ)
            stop = _longest(run, start)
            extra = len(run[start]) - len(run[start + 1]) if start + 1 < len(run) else 0
            if stop - start < 2 and extra > 0:  # layer 1 begins with moves the others lack
                trimmed = [run[start][extra:], *run[start + 1:]]
                if _longest(trimmed, 0) >= 2:
                    _inline(items, run[start][:extra])
                    run, start = trimmed, 0
                    stop = _longest(run, 0)
            if stop - start >= 2:
                layers = run[start:stop]
                items.append(Repeat(layers[0], _terms(layers), [_depth(b) for b in layers]))
            else:
                stop = start + 1
                _inline(items, run[start])
            start = stop
        i = j
    return items


def _longest(run: list[list[Move]], start: int) -> int:
    """The end of the longest stretch of ``run`` from ``start`` that folds (``start + 1``
    or less: none)."""
    stop = len(run)
    while stop - start >= 2 and _terms(run[start:stop]) is None:
        stop -= 1
    return stop


def _inline(items: list, moves: list[Move]) -> None:
    if items and isinstance(items[-1], Inline):
        items[-1].moves.extend(moves)
    else:
        items.append(Inline(list(moves)))
