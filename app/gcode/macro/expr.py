"""Expressions and parameter references, compiled once into Python code.

``Reader`` walks a squeezed line (``text.py``) and turns each value it reads into a
Python expression (a string) over the scope ``S`` of the walk: ``S.num(n)`` for
``#n``, ``S.named(name)`` for ``#<name>``, ``S.exists(name)``. ``block.py`` joins a
line's values into one function, compiled once, so running the line again (a loop,
a call) costs one call. ``None`` is Fanuc's vacant value (``#0``, an unset
parameter): arithmetic reads it as 0, ``EQ``/``NE`` tell it from 0.

Precedence as LinuxCNC's rs274ngc, all left-associative: ``**``; ``* / MOD``;
``+ -``; ``EQ NE GT GE LT LE``; ``AND OR XOR``. A unary sign belongs to its operand
(``-2**2`` is 4). Angles are degrees; ``ATAN[a]/[b]`` is atan2 (Fanuc also takes
``ATAN[a]`` and ``ATAN[a,b]``). ``FIX``/``FUP`` are floor/ceiling in LinuxCNC and
toward/away from zero in Fanuc (its manual: ``FIX[-1.2]`` is -1, ``FUP[-1.2]`` -2).
``EQ``/``NE`` allow 1e-4 as rs274ngc does. Errors (division by zero, ``SQRT`` of a
negative, ``ACOS`` out of range ...) name the line and column of the operator or
function, and are raised when the line runs.
"""

from __future__ import annotations

import math

from app.i18n import msg

from . import predefined
from .errors import MacroError
from .text import Squeezed

FANUC_LOCALS, LINUXCNC_LOCALS = 33, 30
MACHINE_PARAMETERS = 5000  # #5000 and up: the interpreter's (read after a sync)
FANUC_SYSTEM = 4000  # Fanuc: #4000 and up are the control's (fanuc_system.py; read after a sync)

EQUAL_TOLERANCE = 1e-4
MAX_DEPTH = 50  # brackets, functions and signs inside each other
PRECEDENCE = {"**": 6, "*": 5, "/": 5, "mod": 5, "+": 4, "-": 4,
              "eq": 3, "ne": 3, "gt": 3, "ge": 3, "lt": 3, "le": 3, "and": 2, "or": 2, "xor": 2}
_DIGITS_DOT = frozenset("0123456789.")
_WORD_OPS = ("mod", "eq", "ne", "gt", "ge", "lt", "le", "and", "or", "xor")


def _z(v):
    return 0.0 if v is None else v


def _eq(a, b) -> float:
    if a is None or b is None:
        return 1.0 if a is b else 0.0
    return 1.0 if abs(a - b) < EQUAL_TOLERANCE else 0.0


def _div(a, b, line, col):
    if b == 0.0:
        raise MacroError(msg("division by zero"), line, col)
    return a / b


def _pow(a, b, line, col):
    if a < 0 and b != int(b):
        raise MacroError(msg("negative number raised to a non-integer power"), line, col)
    try:
        return float(a ** b)
    except (OverflowError, ZeroDivisionError):
        raise MacroError(msg("{a:g} ** {b:g} cannot be computed", a=float(a), b=float(b)), line,
                         col) from None


def _mod(a, b, line, col):
    if b == 0.0:
        raise MacroError(msg("MOD by zero"), line, col)
    r = math.fmod(a, b)
    return r + abs(b) if r < 0 else r


def _checked(name, test, fn, what):
    def apply(x, line, col):
        if not test(x):
            raise MacroError(msg("{name} of {x:g}: {what}", name=name.upper(), x=float(x), what=what), line,
                             col)
        return fn(x)
    return apply


def _round(x, line, col):
    return float(int(x + (-0.5 if x < 0 else 0.5)))


def _index(v, line, col) -> int:
    if v is None:
        raise MacroError(msg("parameter number is vacant"), line, col)
    n = round(v)
    if abs(v - n) > 1e-4:
        raise MacroError(msg("parameter number {v:g} is not a whole number", v=float(v)), line, col)
    return int(n)


def _atan2(y, x):
    return math.degrees(math.atan2(y, x))


def _unset(name, line, col):
    raise MacroError(msg("named parameter #<{name}> is not set", name=name), line, col)


_RANGE = msg("out of the range -1..1")
FUNCTIONS = {
    "sin": lambda x, line, col: math.sin(math.radians(x)),
    "cos": lambda x, line, col: math.cos(math.radians(x)),
    "tan": lambda x, line, col: math.tan(math.radians(x)),
    "asin": _checked("asin", lambda x: -1.0 <= x <= 1.0, lambda x: math.degrees(math.asin(x)), _RANGE),
    "acos": _checked("acos", lambda x: -1.0 <= x <= 1.0, lambda x: math.degrees(math.acos(x)), _RANGE),
    "atan": lambda x, line, col: math.degrees(math.atan(x)),
    "abs": lambda x, line, col: abs(x),
    "sqrt": _checked("sqrt", lambda x: x >= 0.0, math.sqrt, msg("square root of a negative number")),
    "exp": _checked("exp", lambda x: x < 709.0, math.exp, msg("too large")),
    "ln": _checked("ln", lambda x: x > 0.0, math.log, msg("logarithm of zero or a negative number")),
    "round": _round,
    "fix": lambda x, line, col: float(math.floor(x)),
    "fup": lambda x, line, col: float(math.ceil(x)),
    "fix_fanuc": lambda x, line, col: float(math.trunc(x)),
    "fup_fanuc": lambda x, line, col: float(math.copysign(math.ceil(abs(x)), x)),
}
NAMESPACE = {"_z": _z, "_eq": _eq, "_div": _div, "_pow": _pow, "_mod": _mod, "_index": _index,
             "_atan2": _atan2, "_unset": _unset, "inf": math.inf, "nan": math.nan,
             **{f"_f_{k}": v for k, v in FUNCTIONS.items()}}
_NAMES = sorted([*(f for f in FUNCTIONS if not f.endswith("_fanuc")), "exists"], key=len, reverse=True)
_COMPARE = {"gt": ">", "ge": ">=", "lt": "<", "le": "<="}


def compile_codes(codes: list[str]):
    """One function ``fn(S) -> tuple`` computing every code of a line at once (constants
    need no compiling)."""
    values = tuple(constant(c) for c in codes)
    if None not in values:
        return lambda S: values
    return eval("lambda S: (" + "".join(c + ", " for c in codes) + ")", NAMESPACE)  # noqa: S307


def compile_locals(codes: list[str]):
    """``fn(S)`` -> ``{1: value of codes[0], 2: ...}`` (a call's arguments into ``#1``..)."""
    return eval("lambda S: {" + "".join(f"{i}: {c}, " for i, c in enumerate(codes, 1)) + "}", NAMESPACE)  # noqa: S307


def compile_code(code: str):
    """A function ``fn(S) -> value`` computing ``code`` (a constant needs no compiling)."""
    value = constant(code)
    if value is not None:
        return lambda S: value
    return eval("lambda S: " + code, NAMESPACE)  # noqa: S307


def constant(code: str) -> float | None:
    """The value of ``code`` when it is a plain number, else None."""
    try:
        return float(code)
    except ValueError:
        return None


def _fold(code: str) -> str:
    """``code`` computed now when it reads no parameter and cannot fail, else as is."""
    if "S." in code:
        return code
    try:
        return repr(float(eval(code, NAMESPACE)))  # noqa: S307 (our own generated code)
    except (MacroError, ArithmeticError, ValueError, TypeError, NameError):
        return code  # an error is reported when the line runs, as rs274ngc does


class Reader:
    """Reads values from a squeezed line starting at ``pos``; ``fanuc`` picks the dialect."""

    def __init__(self, sq: Squeezed, line_no: int, fanuc: bool, pos: int = 0):
        self.sq, self.text, self.line_no, self.fanuc, self.pos = sq, sq.text, line_no, fanuc, pos
        self.depth = 0

    # --- helpers ---------------------------------------------------------------------
    def error(self, message: str, at: int | None = None) -> MacroError:
        return MacroError(message, self.line_no, self.sq.column(self.pos if at is None else at))

    def peek(self, n: int = 1) -> str:
        return self.text[self.pos:self.pos + n]

    def expect(self, char: str, what: str) -> None:
        if self.peek() != char:
            found = repr(self.peek()) if self.peek() else msg("the end of the line")
            raise self.error(msg("expected '{char}' {what}, found {found}", char=char, what=what,
                                 found=found))
        self.pos += 1

    def at_end(self) -> bool:
        return self.pos >= len(self.text)

    def letters(self) -> str:
        """The run of letters at ``pos`` (not consumed)."""
        end = self.pos
        while end < len(self.text) and self.text[end].isalpha():
            end += 1
        return self.text[self.pos:end]

    def where(self, at: int) -> str:
        """``line, column`` of position ``at``, as code arguments."""
        return f"{self.line_no}, {self.sq.column(at)}"

    def z(self, code: str) -> str:
        """``code`` read as a number: Fanuc's vacant value becomes 0."""
        return f"_z({code})" if self.fanuc and constant(code) is None else code

    # --- values ----------------------------------------------------------------------
    def number(self) -> float:
        start = self.pos
        while self.pos < len(self.text) and self.text[self.pos] in _DIGITS_DOT:  # ASCII: not "²"
            self.pos += 1
        token = self.text[start:self.pos]
        if token.count(".") > 1 or token.strip(".") == "":
            raise self.error(msg("a number was expected here"), start)
        return float(token)

    def value(self) -> str:
        """One real value: ``[expr]``, ``#param``, a function, a signed number or value."""
        self.depth += 1
        try:
            return self._value()
        finally:
            self.depth -= 1

    def _value(self) -> str:
        if self.depth > MAX_DEPTH:
            raise self.error(msg("expression nested more than {depth} deep", depth=MAX_DEPTH))
        c = self.peek()
        if c == "[":
            self.pos += 1
            code = self.expression()
            self.expect("]", msg("to close the expression"))
            return code
        if c == "#":
            return self.parameter()
        if c and c in "+-":
            self.pos += 1
            inner = self.value()
            return inner if c == "+" else _fold(f"(-{self.z(inner)})")
        if c.isalpha():
            return self.function()
        if c.isdigit() or c == ".":
            return repr(self.number())
        raise self.error(msg("a value was expected here") if c
                         else msg("a value was expected at the end of the line"))

    def function(self) -> str:
        start = self.pos
        name = next((f for f in _NAMES if self.text.startswith(f, start)), None)
        if name is None:
            raise self.error(msg("unknown function or word {word!r}", word=self.letters().upper()), start)
        self.pos += len(name)
        if name == "exists":
            return self.exists()
        self.expect("[", msg("after {name}", name=name.upper()))
        arg = self.expression()
        if name == "atan" and self.fanuc and self.peek() == ",":
            self.pos += 1
            return self.atan2(arg, self.expression())
        self.expect("]", msg("to close {name}[", name=name.upper()))
        if name == "atan" and (self.peek() == "/" or not self.fanuc):
            self.expect("/", msg("after ATAN[a] (the form is ATAN[a]/[b])"))
            self.expect("[", msg("after ATAN[a]/ (the form is ATAN[a]/[b])"))
            return self.atan2(arg, self.expression())
        if self.fanuc and name in ("fix", "fup"):
            name += "_fanuc"  # Fanuc: FIX toward zero, FUP away from zero (LinuxCNC: floor, ceil)
        return _fold(f"_f_{name}({self.z(arg)}, {self.where(start)})")

    def atan2(self, y: str, x: str) -> str:
        self.expect("]", msg("to close ATAN"))
        return _fold(f"_atan2({self.z(y)}, {self.z(x)})")

    def exists(self) -> str:
        self.expect("[", msg("after EXISTS"))
        self.expect("#", msg("in EXISTS[#<name>]"))
        self.expect("<", msg("in EXISTS[#<name>]"))
        name = self.name()
        self.expect("]", msg("to close EXISTS["))
        return f"(1.0 if S.exists({name!r}) else 0.0)"

    def name(self) -> str:
        end = self.text.find(">", self.pos)
        if end < 0:
            raise self.error(msg("'#<' name is not closed with '>'"))
        name, self.pos = self.text[self.pos:end], end + 1
        if not name:
            raise self.error(msg("empty parameter name"), end)

        return name

    def parameter(self) -> str:
        """``#n``, ``#[expr]``, ``##n`` or ``#<name>`` as code reading it."""
        at = self.pos
        target = self.target()
        if isinstance(target, str):
            if target == "_line":
                return f"{float(self.line_no)!r}"
            if target in predefined.CONSTANT:
                return repr(predefined.CONSTANT[target])
            if target in predefined.FROM_STATE:
                return f"S.system({target!r})"
            return f"(S.named({target!r}) if S.has({target!r}) else _unset({target!r}, {self.where(at)}))"
        if isinstance(target, int):
            return self.fixed_parameter(target)
        return f"S.num({target})"

    def fixed_parameter(self, n: int) -> str:
        """Code reading ``#n`` for a fixed ``n``: the tables directly (no call), except
        for the machine's parameters (Fanuc: system variables), which ``S.num`` reads
        after a sync."""
        default = "" if self.fanuc else ", 0.0"  # LinuxCNC: unset reads 0; Fanuc: vacant
        if n == 0 and self.fanuc:
            return "None"
        if 0 < n <= (FANUC_LOCALS if self.fanuc else LINUXCNC_LOCALS):
            return f"S.frame.locals.get({n}{default})"
        if 0 < n < (FANUC_SYSTEM if self.fanuc else MACHINE_PARAMETERS):
            return f"S.params.numbered.get({n}{default})"
        return f"S.num({n})"

    def target(self) -> str | int:
        """After ``#``: a name (str), or code giving the number (int when fixed)."""
        at = self.pos
        self.expect("#", "")
        if self.peek() == "<":
            self.pos += 1
            return self.name()
        if self.peek().isdigit():
            return _index(self.number(), self.line_no, self.sq.column(at))
        code = self.value()
        fixed = constant(code)
        if fixed is not None:
            return _index(fixed, self.line_no, self.sq.column(at))
        return f"_index({code}, {self.where(at)})"

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

    def expression(self, min_prec: int = 1) -> str:
        """A binary expression (precedence climbing, left-associative)."""
        left = self.value()
        while True:
            op = self.operator()
            if op is None or PRECEDENCE[op] < min_prec:
                return left
            at = self.pos
            self.pos += len(op)
            right = self.expression(PRECEDENCE[op] + 1)
            left = _fold(self.binary(op, left, right, at))

    def binary(self, op: str, a: str, b: str, at: int) -> str:
        if op in ("eq", "ne"):
            test = f"_eq({a}, {b})" if self.fanuc else f"(1.0 if abs({a} - {b}) < {EQUAL_TOLERANCE} else 0.0)"
            return test if op == "eq" else f"(1.0 - {test})"
        a, b = self.z(a), self.z(b)
        if op in ("+", "-", "*"):
            return f"({a} {op} {b})"
        if op in _COMPARE:
            return f"(1.0 if {a} {_COMPARE[op]} {b} else 0.0)"
        if op == "and":
            return f"(1.0 if {a} != 0.0 and {b} != 0.0 else 0.0)"
        if op == "or":
            return f"(1.0 if {a} != 0.0 or {b} != 0.0 else 0.0)"
        if op == "xor":
            return f"(1.0 if ({a} != 0.0) != ({b} != 0.0) else 0.0)"
        helper = {"/": "_div", "**": "_pow", "mod": "_mod"}[op]
        return f"{helper}({a}, {b}, {self.where(at)})"
