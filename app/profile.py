"""The machine profile: every number of the machine in one range-checked dataclass.

Shared by the G-code core (envelope, feeds, accelerations for time estimates), the
simulator (motors, encoders, PID) and the GUI (settings). Pure stdlib, no Qt.
``load_profile(path)`` reads a TOML or JSON file whose tables override the defaults
(``[axis] lead_mm = 4``); an unknown key or an out-of-range value raises
``ProfileError`` naming the file, the key and the allowed range.
"""

from __future__ import annotations

import json
import math
import tomllib
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from app.i18n import msg

AXES = ("X", "Y", "Z")


class ProfileError(ValueError):
    """A profile file or value that cannot be used; the message names it."""


def _f(default: float, lo: float, hi: float, doc: str = "") -> Any:
    return field(default=default, metadata={"range": (lo, hi), "doc": doc})


@dataclass(frozen=True)
class AxisDrive:
    """One axis: JGA25-370 gear motor on an L298N, encoder, lead screw."""

    supply_v: float = _f(12.0, 5.0, 24.0, "motor supply voltage")
    bridge_drop_v: float = _f(2.0, 0.0, 4.0, "voltage lost in the L298N")
    no_load_rpm: float = _f(130.0, 10.0, 1000.0, "output shaft rpm unloaded at supply_v")
    gear_ratio: float = _f(45.0, 1.0, 500.0, "motor turns per output turn")
    encoder_ppr: int = _f(11, 1, 10000, "pulses per motor turn per channel")
    quadrature: int = _f(4, 1, 4, "edges counted per pulse")
    lead_mm: float = _f(8.0, 0.5, 50.0, "lead screw travel per output turn")

    @property
    def counts_per_rev(self) -> int:
        """Encoder counts per output revolution (1980 by default)."""
        return int(self.encoder_ppr * self.quadrature * self.gear_ratio)

    @property
    def mm_per_count(self) -> float:
        return self.lead_mm / self.counts_per_rev

    @property
    def max_speed_mm_s(self) -> float:
        """Unloaded top speed of the axis (about 17 mm/s by default)."""
        return self.no_load_rpm / 60.0 * self.lead_mm


@dataclass(frozen=True)
class Spindle:
    """RS775 spindle with a 20 pulse/rev encoder."""

    supply_v: float = _f(12.0, 5.0, 48.0)
    no_load_rpm: float = _f(4500.0, 100.0, 30000.0)
    encoder_ppr: int = _f(20, 1, 1000)


@dataclass(frozen=True)
class Travel:
    """Machine-coordinate travel in mm and the default work offset."""

    x_max: float = _f(150.0, 1.0, 2000.0)
    y_max: float = _f(150.0, 1.0, 2000.0)
    z_max: float = _f(30.0, 1.0, 500.0)
    home_backoff_mm: float = _f(10.0, 0.0, 50.0, "back-off from each switch after homing")
    work_x: float = _f(0.0, -2000.0, 2000.0, "default work offset X")
    work_y: float = _f(0.0, -2000.0, 2000.0, "default work offset Y")
    work_z: float = _f(20.0, -500.0, 500.0, "default work offset Z")

    def limits(self) -> tuple[tuple[float, float], ...]:
        """(min, max) machine travel per axis X, Y, Z."""
        return ((0.0, self.x_max), (0.0, self.y_max), (0.0, self.z_max))

    def work_offset(self) -> tuple[float, float, float]:
        return (self.work_x, self.work_y, self.work_z)


@dataclass(frozen=True)
class Motion:
    """Feeds and accelerations used by the planner and the time estimate."""

    rapid_mm_min: float = _f(600.0, 10.0, 20000.0, "G00 feed")
    max_feed_mm_min: float = _f(600.0, 10.0, 20000.0, "cap on programmed feeds")
    accel_mm_s2: float = _f(50.0, 1.0, 10000.0)
    jerk_mm_s3: float = _f(1000.0, 1.0, 1e6)
    junction_deviation_mm: float = _f(0.02, 0.0, 1.0)
    arc_tolerance_mm: float = _f(0.01, 0.0001, 1.0, "chord error when arcs become lines")
    homing_mm_min: float = _f(300.0, 10.0, 5000.0)


@dataclass(frozen=True)
class Pid:
    """Position PID gains (duty per mm, per mm*s, per mm/s) and limits, same for X, Y, Z."""

    kp: float = _f(8.0, 0.0, 1e4)
    ki: float = _f(20.0, 0.0, 1e5)
    kd: float = _f(0.05, 0.0, 1e3)
    rate_hz: float = _f(1000.0, 100.0, 20000.0)
    following_error_mm: float = _f(2.0, 0.05, 100.0)


@dataclass(frozen=True)
class Link:
    """Host link timing (docs/protocol.md)."""

    heartbeat_s: float = _f(1.0, 0.1, 10.0)
    degraded_s: float = _f(2.0, 0.2, 30.0)
    lost_s: float = _f(3.0, 0.3, 60.0)
    baud: int = _f(115200, 1200, 4000000)


@dataclass(frozen=True)
class Job:
    """What the machine does at program stops and after a job (docs/protocol.md)."""

    optional_stop: int = _f(1, 0, 1, "M01 holds the job (1) or is skipped (0)")
    stop_spindle: int = _f(0, 0, 1, "M00/M01 also stop the spindle (1)")
    after_job: int = _f(1, 0, 3, "after the job: 0 stay, 1 lift Z, 2 work zero X0 Y0, 3 home")


@dataclass(frozen=True)
class MachineProfile:
    """All numbers of the machine (DESIGN.md); every field has a checked range."""

    axis: AxisDrive = field(default_factory=AxisDrive)
    spindle: Spindle = field(default_factory=Spindle)
    travel: Travel = field(default_factory=Travel)
    motion: Motion = field(default_factory=Motion)
    pid: Pid = field(default_factory=Pid)
    link: Link = field(default_factory=Link)
    job: Job = field(default_factory=Job)

    def to_dict(self) -> dict[str, dict[str, float]]:
        return {f.name: _section_dict(getattr(self, f.name)) for f in fields(self)}

    def max_spindle_rpm(self) -> float:
        """The speed the spindle reaches at full duty: no-load rpm scaled by the voltage
        the H-bridge leaves (4500 rpm at 12 V less a 2 V drop: 3750 rpm)."""
        sp = self.spindle
        return sp.no_load_rpm * max(0.0, sp.supply_v - self.axis.bridge_drop_v) / sp.supply_v


def _section_dict(section: Any) -> dict[str, float]:
    return {f.name: getattr(section, f.name) for f in fields(section)}


def check_value(section: Any, key: str, value: Any, where: str = "") -> float | int:
    """Return ``value`` converted for ``section.key``, or raise ProfileError with its range."""
    spec = {f.name: f for f in fields(section)}.get(key)
    prefix = f"{where}: " if where else ""
    if spec is None:
        known = ", ".join(sorted(_names(section)))
        raise ProfileError(f"{prefix}unknown setting {key!r}; known: {known}")
    lo, hi = spec.metadata["range"]
    kind = int if isinstance(spec.default, int) and not isinstance(spec.default, bool) else float
    try:
        number = kind(value)
    except (TypeError, ValueError):
        raise ProfileError(msg("{prefix}{key} = {value!r} is not a number", prefix=prefix, key=key,
                               value=value)) from None
    if isinstance(number, float) and not math.isfinite(number) or not lo <= number <= hi:
        raise ProfileError(msg("{prefix}{key} = {value!r} is out of range {lo:g}..{hi:g}", prefix=prefix,
                               key=key, value=value, lo=float(lo), hi=float(hi)))
    return number


def _names(section: Any) -> list[str]:
    return [f.name for f in fields(section)]


def with_overrides(base: MachineProfile, data: dict[str, Any], where: str = "") -> MachineProfile:
    """``base`` with ``{"section": {"key": value}}`` applied, every value range-checked."""
    sections = {f.name: f for f in fields(base)}
    changes = {}
    for name, table in data.items():
        if name not in sections or not isinstance(table, dict):
            raise ProfileError(f"{where}: unknown section {name!r}; known: {', '.join(sections)}")
        section = getattr(base, name)
        values = {k: check_value(section, k, v, f"{where} [{name}]") for k, v in table.items()}
        changes[name] = replace(section, **values)
    return replace(base, **changes)


def load_profile(path: str | Path | None = None) -> MachineProfile:
    """The default profile, overridden by a TOML or JSON file if ``path`` is given."""
    if path is None:
        return MachineProfile()
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
        data = json.loads(text) if path.suffix == ".json" else tomllib.loads(text)
    except (OSError, UnicodeDecodeError) as exc:
        raise ProfileError(f"{path}: cannot read: {exc}") from None
    except (json.JSONDecodeError, tomllib.TOMLDecodeError) as exc:
        kind = "JSON" if path.suffix == ".json" else "TOML"
        raise ProfileError(f"{path}: not valid {kind}: {exc}") from None
    return with_overrides(MachineProfile(), data, str(path))
