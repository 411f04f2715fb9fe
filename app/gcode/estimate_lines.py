"""The device lines the time estimate reads, known without rendering the program.

Contract: ``EventLines(ops, plan)`` is a read-only sequence as long as the program's
device lines whose items are the machine's text of every dwell, spindle, stop and end
line (``G04 P..``, ``M03 S..``/``M05``, ``M00``/``M01``/``M06 T..``, ``M02``) and ""
for the lines of moves, which the estimate takes from the toolpath. Rendering a million
lines takes a second or more; ``cnc-gcode check`` need not wait for it.
"""

from __future__ import annotations

import numpy as np

from .ops import DWELL, END, PAUSE, SPINDLE
from .stops import device_line


class EventLines:
    def __init__(self, ops, plan) -> None:
        rows = np.flatnonzero(np.isin(ops.kind, (DWELL, SPINDLE, END, PAUSE)) & (plan.count > 0))
        kinds, values = ops.kind[rows].tolist(), ops.value[rows].tolist()
        self.total = int(plan.total)
        self.text = {int(first): _text(kind, value)
                     for first, kind, value in zip(plan.first[rows].tolist(), kinds, values, strict=True)}

    def __len__(self) -> int:
        return self.total

    def __getitem__(self, index: int) -> str:
        if not -self.total <= index < self.total:
            raise IndexError(index)
        return self.text.get(index % self.total, "")


def _text(kind: int, value: float) -> str:
    if kind == DWELL:
        return f"G04 P{value:g}"
    if kind == SPINDLE:
        return f"M03 S{value:g}" if value > 0 else "M05"
    if kind == PAUSE:
        return device_line(value)
    return "M02"
