"""The G-code core: lexer, modal interpreter, normaliser, toolpath, CLI. No Qt.

``load(path)`` / ``load_text(text, name)`` -> ``Program`` with ``source_lines``,
``device_lines`` (the machine's dialect), ``line_map`` (device index -> source line),
``errors`` / ``warnings`` / ``diagnostics`` (``Diagnostic(line, column, severity,
message)``), ``pauses``, ``toolpath`` (``Toolpath`` arrays) and ``moves`` (dicts in
the ``cnc-gcode moves`` format). ``normalize_text(text)`` gives the device lines.
"""

from .diagnostics import Diagnostic
from .ops import ARC_CCW, ARC_CW, DWELL, FEED, RAPID
from .program import Program, load, load_text
from .toolpath import Toolpath


def normalize_text(text: str) -> list[str]:
    """Device lines of G-code ``text`` (lines with errors are left out)."""
    return load_text(text).device_lines


__all__ = [
    "ARC_CCW", "ARC_CW", "DWELL", "FEED", "RAPID",
    "Diagnostic", "Program", "Toolpath", "load", "load_text", "normalize_text",
]
