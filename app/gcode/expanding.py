"""The expander's side of a load: a program that needs parameters, control flow or calls.

``program._interpret`` comes here when ``sniff`` (or the fast path's scan, on the way)
finds that a program is not plain. ``interpret`` expands the lines before ``stop``
(``macro.expand``), its rows traced to their source (``ops.Source``), and probes where
the job starts (``start.probe``): the rows read from the origin are the whole program's
own, so only the shifted reading is made again, and only as far as the probe asks.
The plain-run scan of the lines (``macro.plain_runs``, 75 MB for a 1 M-line program) is
made once for both and freed before the rest of the load. ``macro`` is imported here
only when called: a plain load never imports it.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from .diagnostics import Report
from .ops import CappedBuffer, Enough, OpBuffer, Ops, Source
from .source import Lines
from .start import StartInfo, probe
from .state import State

StateAt = Callable[[tuple], State]  # origin (work mm) -> the interpreter's state before line 1


def interpret(lines: Lines, name: str, folder: Path | None, stop: int, state_at: StateAt,
              origin: tuple) -> tuple[Ops, int, StartInfo, Report]:
    """The lines before index ``stop`` expanded from ``origin``: (ops, line of M2/M30 or 0,
    where the job starts, report). ``state_at(origin)`` gives a fresh start state."""
    from . import macro

    report = Report()
    chunked = macro.plain_runs(lines.as_list()[:stop])  # scanned once for the walk and the probe
    ops, ended = _expanded(lines, name, folder, state_at(origin), report, stop, chunked)
    shifted = reader(lines, name, folder, stop, state_at, chunked)

    def read(at, limit: int) -> tuple[Ops, bool]:
        return (ops, True) if np.array_equal(at, origin) else shifted(at, limit)

    where = probe(read, origin)
    return ops, ended, where, report


def _expanded(lines: Lines, name: str, folder: Path | None, start: State, report: Report,
              stop: int, chunked: tuple) -> tuple[Ops, int]:
    """(ops, line of M2/M30 or 0) of the lines before index ``stop``, rows traced to their
    source; ``chunked``: ``macro.plain_runs`` of those lines."""
    from . import macro

    buffer = OpBuffer()
    trace = macro.expand(lines.as_list()[:stop], name, folder, start, buffer, report, chunked=chunked)
    ops = buffer.finish()
    ops.source = Source(trace.file.array(np.int32), trace.call_line.array(np.int64),
                        trace.context.array(np.int32), trace.iteration.array(np.int32),
                        trace.files, trace.names)
    return ops, trace.state.ended


def reader(lines: Lines, name: str, folder: Path | None, stop: int, state_at: StateAt, chunked: tuple):
    """``start.Reader`` of an expanded program: expanded from a given origin until it has
    made the rows asked for (the flag: it ran to its end)."""

    def read(origin, limit: int) -> tuple[Ops, bool]:
        from . import macro

        buffer = CappedBuffer(cap=limit)
        try:
            macro.expand(lines.as_list()[:stop], name, folder, state_at(origin), buffer, Report(),
                         rows_wanted=limit, chunked=chunked)
        except Enough:
            return buffer.finish(), False
        return buffer.finish(), True

    return read
