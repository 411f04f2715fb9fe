"""GRBL status reports merged into what the layers above read.

``ReportMerger`` keeps the fields GRBL sends only now and then (``WCO``, ``Ov`` with
``A``), converts inches to millimetres when ``$13`` says so, and completes the other
position (``WPos = MPos - WCO``). ``to_status_event`` maps a ``GrblStatus`` onto the
shared ``StatusEvent`` (state names of docs/protocol.md: Idle IDLE, Run RUN, Hold HOLD,
Jog JOG, Home HOMING, Alarm ALARM, Door HOLD with flag C, Check IDLE, Sleep ALARM;
flags ``H`` homed, ``C`` door open, ``P`` spindle on, ``W`` waiting at a program stop).
"""

from __future__ import annotations

from app.comm.events import StatusEvent
from app.comm.grbl.events import GrblStatus
from app.comm.grbl.protocol import Report

INCH = 25.4
STATES = {"Idle": "IDLE", "Run": "RUN", "Hold": "HOLD", "Jog": "JOG", "Home": "HOMING",
          "Alarm": "ALARM", "Door": "HOLD", "Check": "IDLE", "Sleep": "ALARM"}


def _mm(values, scale: float):
    return tuple(float(v) * scale for v in values[:3])


class ReportMerger:
    """See the module docstring."""

    def __init__(self) -> None:
        self.wco = (0.0, 0.0, 0.0)
        self.overrides = (100, 100, 100)
        self.accessories = ""
        self.inches = False

    def reset(self) -> None:
        self.__init__()

    def merge(self, report: Report, now: float) -> GrblStatus:
        scale = INCH if self.inches else 1.0
        if report.wco is not None:
            self.wco = _mm(report.wco, scale)
        if report.overrides is not None:
            self.overrides = report.overrides
            self.accessories = report.accessories or ""
        elif report.accessories is not None:
            self.accessories = report.accessories
        if report.mpos is not None:
            mpos = _mm(report.mpos, scale)
            wpos = tuple(m - o for m, o in zip(mpos, self.wco, strict=True))
        else:
            wpos = _mm(report.wpos or (0.0, 0.0, 0.0), scale)
            mpos = tuple(w + o for w, o in zip(wpos, self.wco, strict=True))
        return GrblStatus(report.state, report.substate, mpos, wpos, self.wco,
                          (report.feed or 0.0) * scale, report.rpm or 0.0, self.overrides,
                          report.pins or "", report.planner_free, report.rx_free,
                          self.accessories, now)


def to_status_event(status: GrblStatus, boot: str, acc: int, done: int, homed: bool,
                    waiting: bool) -> StatusEvent:
    """The shared ``StatusEvent`` of a GRBL report (see the module docstring)."""
    flags = ""
    if homed:
        flags += "H"
    if status.state == "Door" and status.substate != 0:
        flags += "C"
    if "S" in status.accessories or "C" in status.accessories:
        flags += "P"
    if waiting:
        flags += "W"
    x, y, z = status.wpos
    free = status.planner_free if status.planner_free is not None else -1
    return StatusEvent(boot, STATES.get(status.state, status.state.upper()), x, y, z, acc, done,
                       free, int(status.rpm), flags, status.time)
