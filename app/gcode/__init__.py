"""The G-code core: lexer, modal interpreter, normaliser, toolpath, CLI. No Qt.

``load(path)`` / ``load_text(text, name)`` -> ``Program`` with ``source_lines``,
``device_lines`` (the machine's dialect), ``line_map`` (device index -> source line),
``errors`` / ``warnings`` / ``diagnostics`` (``Diagnostic(line, column, severity,
message)``), ``pauses``, ``toolpath`` (``Toolpath`` arrays) and ``moves`` (dicts in
the ``cnc-gcode moves`` format). ``normalize_text(text)`` gives the device lines.

The names are imported on first use (PEP 562), so that ``import app.gcode.cli`` can
set up numpy's environment before anything imports numpy.
"""

from importlib import import_module

_HOMES = {
    "Diagnostic": "diagnostics",
    "ARC_CCW": "ops", "ARC_CW": "ops", "DWELL": "ops", "FEED": "ops", "RAPID": "ops",
    "Program": "program", "load": "program", "load_text": "program",
    "Toolpath": "toolpath",
}


def normalize_text(text: str) -> list[str]:
    """Device lines of G-code ``text`` (lines with errors are left out)."""
    from .program import load_text

    return load_text(text).device_lines


def __getattr__(name: str):
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(f"{__name__}.{home}"), name)
    globals()[name] = value  # found once
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *_HOMES])


__all__ = [
    "ARC_CCW", "ARC_CW", "DWELL", "FEED", "RAPID",
    "Diagnostic", "Program", "Toolpath", "load", "load_text", "normalize_text",
]
