"""Long runs of plain lines in an expanded program (``plain.py``) are read by the fast
path, not compiled: a program of any length with a few parameter lines runs (issue 19),
and means what the plain reading and the compiled reading of its lines mean."""

import random

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.macro import plain

from .walks import same_walks


def _moves(n: int, seed: int = 1) -> str:
    rnd = random.Random(seed)
    return "".join(f"G1 X{rnd.uniform(0, 100):.3f} Y{rnd.uniform(0, 100):.3f} Z{-rnd.uniform(0, 2):.3f}\n"
                   for _ in range(n))


def test_a_200000_line_program_with_one_parameter_line_runs_as_its_plain_reading():
    body = "G21 G90\nG0 Z5\nF300\n" + _moves(200_000) + "G0 Z5\nM2\n"
    expanded = load_text("#1 = 2 (the one parameter line)\n" + body)
    plain_reading = load_text("(no parameter)\n" + body)
    assert not expanded.errors and not plain_reading.errors
    assert len(expanded.moves) == len(plain_reading.moves) > 200_000
    a, b = expanded.toolpath, plain_reading.toolpath
    for column in ("start", "end", "kind", "source_line", "feed"):
        if hasattr(a, column):
            assert np.array_equal(getattr(a, column), getattr(b, column)), column
    assert expanded.device_lines == plain_reading.device_lines
    assert expanded.ops.source is not None and set(np.unique(expanded.ops.source.file)) == {0}


def _same(text: str, monkeypatch):
    return same_walks(text, monkeypatch, ((plain, "CHUNK_MIN", 10**9),), work=False)


MOVES = _moves(100)
ARCS = "".join(f"G2 X{k % 2} Y0 I0.5 J0\n" for k in range(80))
PROGRAMS = {
    "a loop around a chunk": "#1 = 0\nG21 F200\no1 while [#1 LT 3]\n" + MOVES
                             + "#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "a chunk in a subroutine": "o<s> sub\n" + MOVES
                               + "o<s> endsub\nG21 F200\no<s> call\n#1 = 1\no<s> call\nM2\n",
    "arcs in G18 and G17": "#1 = 1\nG21 F100\nG18\n" + ARCS + "G17\n" + ARCS + "M2\n",
    "M2 inside a chunk": "#1 = 1\nG21 F100\n" + MOVES + "M2\n" + MOVES + "\n\n",
    "comments and an ABORT": "#1 = 1\nG21 F100\n" + MOVES.replace("\n", " (c) ; d\n") + "(ABORT, stop here)\n"
                             + MOVES + "M2\n",
    "an error in a chunk": "#1 = 1\nG21 F100\n" + MOVES + "G1 X1 Y1 Z1 G0\n" + MOVES + "M2\n",
    "an error in a chunk in a loop": "#1 = 0\nG21 F200\no1 while [#1 LT 3]\n" + MOVES + "G1 X1 G0\n"
                                     + MOVES + "#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "a bad arc in a chunk in a loop": "#1 = 0\nG21 F200\no1 while [#1 LT 3]\n" + MOVES
                                      + "G2 X10 Y0 I0.001 J0\n" + MOVES + "#1 = [#1 + 1]\no1 endwhile\nM2\n",
    "no feed in a chunk in a loop": "#1 = 0\nG21\no1 while [#1 LT 3]\n" + MOVES + "F100\n#1 = [#1 + 1]\n"
                                    "o1 endwhile\nM2\n",
    "Fanuc GOTO into a chunk": "O1\nG21 F100\n#1 = 0\nGOTO 50\n" + MOVES + "N50 G1 X7 Y7\n" + MOVES
                               + "#1 = #1 + 1\nIF [#1 LT 2] GOTO 50\nM30\n",
    "Fanuc dwell and calls stay compiled": "O1\nG21 F100\n#1 = 1\n" + MOVES + "G04 X1.5\nG4 P500\nM98 P2\n"
                                           + MOVES + "M30\nO2\n" + MOVES + "M99\n",
}


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_chunk_means_what_its_compiled_lines_mean(name, monkeypatch):
    _same(PROGRAMS[name], monkeypatch)


def test_chunks_are_found_where_simple_lines_run_long():
    lines = ["#1 = 1"] + ["G1 X1"] * 70 + ["G1 X#1"] + ["G1 X2"] * 10 + ["(ABORT, x)"] + ["G1 Y1 (c)"] * 64
    found, scan = plain.chunks(lines)
    assert found == [(1, 71), (83, 147)] and len(scan.simple) == len(lines)
    calls = ["M98 P12", "G65 P9 X1", "M 9 9", "G04 X1", "M2"] + ["N5 G1 X1"] * 64
    found, _ = plain.chunks(calls)
    assert found == [(5, 69)] and plain.labels(calls, found)[5] == 5
    assert plain.outside(calls, found) == "\n".join(calls[:5]) + "\n"
    assert plain.chunks(["G1 X1"] * 63) == ([], None)


def test_a_load_scans_the_plain_runs_once_for_the_walk_and_the_first_move_probe(monkeypatch):
    """The first-move probe expands the program again from another origin: it reuses the
    walk's scan (a 1 M-line program's took half a second and 75 MB, twice)."""
    import app.gcode.macro as macro

    calls, real = [], plain.chunks
    monkeypatch.setattr(macro, "plain_runs", lambda lines: calls.append(len(lines)) or real(lines))
    from app.gcode.macro import structure

    monkeypatch.setattr(structure, "chunks", lambda lines: pytest.fail("a Unit scanned the plain runs again"))
    program = load_text("#1 = 2\nG21 G90 F300\nG0 X1 Y1\nG1 Z-1\n" + MOVES + "M2\n")
    assert not program.errors and len(program.moves) > 100
    assert calls == [len(program.lines)]
    assert program.start is not None


def test_an_expansion_frees_its_walk_as_it_returns():
    """Without the cyclic collector (reference counting alone), the walker, its frames
    and the units' scan are gone once ``expand`` returns: they held 75 MB of a 1 M-line
    program through the rest of the load."""
    import gc
    import weakref

    import app.gcode.macro as macro
    from app.gcode.diagnostics import Report
    from app.gcode.ops import OpBuffer
    from app.gcode.state import State

    lines = ("#1 = 2\nG21 F300\n" + MOVES + "M2\n").splitlines()
    chunked = macro.plain_runs(lines)
    scan = weakref.ref(chunked[1].simple)
    was = gc.isenabled()
    gc.disable()
    try:
        trace = macro.expand(lines, "t", None, State(), OpBuffer(), Report(), chunked=chunked)
        del chunked
        assert scan() is None
    finally:
        if was:
            gc.enable()
    assert trace.state.ended
