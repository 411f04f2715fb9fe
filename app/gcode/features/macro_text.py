"""What the parametric writers (``round_macro.py``, ``face_macro.py``) share: calls and
loops in the two Fanuc dialects, and the loop over a feature's layers.

- ``fanuc31``: ``WHILE [...] DO m`` / ``END m`` loops, ``G65 P<n> Z<depth>`` calls (the
  depth arrives in the subprogram as ``#26``);
- ``fanuc21``: ``IF [...] GOTO`` loops on ``N`` labels, ``M98 P<n>`` calls, the depth in
  the common ``#101`` (no WHILE, no G65: the paper's table 1).

The layer loop counts ``#102`` from 1 and computes the depth ``#101`` as
``top - span·#102/count`` (the levels of ``Cutting.layers``), never by adding a rounded
step.
"""

from __future__ import annotations

from dataclasses import dataclass

from .plain import num

DEPTH, LAYER = "#101", "#102"


@dataclass(frozen=True)
class Levels:
    """Layers ``top - span·k/count`` for k = 1..count, each from the one above."""

    span: float
    count: int

    def depth(self, k: int, top: float) -> float:
        return top - self.span * k / self.count


def levels_of(cut, bottom: float) -> Levels:
    """The levels of ``cut.layers(bottom)`` as a span and a count."""
    levels = cut.layers(bottom)
    return Levels(cut.top - levels[-1], len(levels))


class MacroText:
    """Calls and loops of one dialect (see the module docstring)."""

    def __init__(self, dialect: str, top: float) -> None:
        self.f31 = dialect == "fanuc31"
        self.top = top
        self.depth = "#26" if self.f31 else DEPTH  # the layer's depth inside a subprogram

    def call(self, number: int, depth: str | None = None) -> list[str]:
        """Call ``O<number>`` (at ``depth``: an expression or ``#101``)."""
        if self.f31:
            return [f"G65 P{number}" + (f" Z{depth}" if depth else "")]
        return ([f"{DEPTH} = {depth}"] if depth and depth != DEPTH else []) + [f"M98 P{number}"]

    def loop(self, var: str, first: str, test: str, stop: str, body: list[str], do: int,
             label: int) -> list[str]:
        """``body`` with ``var`` from ``first`` while ``var test stop`` (``LE``/``LT``), by
        one; ``do`` (Fanuc 31) and ``label``, ``label + 1`` (Fanuc 21) name the loop."""
        if self.f31:
            return [f"{var} = {first}", f"WHILE [{var} {test} {stop}] DO {do}", *body,
                    f"{var} = [{var} + 1]", f"END {do}"]
        negated = {"LE": "GT", "LT": "GE"}[test]
        return [f"{var} = {first}", f"N{label} IF [{var} {negated} {stop}] GOTO {label + 1}", *body,
                f"{var} = [{var} + 1]", f"GOTO {label}", f"N{label + 1} {var} = 0"]

    def layers(self, levels: Levels, number: int, label: int, after: list[str] = ()) -> list[str]:
        """The loop over ``levels`` calling ``O<number>`` at each depth, then ``after``."""
        body = [f"{DEPTH} = [{num(self.top)} - {num(levels.span)}*{LAYER}/{levels.count}]",
                *self.call(number, DEPTH), *after]
        return self.loop(LAYER, "1", "LE", str(levels.count), body, 1, label)
