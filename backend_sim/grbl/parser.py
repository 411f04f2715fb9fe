"""The simulated GRBL's own G-code block parser (GRBL 1.1's subset, as documented).

``parse_block(text)`` -> ``Block`` or raises ``GrblError(code)`` with GRBL's error
numbers: the line is cleaned as GRBL's pre-parser does (spaces and ``( )`` / ``;``
comments dropped, upper case), read into words, and checked: a value with no letter
(1), a bad number (2), an unsupported command or letter (20), two commands of one
modal group (21), a repeated word (25), a non-integer where one is needed (23).
What the words mean at the machine's state is ``machine``'s part (feed set, axis
words present, targets).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

MAX_LINE = 80  # bytes GRBL's line buffer holds (longer: error 11)

MODAL_G = {  # G number (x10) -> modal group name
    0: "motion", 10: "motion", 20: "motion", 30: "motion", 800: "motion",
    170: "plane", 180: "plane", 190: "plane",
    900: "distance", 910: "distance", 911: "arc_distance",
    930: "feed_mode", 940: "feed_mode",
    200: "units", 210: "units",
    400: "cutter",
    431: "tool_length", 490: "tool_length",
    540: "wcs", 550: "wcs", 560: "wcs", 570: "wcs", 580: "wcs", 590: "wcs",
    40: "non_modal", 100: "non_modal", 530: "non_modal", 920: "non_modal", 921: "non_modal",
}
MODAL_M = {0: "stopping", 1: "stopping", 2: "stopping", 30: "stopping",
           3: "spindle", 4: "spindle", 5: "spindle", 7: "coolant", 8: "coolant", 9: "coolant"}
VALUE_LETTERS = frozenset("FIJKLNPRSTXYZ")
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)")


class GrblError(Exception):
    """A line GRBL refuses: ``code`` is its ``error:N`` number."""

    def __init__(self, code: int) -> None:
        super().__init__(f"error:{code}")
        self.code = code


@dataclass
class Block:
    """One line's words: G and M commands by group, and the value words."""

    g: dict[str, int] = field(default_factory=dict)  # group -> G number x10
    m: dict[str, int] = field(default_factory=dict)
    values: dict[str, float] = field(default_factory=dict)

    @property
    def axes(self) -> dict[str, float]:
        return {k: v for k, v in self.values.items() if k in "XYZ"}


def clean(text: str) -> str:
    """GRBL's pre-parser: no spaces, no comments, upper case."""
    out, depth = [], 0
    for ch in text:
        if ch == "(":
            depth += 1
        elif ch == ")" and depth:
            depth -= 1
        elif ch == ";" and not depth:
            break
        elif not depth and not ch.isspace():
            out.append(ch.upper())
    return "".join(out)


def _words(line: str):
    pos = 0
    while pos < len(line):
        letter = line[pos]
        if not letter.isalpha():
            raise GrblError(1)
        match = _NUMBER.match(line, pos + 1)
        if match is None:
            raise GrblError(2)
        yield letter, float(match[0])
        pos = match.end()


def parse_block(text: str) -> Block:
    """``text`` (one line) as a ``Block``; ``GrblError`` as the module says."""
    block = Block()
    for letter, value in _words(clean(text)):
        if letter == "G":
            _command(block.g, MODAL_G, round(value * 10), value)
        elif letter == "M":
            if value != int(value):
                raise GrblError(20)
            _command(block.m, MODAL_M, int(value), value, scale=1)
        elif letter in VALUE_LETTERS:
            if letter in block.values:
                raise GrblError(25)
            block.values[letter] = value
        else:
            raise GrblError(20)
    return block


def _command(groups: dict, table: dict, code: int, value: float, scale: int = 10) -> None:
    if abs(value * scale - code) > 1e-6:
        raise GrblError(20)
    group = table.get(code)
    if group is None:
        raise GrblError(20)
    if group in groups:
        raise GrblError(21)
    groups[group] = code
