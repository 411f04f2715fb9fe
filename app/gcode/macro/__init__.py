"""The expander: parametric programs (Fanuc macro B, LinuxCNC o-words) -> plain blocks.

``needs_expander(raw)`` is the loader's cheap test on a file's bytes: ``#``, ``[``,
an ``O`` word, ``IF``/``WHILE``/``END``, ``M98``/``M99``/``G65`` outside comments.
``expand(lines, name, folder, state, ops, report)`` compiles the program
(``structure.Unit``), walks it (``walker.Walker``) and hands every block left to
``interp.interpret_line``; it returns the ``Trace`` of the rows it added. The
dialect is Fanuc when the program has a bare ``O`` number line, ``IF [``, ``GOTO``,
``WHILE [``, ``DO``/``END`` or ``M98``/``M99``/``G65``; else LinuxCNC. Nothing
here imports Qt.
"""

from __future__ import annotations

import re
from pathlib import Path

from app.gcode.diagnostics import ERROR, Report
from app.gcode.ops import OpBuffer
from app.gcode.params import Params

from .calls import Library
from .structure import Unit
from .walker import Trace, Walker

_COMMENTS = re.compile(rb"\([^()\n]*\)|;[^\n]*")
_NEEDS = re.compile(rb"(?i)[#\[o]|i\s*f|w\s*h\s*i\s*l\s*e|e\s*n\s*d"
                    rb"|m\s*0*\s*9\s*[89](?![\d.])|g\s*0*\s*6\s*5(?![\d.])")
_TRIGGER = re.compile(rb"[#\[oOiIwWeEmMgG]")
_FANUC = re.compile(
    r"(?im)^[ \t]*(?:n[ \t]*\d+[ \t]*)?(?:o[ \t]*\d+[ \t]*(?:\([^\n]*\))?[ \t]*$|if[ \t]*\[|goto"
    r"|while[ \t]*\[|(?:do|end)[ \t]*\d)|m[ \t]*0*9[ \t]*[89](?![\d.])|g[ \t]*0*6[ \t]*5(?![\d.])")


def needs_expander(raw: bytes) -> bool:
    """True when the program uses anything beyond plain words (see the module docstring)."""
    if not _TRIGGER.search(raw):
        return False
    if b"(" in raw or b";" in raw:
        raw = _COMMENTS.sub(b" ", raw)
    return _NEEDS.search(raw) is not None


def is_fanuc(text: str) -> bool:
    """True when ``text`` is written in Fanuc macro B rather than LinuxCNC o-words."""
    return _FANUC.search(re.sub(r"\([^()\n]*\)", "", text)) is not None


def expand(lines, name: str, folder: Path | None, state, ops: OpBuffer, report: Report) -> Trace:
    """Expand the program ``lines`` into ``ops`` (see the module docstring)."""
    fanuc = is_fanuc("\n".join(lines))
    unit = Unit(name, lines, fanuc)
    for exc in unit.errors:
        report.add(exc.line, exc.column, ERROR, exc.message)
    params = getattr(state, "params", None)
    walker = Walker(Library(unit, folder), state, ops, report, params if params is not None else Params())
    if unit.structure_ok:
        walker.run()
    walker.trace.state = walker.state
    return walker.trace
