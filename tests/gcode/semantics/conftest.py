"""Helpers for the semantics tests: load text with a tool table, read rows."""

from __future__ import annotations

import pytest

from app.gcode import load_text
from app.gcode.tools import Tool

TOOLS = {1: Tool(1, 6.0, 0.0), 2: Tool(2, 4.0, 12.5), 3: Tool(3, 10.0, -3.0)}


@pytest.fixture
def run():
    """``run(text)`` -> Program loaded with ``TOOLS``."""

    def _run(text: str, tools=None):
        return load_text(text, tools=TOOLS if tools is None else tools)

    return _run


def ends(program) -> list[list[float]]:
    """End point of every move, rounded to 4 places."""
    return [[round(v, 4) for v in m["end"]] for m in program.moves if "end" in m]
