"""GRBL status reports merged into what the layers above read.

``ReportMerger`` keeps the fields GRBL sends only now and then (``WCO``, ``Ov`` with
``A``), converts inches to millimetres when ``$13`` says so, and completes the other
position (``WPos = MPos - WCO``). ``to_status_event`` maps a ``GrblStatus`` onto the
shared ``StatusEvent`` (state names of docs/protocol.md: Idle IDLE, Run RUN, Hold HOLD,
Jog JOG, Home HOMING, Alarm ALARM, Door HOLD with flag C, Check IDLE, Sleep ALARM;
flags ``H`` homed, ``C`` door open, ``P`` spindle on, ``W`` waiting at a program stop;
``why`` GRBL's hold with its substate, ``Hold:0``..``Door:3``, for ``codes.hold_text``).

Overrides asked for (``expect``) count as the machine's until a report shows them, or
until the second report after the asking carries ``Ov:`` (the first may have been made
before the bytes were read): ``overrides_now()``, what the next step is counted from, so
a slider moved twice between two reports does not step twice from the same value.
"""

from __future__ import annotations

from app.comm.events import HoldEvent, StatusEvent
from app.comm.grbl.codes import hold_text
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
        self.merged = 0  # reports merged since the last reset
        self._expected: dict[int, tuple[int, int]] = {}  # Ov index -> (percent, merged when asked)

    def reset(self) -> None:
        self.__init__()

    def expect(self, index: int, percent: int) -> None:
        """Override ``index`` (0 feed, 1 rapid, 2 spindle: GRBL's ``Ov`` order) was asked to
        become ``percent``."""
        self._expected[index] = (percent, self.merged)

    def overrides_now(self) -> tuple[int, int, int]:
        """The overrides as they are once what was asked for has been read (see the module)."""
        return tuple(self._expected[k][0] if k in self._expected else v for k, v in enumerate(self.overrides))

    def _reported_overrides(self, values) -> None:
        self.overrides = tuple(values)
        for index, (percent, asked_at) in list(self._expected.items()):
            if values[index] == percent or self.merged > asked_at + 1:
                del self._expected[index]

    def merge(self, report: Report, now: float) -> GrblStatus:
        scale = INCH if self.inches else 1.0
        self.merged += 1
        if report.wco is not None:
            self.wco = _mm(report.wco, scale)
        if report.overrides is not None:
            self._reported_overrides(report.overrides)
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
    feed, rapid, spindle = status.overrides  # GRBL's Ov order; the event's is feed, spindle, rapid
    why = f"{status.state}:{status.substate or 0}" if status.state in ("Hold", "Door") else ""
    return StatusEvent(boot, STATES.get(status.state, status.state.upper()), x, y, z, acc, done,
                       free, int(status.rpm), flags, status.time, why, overrides=(feed, spindle, rapid))


def hold_event(status: StatusEvent) -> HoldEvent:
    """A status's hold in words (``why`` ``Hold:0``..``Door:3``, the door's source the
    cover), as the frame protocol's sessions report holds; ``why`` "": running again."""
    if not status.why:
        return HoldEvent("", status.state)
    source = "cover" if status.why.startswith("Door") else "machine"
    return HoldEvent(status.why, status.state, source, hold_text(status.why))
