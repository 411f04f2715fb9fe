"""A line's assignments compiled once into one function (the rules of ``Scope.assign``).

Fanuc: a local ``#1``-``#33`` or a common set to vacant is unset again; LinuxCNC: a
vacant value is 0. Numbers outside ``#1``..``#5602``, names and computed numbers are
left to ``Scope.assign``, which knows their rules and errors.
"""

from __future__ import annotations

from app.gcode.params import LAST

from . import fanuc_system
from .expr import FANUC_LOCALS, LINUXCNC_LOCALS


def compile_stores(assigns: list, fanuc: bool, comment: str = ""):
    """``fn(S, values)`` doing ``S.assign`` for each (target, index of its value) of a
    line, in order: a fixed number is stored straight into its table by the same rules,
    a name or a computed number goes through ``S.assign``. Fanuc: ``#3000`` raises the
    alarm with the line's ``comment``, a read-only system variable is refused."""
    local_max = FANUC_LOCALS if fanuc else LINUXCNC_LOCALS
    lines = ["def store(S, v):"]
    for target, i in assigns:
        if fanuc and target == fanuc_system.ALARM:
            lines.append(f"    raise alarm(v[{i}], {comment!r})")
        elif fanuc and type(target) is int and fanuc_system.read_only(target):
            lines.append(f"    raise refuse_write({target})")
        elif type(target) is int and 0 < target <= LAST:
            table = "S.frame.locals" if target <= local_max else "S.params.numbered"
            if fanuc:
                lines += [f"    if v[{i}] is None: {table}.pop({target}, None)",
                          f"    else: {table}[{target}] = float(v[{i}])"]
            else:
                lines.append(f"    {table}[{target}] = 0.0 if v[{i}] is None else float(v[{i}])")
        else:
            code = f"v[{target[0]}]" if type(target) is tuple else repr(target)
            lines.append(f"    S.assign({code}, v[{i}])")
    namespace: dict = {"alarm": fanuc_system.alarm, "refuse_write": fanuc_system.refuse_write}
    exec("\n".join(lines), namespace)  # noqa: S102
    return namespace["store"]
