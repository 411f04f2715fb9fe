"""The program summary as text: lines, moves, bounds, lengths, estimated time."""

from __future__ import annotations

import numpy as np


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
    """Number of device lines, without rendering them (``line_map`` has one entry each)."""
    return len(program.line_map)


def describe(program, name: str = "") -> str:
    tp = program.toolpath
    errors, warnings = program.errors, program.warnings
    parts = [f"<b>{name}</b>" if name else ""]
    parts.append(
        f"{len(program.lines):,} lines → {device_count(program):,} machine lines, "
        f"{len(tp.start):,} moves"
    )
    box = bounds_array(getattr(tp, "bounds", None))
    if box is not None and len(tp.start):
        (x0, y0, z0), (x1, y1, z1) = box
        parts.append(f"X {x0:.2f} … {x1:.2f}, Y {y0:.2f} … {y1:.2f}, Z {z0:.2f} … {z1:.2f} mm")
    parts.append(
        f"cut {getattr(tp, 'cut_length', 0.0):,.0f} mm, rapid {getattr(tp, 'rapid_length', 0.0):,.0f} mm, "
        f"estimated {format_duration(getattr(tp, 'estimated_time', 0.0))}"
    )
    status = f"{len(errors)} errors, {len(warnings)} warnings"
    colour = "#e05050" if errors else ("#c8a000" if warnings else "#39a353")
    parts.append(f"<span style='color:{colour}'>{status}</span>")
    return "<br>".join(p for p in parts if p)
