"""Call frames and the parameter rules of each dialect.

A ``Frame`` is one level of the walk: the unit it runs, the next block, its locals
(Fanuc ``#1``-``#33``, LinuxCNC ``#1``-``#30`` and ``#<name>``), its loop counters
and what its caller needs back. ``Scope`` reads and writes parameters for the
innermost frame with the dialect's rule for unset ones: LinuxCNC reads an unset
numbered parameter as 0 and refuses an unset named one; Fanuc reads ``#0`` and any
unset parameter as vacant (``None``).
"""

from __future__ import annotations

from app.gcode.params import LAST, ParamError, Params
from app.i18n import msg

from . import fanuc_system, predefined
from .errors import MacroError
from .expr import FANUC_LOCALS, FANUC_SYSTEM, LINUXCNC_LOCALS, MACHINE_PARAMETERS
from .structure import Unit

DEPTH_LIMIT = 64  # call levels below the main program (the walker refuses deeper calls)


class Frame:
    """One call level (see the module docstring)."""

    __slots__ = ("unit", "pc", "locals", "named", "program", "name", "file_id", "calls_left",
                 "counts", "repeat_left", "iteration", "caller_line", "wid")

    def __init__(self, unit: Unit, pc: int, locals_: dict, name: str, file_id: int,
                 program: int = 0, calls_left: int = 1, caller_line: int = 0):
        self.unit, self.pc, self.locals, self.name, self.file_id = unit, pc, locals_, name, file_id
        self.named: dict[str, float] = {}
        self.program, self.calls_left, self.caller_line = program, calls_left, caller_line
        self.counts: dict[int, int] = {}  # loop head -> times it was jumped back to
        self.repeat_left: dict[int, int] = {}
        self.iteration = 0
        self.wid = 0  # the batch's id of where its rows come from: set by the walker


class Scope:
    """Parameter access for the innermost frame (the ``env`` of ``expr.py``)."""

    def __init__(self, params: Params, fanuc: bool):
        self.params, self.fanuc = params, fanuc
        self.local_max = FANUC_LOCALS if fanuc else LINUXCNC_LOCALS
        self.frame: Frame | None = None
        self.sync = None  # called before reading a machine parameter (#5000 and up)
        self.synced_from = FANUC_SYSTEM if fanuc else MACHINE_PARAMETERS

    def num(self, n: int):
        if n >= self.synced_from and self.sync is not None:
            self.sync()  # the interpreter's rows so far must be in before it is read
        if n <= self.local_max and n > 0:
            v = self.frame.locals.get(n)
        elif n == 0 and self.fanuc:
            return None
        elif 0 < n <= LAST:
            v = self.params.numbered.get(n)
        else:
            try:
                v = self.params.get(n)
            except ParamError as exc:
                raise MacroError(exc.args[0]) from None
        if v is None and not self.fanuc:
            return 0.0
        return v

    def system(self, name: str) -> float:
        """A predefined parameter (``#<_x>`` ...): the interpreter's state, after a sync."""
        if self.sync is not None:
            self.sync()
        return self.params.named.get(name, 0.0)

    def named(self, name: str) -> float | None:
        """The value of ``#<name>``, ``None`` when unset (the reader refuses it)."""
        return self.params.get_named(name) if name[0] == "_" else self.frame.named.get(name)

    def has(self, name: str) -> bool:
        """True when ``#<name>`` is set."""
        return name in (self.params.named if name[0] == "_" else self.frame.named)

    def exists(self, name: str) -> bool:
        table = self.params.named if name[0] == "_" else self.frame.named
        return name in table

    def assign(self, target, value) -> None:
        """Set ``#target`` (a number or a name) to ``value`` (``None``: vacant)."""
        if isinstance(target, str):
            if target in predefined.READ_ONLY or target.startswith("_ini["):
                raise predefined.refuse_write(target)
            if value is None:
                value = 0.0
            if target[0] == "_":
                self.params.set_named(target, value)
            else:
                self.frame.named[target] = float(value)
            return
        if not self.fanuc and value is None:
            value = 0.0
        if 0 < target <= self.local_max:
            if value is None:
                self.frame.locals.pop(target, None)
            else:
                self.frame.locals[target] = float(value)
            return
        if self.fanuc and target == fanuc_system.ALARM:
            raise fanuc_system.alarm(value, "")
        if self.fanuc and fanuc_system.read_only(target):
            raise fanuc_system.refuse_write(target)
        if target == 0:
            raise MacroError(msg("#0 cannot be set (it is always vacant)") if self.fanuc
                             else msg("#0 does not exist"))
        try:
            self.params.set(target, value)
        except ParamError as exc:
            raise MacroError(exc.args[0]) from None

