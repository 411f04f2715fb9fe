"""The expander: parametric programs (Fanuc macro B, LinuxCNC o-words) -> plain blocks.

``needs_expander(raw)`` (``app/gcode/sniff.py``, so that a plain program's load does not
import the expander) is the loader's cheap test on a file's bytes.
``expand(lines, name, folder, state, ops, report)`` compiles the program
(``structure.Unit``), walks it (``walker.Walker``) and hands every block left to
``interp.interpret_line``; it returns the ``Trace`` of the rows it added. The
dialect is Fanuc when the program has a bare ``O`` number line, ``IF [``, ``GOTO``,
``WHILE [``, ``DO``/``END`` or ``M98``/``M99``/``G65``; else LinuxCNC
(``structure.is_fanuc``; long runs of simple lines, read by the fast path, are not
looked at: ``plain.py``). Nothing here imports Qt.

The walk runs with Python's cyclic garbage collector paused (``_no_cycle_collection``):
it makes millions of small tuples, dicts and frames and no reference cycles (but the
walker's own, broken at the end), and the collector's passes over the growing batch cost
a quarter of the time.
"""

from __future__ import annotations

import contextlib
import gc
from pathlib import Path

from app.gcode.diagnostics import ERROR, Report
from app.gcode.ops import OpBuffer
from app.gcode.params import Params

from . import structure
from .calls import Library
from .plain import chunks as plain_runs  # noqa: F401  (the package's interface: see expand)
from .structure import Unit, is_fanuc  # noqa: F401  (is_fanuc: the package's interface)
from .walker import Trace, Walker


@contextlib.contextmanager
def _no_cycle_collection():
    """Pause the cyclic garbage collector (reference counting still frees everything),
    and start it again after, if it was running."""
    running = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if running:
            gc.enable()


def expand(lines, name: str, folder: Path | None, state, ops: OpBuffer, report: Report,
           rows_wanted: int | None = None, chunked: tuple | None = None) -> Trace:
    """Expand the program ``lines`` into ``ops`` (see the module docstring). ``rows_wanted``:
    the caller stops the walk once it has that many rows (the first-move probe,
    ``start.py``), so plain moves are interpreted in batches no larger: the walk does not
    run ahead of what is wanted. ``chunked``: ``plain_runs(lines)``, for a caller that
    expands the same lines more than once (the fast path's scan of a 1 M-line program
    takes half a second and 75 MB)."""
    unit = Unit(name, lines, None, getattr(state, "block_delete", False), structure.MAX_LINES, chunked)
    state.fanuc = unit.fanuc  # offset registers (G10 L12, D) exist without a tool table
    for exc in unit.errors:
        report.add(exc.line, exc.column, ERROR, exc.message)
    params = getattr(state, "params", None)
    walker = Walker(Library(unit, folder), state, ops, report, params if params is not None else Params())
    if rows_wanted is not None:
        walker.batch_limit = max(1, min(walker.batch_limit, rows_wanted))
    try:
        if unit.structure_ok:
            with _no_cycle_collection():
                walker.run()
        walker.trace.state = walker.state
        return walker.trace
    finally:  # the walker's one cycle (its scope calls back into it) broken: its frames, units and
        walker.scope.sync = None  # their scan (75 MB for 1 M lines) go now, not at the collector's next pass
