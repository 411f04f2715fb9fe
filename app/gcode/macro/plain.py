"""Long runs of plain lines in an expanded program, read by the fast path, never compiled.

A program that needs the expander is often a long plain program with a few parameter
lines. ``chunks(lines)`` scans the whole file once with the fast path's scanner
(``bulk.scan``) and finds the runs of at least ``CHUNK_MIN`` lines it calls simple
(G0-G3, G20/G21, X Y Z I J F, M3/M5 and S, N numbers and comments: no parameter,
expression, o-word, call, dwell or program end), leaving out ``(ABORT, ..)`` lines,
which stop a walk. The walker runs such a chunk (``run_chunk``) the way the loader
runs a plain file, with the same scan: the ``Runner`` of the fast path, from the
walker's state, with the lines' own numbers, ``PIECE`` lines at a time (at most the
batch's size: the first-move probe reads no further than it asks); the rows are
traced to their frame. A chunk costs the walk one block per line and its rows; a jump
into its middle (a Fanuc ``GOTO`` to one of its ``N`` labels) runs it from there. An
error is reported as in a plain file, and a line refused a second time (a loop) stops
the walk there, as a compiled block refused twice does (``Batch.refused_again``).
"""

from __future__ import annotations

import re

import numpy as np

from app.gcode import bulk
from app.gcode.diagnostics import ERROR
from app.gcode.ops import OpBuffer
from app.gcode.runner import Runner

from .errors import Stopped

CHUNK_MIN = 64  # simple lines in a row worth a chunk (a shorter run compiles, as any line)
PIECE = 1 << 16  # lines of a chunk read at once
_LABEL = re.compile(r"(?m)^[ \t]*[Nn][ \t]*(\d+)")
_ABORT = re.compile(r"(?i)\(\s*abort")


def _line_numbers(text: str, offsets: list[int]) -> list[int]:
    """The 0-based line index of each character offset of ``text``."""
    newlines = np.flatnonzero(np.frombuffer(text.encode("latin-1", "replace"), np.uint8) == 10)
    return np.searchsorted(newlines, np.asarray(offsets, np.int64)).tolist()


def chunks(lines: list[str]) -> tuple[list[tuple[int, int]], bulk.Scan | None]:
    """([start, end) of each chunk of simple lines, in order; the scan of every line
    (None when there is no chunk)."""
    if len(lines) < CHUNK_MIN:
        return [], None
    text = "\n".join(lines)
    aborts = [m.start() for m in _ABORT.finditer(text)]
    aborted = _line_numbers(text, aborts) if aborts else []
    data = (text + "\n").encode("utf-8")
    del text  # (a 1 M-line program: 40 MB less beside the scan)
    scan = bulk.scan(data, len(lines))
    del data
    simple = scan.simple.copy()
    simple[aborted] = False
    edges = np.flatnonzero(np.diff(np.concatenate(([0], simple.view(np.int8), [0]))))
    found = [(int(a), int(b)) for a, b in zip(edges[::2], edges[1::2], strict=True) if b - a >= CHUNK_MIN]
    return (found, scan) if found else ([], None)


def labels(lines: list[str], found: list[tuple[int, int]]) -> dict[int, int]:
    """{line index: N number} of the lines of the chunks ``found`` that start with one
    (Fanuc's ``GOTO`` targets)."""
    said: dict[int, int] = {}
    for start, end in found:
        text = "\n".join(lines[start:end])
        matches = list(_LABEL.finditer(text))
        for i, m in zip(_line_numbers(text, [m.start() for m in matches]), matches, strict=True):
            said[start + i] = int(m.group(1))
    return said


def outside(lines: list[str], found: list[tuple[int, int]]) -> str:
    """The lines outside the chunks ``found``, joined (what can make a program Fanuc's)."""
    parts, start = [], 0
    for a, b in [*found, (len(lines), len(lines))]:
        parts.append("\n".join(lines[start:a]))
        start = b
    return "\n".join(parts)


def run_chunk(w, f, b) -> None:
    """Run the chunk ``b`` from ``f.pc``: one piece of it (see the module docstring)."""
    w._spend()
    w.flush()
    unit, start = f.unit, f.pc
    stop = min(b.end, start + min(PIECE, w.batch_limit))
    report = w.reports[f.file_id]
    said = len(w.report.items)
    piece = OpBuffer()
    runner = Runner(unit.lines, piece, report, w.state)
    runner.i = start
    runner.advance(unit.scan, stop)
    w.state, f.pc = runner.state, runner.i
    w.fast_ok = w.state.fast_path_ok()
    w.blocks_run += runner.i - start
    again = _refused_again(w, f.file_id, said)
    _add_rows(w, f, piece, again or stop + 1)
    if again:
        raise Stopped(again)


def _refused_again(w, file_id: int, said: int) -> int:
    """The first line of the piece refused before (0: none); what was reported from there
    on is taken back (the walk stops there). Lines refused for the first time are noted."""
    items, refused = w.report.items, w.batch.refused
    for k in range(said, len(items)):
        d = items[k]
        if d.severity != ERROR:
            continue
        if (file_id, d.line) in refused:
            del items[k:]
            return d.line
        refused.add((file_id, d.line))
    return 0


def _add_rows(w, f, piece: OpBuffer, before: int) -> None:
    """The rows of a piece made by lines before line ``before`` into the walk's rows,
    traced to frame ``f``."""
    ops = piece.finish()
    keep = ops.line < before
    n = int(keep.sum())
    if not n:
        return
    lines = ops.line[keep]
    trace = w.trace
    trace.file.add(np.full(n, f.file_id, np.int32))
    trace.call_line.add(lines if f is w.frames[0] else np.full(n, w._call_line(f, None), np.int64))
    trace.context.add(np.full(n, w._names[f.name], np.int32))
    trace.iteration.add(np.full(n, f.iteration, np.int32))
    w.ops.messages.extend(ops.messages)  # none: a simple line makes no pause
    kept = [column[keep] for column in (ops.kind, ops.end, ops.center, ops.turn, ops.value)]
    w.ops.add_block(lines, *kept, plane=ops.plane[keep])
    w.check_moves(int(lines[-1]))
