"""Expressions and parameter references, compiled once into closures.

``Reader`` walks a squeezed line (``text.py``) and turns each value it reads into a
function ``fn(env) -> float | None``; evaluating a line again (a loop, a call) only
calls those functions. ``env`` gives ``num(n)`` (``#n``), ``named(name)``
(``#<name>``) and ``exists(name)``. ``None`` is Fanuc's vacant value (``#0``, an
unset parameter); arithmetic reads it as 0, ``EQ``/``NE`` tell it from 0.

Precedence as LinuxCNC's rs274ngc, all left-associative: ``**``; ``* / MOD``;
``+ -``; ``EQ NE GT GE LT LE``; ``AND OR XOR``. A unary sign belongs to its operand
(``-2**2`` is 4). Angles are degrees; ``ATAN[a]/[b]`` is atan2. ``EQ``/``NE`` allow
1e-4 as rs274ngc does. Errors name the line and column of the operator or function.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from .errors import MacroError
from .text import Squeezed

Fn = Callable[[object], "float | None"]
EQUAL_TOLERANCE = 1e-4
PRECEDENCE = {"**": 6, "*": 5, "/": 5, "mod": 5, "+": 4, "-": 4,
              "eq": 3, "ne": 3, "gt": 3, "ge": 3, "lt": 3, "le": 3, "and": 2, "or": 2, "xor": 2}
_WORD_OPS = ("mod", "eq", "ne", "gt", "ge", "lt", "le", "and", "or", "xor")


def _z(v):
    return 0.0 if v is None else v


def _equal(a, b) -> float:
    if a is None or b is None:
        return 1.0 if a is b else 0.0
    return 1.0 if abs(a - b) < EQUAL_TOLERANCE else 0.0


def _divide(a, b, fail):
    if b == 0.0:
        fail("division by zero")
    return a / b


def _power(a, b, fail):
    if a < 0 and b != int(b):
        fail("negative number raised to a non-integer power")
    try:
        return float(a ** b)
    except (OverflowError, ZeroDivisionError):
        fail(f"{a:g} ** {b:g} cannot be computed")


def _mod(a, b, fail):
    if b == 0.0:
        fail("MOD by zero")
    r = math.fmod(a, b)
    return r + abs(b) if r < 0 else r


BINARY = {
    "+": lambda a, b, f: a + b, "-": lambda a, b, f: a - b, "*": lambda a, b, f: a * b,
    "/": _divide, "**": _power, "mod": _mod,
    "gt": lambda a, b, f: float(a > b), "ge": lambda a, b, f: float(a >= b),
    "lt": lambda a, b, f: float(a < b), "le": lambda a, b, f: float(a <= b),
    "and": lambda a, b, f: float(a != 0.0 and b != 0.0), "or": lambda a, b, f: float(a != 0.0 or b != 0.0),
    "xor": lambda a, b, f: float((a != 0.0) != (b != 0.0)),
}


def _checked(name, test, fn, what):
    def apply(x, fail):
        if not test(x):
            fail(f"{name.upper()} of {x:g}: {what}")
        return fn(x)
    return apply


_RANGE = "out of the range -1..1"


def _round(x):
    return float(int(x + (-0.5 if x < 0 else 0.5)))


UNARY = {
    "sin": lambda x, f: math.sin(math.radians(x)), "cos": lambda x, f: math.cos(math.radians(x)),
    "tan": lambda x, f: math.tan(math.radians(x)),
    "asin": _checked("asin", lambda x: -1.0 <= x <= 1.0, lambda x: math.degrees(math.asin(x)), _RANGE),
    "acos": _checked("acos", lambda x: -1.0 <= x <= 1.0, lambda x: math.degrees(math.acos(x)), _RANGE),
    "atan": lambda x, f: math.degrees(math.atan(x)), "abs": lambda x, f: abs(x),
    "sqrt": _checked("sqrt", lambda x: x >= 0.0, math.sqrt, "square root of a negative number"),
    "exp": _checked("exp", lambda x: x < 709.0, math.exp, "too large"),
    "ln": _checked("ln", lambda x: x > 0.0, math.log, "logarithm of zero or a negative number"),
    "round": lambda x, f: _round(x), "fix": lambda x, f: float(math.floor(x)),
    "fup": lambda x, f: float(math.ceil(x)),
}


_FUNCTIONS = sorted([*UNARY, "exists"], key=len, reverse=True)


class Reader:
    """Reads values from a squeezed line starting at ``pos``; ``fanuc`` picks the dialect."""

    def __init__(self, sq: Squeezed, line_no: int, fanuc: bool, pos: int = 0):
        self.sq, self.text, self.line_no, self.fanuc, self.pos = sq, sq.text, line_no, fanuc, pos

    # --- helpers ---------------------------------------------------------------------
    def error(self, message: str, at: int | None = None) -> MacroError:
        return MacroError(message, self.line_no, self.sq.column(self.pos if at is None else at))

    def peek(self, n: int = 1) -> str:
        return self.text[self.pos:self.pos + n]

    def expect(self, char: str, what: str) -> None:
        if self.peek() != char:
            found = repr(self.peek()) if self.peek() else "the end of the line"
            raise self.error(f"expected '{char}' {what}, found {found}")
        self.pos += 1

    def at_end(self) -> bool:
        return self.pos >= len(self.text)

    def letters(self) -> str:
        """The run of letters at ``pos`` (not consumed)."""
        end = self.pos
        while end < len(self.text) and self.text[end].isalpha():
            end += 1
        return self.text[self.pos:end]

    def failer(self, at: int):
        line, col = self.line_no, self.sq.column(at)

        def fail(message: str):
            raise MacroError(message, line, col)
        return fail

    # --- values ----------------------------------------------------------------------
    def number(self) -> float:
        start = self.pos
        while self.pos < len(self.text) and (self.text[self.pos].isdigit() or self.text[self.pos] == "."):
            self.pos += 1
        token = self.text[start:self.pos]
        if token.count(".") > 1 or not any(c.isdigit() for c in token):
            raise self.error("a number was expected here", start)
        return float(token)

    def value(self) -> Fn:
        """One real value: ``[expr]``, ``#param``, a function, a signed number or value."""
        c = self.peek()
        if c == "[":
            self.pos += 1
            fn = self.expression()
            self.expect("]", "to close the expression")
            return fn
        if c == "#":
            return self.parameter()
        if c and c in "+-":
            self.pos += 1
            inner = self.value()
            return inner if c == "+" else _fold1(lambda x: -_z(x), inner)
        if c.isalpha():
            return self.function()
        if c.isdigit() or c == ".":
            v = self.number()
            return _const(v)
        raise self.error("a value was expected here" if c else "a value was expected at the end of the line")

    def function(self) -> Fn:
        start = self.pos
        name = next((f for f in _FUNCTIONS if self.text.startswith(f, start)), None)
        if name is None:
            raise self.error(f"unknown function or word {self.letters().upper()!r}", start)
        self.pos += len(name)
        if name == "exists":
            return self.exists()
        self.expect("[", f"after {name.upper()}")
        arg = self.expression()
        if name == "atan" and self.peek() == ",":
            self.pos += 1
            return self.atan2(arg, self.expression(), "]")
        self.expect("]", f"to close {name.upper()}[")
        if name == "atan" and (self.peek() == "/" or not self.fanuc):
            self.expect("/", "after ATAN[a] (the form is ATAN[a]/[b])")
            self.expect("[", "after ATAN[a]/ (the form is ATAN[a]/[b])")
            return self.atan2(arg, self.expression(), "]")
        op, fail = UNARY[name], self.failer(start)
        return _fold1(lambda x: op(_z(x), fail), arg)

    def atan2(self, y: Fn, x: Fn, close: str) -> Fn:
        self.expect(close, "to close ATAN")
        return _fold2(lambda a, b: math.degrees(math.atan2(_z(a), _z(b))), y, x)

    def exists(self) -> Fn:
        self.expect("[", "after EXISTS")
        self.expect("#", "in EXISTS[#<name>]")
        self.expect("<", "in EXISTS[#<name>]")
        name = self.name()
        self.expect("]", "to close EXISTS[")
        return lambda env: 1.0 if env.exists(name) else 0.0

    def name(self) -> str:
        end = self.text.find(">", self.pos)
        if end < 0:
            raise self.error("'#<' name is not closed with '>'")
        name, self.pos = self.text[self.pos:end], end + 1
        if not name:
            raise self.error("empty parameter name", end)
        return name

    def parameter(self) -> Fn:
        """``#n``, ``#[expr]``, ``##n`` or ``#<name>`` as a reading function."""
        fail = self.failer(self.pos)
        target = self.target()
        if isinstance(target, str):
            def named(env):
                v = env.named(target)
                if v is None:
                    fail(f"named parameter #<{target}> is not set")
                return v
            return named
        if isinstance(target, int):
            return lambda env: env.num(target)
        index = target
        return lambda env: env.num(index(env))

    def target(self):
        """After ``#``: a name (str), a fixed number (int) or a function giving the number."""
        at = self.pos
        self.expect("#", "")
        if self.peek() == "<":
            self.pos += 1
            return self.name()
        if self.peek().isdigit():
            v = self.number()
            return _index(v, self.failer(at))
        fn, fail = self.value(), self.failer(at)
        return lambda env: _index(fn(env), fail)

    # --- binary expressions ----------------------------------------------------------
    def operator(self) -> str | None:
        if self.peek(2) == "**":
            return "**"
        c = self.peek()
        if c and c in "+-*/":
            return c
        for op in _WORD_OPS:
            if self.text.startswith(op, self.pos):
                return op
        return None

    def expression(self, min_prec: int = 1) -> Fn:
        """A binary expression (precedence climbing, left-associative)."""
        left = self.value()
        while True:
            op = self.operator()
            if op is None or PRECEDENCE[op] < min_prec:
                return left
            at = self.pos
            self.pos += len(op)
            right = self.expression(PRECEDENCE[op] + 1)
            left = _binary(op, left, right, self.failer(at))


def _index(v, fail) -> int:
    if v is None:
        fail("parameter number is vacant")
    n = round(v)
    if abs(v - n) > 1e-4:
        fail(f"parameter number {v:g} is not a whole number")
    return int(n)


def _const(v: float) -> Fn:
    fn = lambda env: v  # noqa: E731
    fn.constant = v
    return fn


def _fold1(op, a: Fn) -> Fn:
    if hasattr(a, "constant"):
        try:
            return _const(op(a.constant))
        except MacroError:  # reported when the line runs, as rs274ngc does
            pass
    return lambda env: op(a(env))


def _fold2(op, a: Fn, b: Fn) -> Fn:
    if hasattr(a, "constant") and hasattr(b, "constant"):
        try:
            return _const(op(a.constant, b.constant))
        except MacroError:  # reported when the line runs, as rs274ngc does
            pass
    return lambda env: op(a(env), b(env))


def _binary(op: str, a: Fn, b: Fn, fail) -> Fn:
    if op in ("eq", "ne"):
        flip = op == "ne"
        return _fold2(lambda x, y: _equal(x, y) if not flip else 1.0 - _equal(x, y), a, b)
    f = BINARY[op]
    if op == "+":
        return _fold2(lambda x, y: _z(x) + _z(y), a, b)
    if op == "*":
        return _fold2(lambda x, y: _z(x) * _z(y), a, b)
    return _fold2(lambda x, y: f(_z(x), _z(y), fail), a, b)
