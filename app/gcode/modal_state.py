"""M70-M73: save and restore the modal state, as LinuxCNC does.

M70 saves units, plane, distance modes, retract mode, feed, speed, spindle on/off and
the coordinate system; M72 restores them (a spindle change emits its row; a different
coordinate system is selected again); M71 forgets the saved state. M73 saves for an
automatic restore when the subprogram returns: the expander calls
``restore_on_return`` when a call level ends (M99, endsub, return); outside a
subprogram M73 is M70. Restoring with nothing saved is refused.
"""

from __future__ import annotations

from app.i18n import msg

from . import offsets
from .errors import LineError
from .ops import SPINDLE, OpBuffer

_FIELDS = ("inch", "plane", "absolute", "ijk_absolute", "retract_r", "feed", "speed")


def apply(state, kind: str, column: int, line_no: int, ops: OpBuffer) -> None:
    """One of M70 (save), M71 (invalidate), M72 (restore), M73 (autorestore)."""
    if kind in ("save", "autorestore"):
        state.saved = {name: getattr(state, name) for name in _FIELDS}
        state.saved["spindle_on"] = state.spindle_on
        state.saved["system"] = state.offsets.system
        state.saved["auto"] = kind == "autorestore"
    elif kind == "invalidate":
        state.saved = None
    else:
        _restore(state, column, line_no, ops)


def _restore(state, column: int, line_no: int, ops: OpBuffer) -> None:
    saved = state.saved
    if saved is None:
        raise LineError(column, msg("Cannot restore context: no M70 or M73 saved it"))
    if state.comp is not None and (saved["plane"] != state.plane or saved["inch"] != state.inch):
        raise LineError(column, msg("cannot change planes or units with cutter radius compensation on"))
    for name in _FIELDS:
        setattr(state, name, saved[name])
    if saved["spindle_on"] != state.spindle_on:
        state.spindle_on = saved["spindle_on"]
        ops.add(line_no, SPINDLE, state.pos, value=(state.speed or -1.0) if state.spindle_on else 0.0)
    offsets.select_system(state, saved["system"], column)


def restore_on_return(state, line_no: int, ops: OpBuffer) -> bool:
    """A subprogram ends: restore what its M73 saved (True), else change nothing (False).
    ``state`` is changed in place: the expander calls this on the state it will keep."""
    if state.saved is None or not state.saved.get("auto"):
        return False
    _restore(state, 0, line_no, ops)
    state.saved = None
    return True
