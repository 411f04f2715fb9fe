"""The program summary as text: lines, moves, bounds, lengths, estimated time."""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QCoreApplication, QObject

from app.ui.numbers import decimal, fill, integer


def format_duration(seconds: float) -> str:
    seconds = max(0, int(round(seconds)))
    hours, rest = divmod(seconds, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes}:{secs:02d}"


def bounds_array(bounds) -> np.ndarray | None:
    """Toolpath bounds as a (2, 3) array [[xmin, ymin, zmin], [xmax, ymax, zmax]]."""
    if bounds is None:
        return None
    arr = np.asarray(bounds, dtype=float)
    if arr.shape == (3, 2):
        arr = arr.T
    return arr.reshape(2, 3) if arr.size == 6 else None


def device_count(program) -> int:
    """Number of device lines, without rendering them: the program's ``device_count``
    (the plan's total), else one per entry of its ``line_map``."""
    count = getattr(program, "device_count", None)
    return int(count) if count is not None else len(program.line_map)


class Summary(QObject):
    """The translation context of the summary (``self.tr`` lets lupdate see the plurals)."""

    def counts(self, lines: int, device: int, moves: int) -> tuple[str, str, str]:
        return (self.tr("%n line(s)", "", lines), self.tr("%n machine line(s)", "", device),
                self.tr("%n move(s)", "", moves))

    def problems(self, errors: int, warnings: int) -> tuple[str, str]:
        return self.tr("%n error(s)", "", errors), self.tr("%n warning(s)", "", warnings)


def describe(program, name: str = "") -> str:
    tp = program.toolpath
    errors, warnings = program.errors, program.warnings
    parts = [f"<b>{name}</b>" if name else ""]
    texts = Summary()
    lines, device, moves = texts.counts(len(program.lines), device_count(program), len(tp.start))
    parts.append(fill(QCoreApplication.translate("Summary", "%1 → %2, %3"), lines, device, moves))
    box = bounds_array(getattr(tp, "bounds", None))
    if box is not None and len(tp.start):
        (x0, y0, z0), (x1, y1, z1) = (map(lambda v: decimal(v, 2), row) for row in box)
        parts.append(f"X {x0} … {x1}, Y {y0} … {y1}, Z {z0} … {z1} mm")
    cut = integer(round(getattr(tp, "cut_length", 0.0)))
    rapid = integer(round(getattr(tp, "rapid_length", 0.0)))
    estimated = format_duration(getattr(tp, "estimated_time", 0.0))
    parts.append(fill(QCoreApplication.translate("Summary", "cut %1 mm, rapid %2 mm, estimated %3"),
                      cut, rapid, estimated))
    stops = _stops(getattr(program, "planned_if_ready", None))
    if stops:
        parts.append(stops)
    errors_said, warnings_said = texts.problems(len(errors), len(warnings))
    status = fill(QCoreApplication.translate("Summary", "%1, %2"), errors_said, warnings_said)
    colour = "#e05050" if errors else ("#c8a000" if warnings else "#39a353")
    parts.append(f"<span style='color:{colour}'>{status}</span>")
    return "<br>".join(p for p in parts if p)


def _stops(planned) -> str:
    """The program stops the estimate leaves out (M00, M01, M06), once the planner has run."""
    if planned is None or not planned.stops:
        return ""
    said = QCoreApplication.translate("Summary", "program stops: %1 (tool changes: %2), not in the "
                                      "estimate: %3 of machine moves, plus the operator's wait")
    return fill(said, integer(planned.stops), integer(planned.tool_changes),
                format_duration(planned.stop_seconds))
