"""The machine profile: every number of the machine in one range-checked dataclass.

Shared by the G-code core (envelope, feeds, accelerations for time estimates), the
simulator (motors, encoders, PID) and the GUI (settings). Pure stdlib, no Qt.
``load_profile(path)`` reads a TOML or JSON file whose tables override the defaults
(``[axis] lead_mm = 4``); an unknown key or a bad value raises ``ProfileError``
naming the file, the key and the rule. ``read_profile(path)`` never raises: each bad
value is named and its default used (the window and the simulator start anyway).
"""

from __future__ import annotations

import math
import re
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


DECIMAL = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)")


def check_value(section: Any, key: str, value: Any, where: str = "", text: bool = False) -> float | int:
    """``value`` for ``section.key``, or ProfileError naming the key and the rule broken.

    A file's values must be numbers (not text, not true/false, finite, whole for an
    integer field, in range); with ``text`` (a dialog's field) a string is read with
    the strict grammar ``DECIMAL`` (no ``1_0``, ``1e3``, ``inf``)."""
    spec = {f.name: f for f in fields(section)}.get(key)
    prefix = f"{where}: " if where else ""
    if spec is None:
        known = ", ".join(sorted(_names(section)))
        raise ProfileError(msg("{prefix}unknown setting {key!r}; known: {known}", prefix=prefix, key=key,
                               known=known))
    lo, hi = spec.metadata["range"]
    whole = isinstance(spec.default, int) and not isinstance(spec.default, bool)
    said = {"prefix": prefix, "key": key, "value": value}
    number = _number(value, text, said)
    if not math.isfinite(number):
        raise ProfileError(msg("{prefix}{key} = {value!r} is not a finite number", **said))
    if whole and not float(number).is_integer():
        raise ProfileError(msg("{prefix}{key} = {value!r} must be a whole number", **said))
    if not lo <= number <= hi:
        raise ProfileError(msg("{prefix}{key} = {value!r} is out of range {lo:g}..{hi:g}", lo=float(lo),
                               hi=float(hi), **said))
    return int(number) if whole else float(number)


def _number(value: Any, text: bool, said: dict) -> float | int:
    if isinstance(value, bool):
        raise ProfileError(msg("{prefix}{key} = {value!r} is true/false, not a number", **said))
    if isinstance(value, int | float):
        return value
    if isinstance(value, str):
        if text and DECIMAL.fullmatch(value):
            return float(value)
        if not text:
            raise ProfileError(msg("{prefix}{key} = {value!r} is not a number (text in quotes)", **said))
    raise ProfileError(msg("{prefix}{key} = {value!r} is not a number", **said))


def consistency_problems(profile: MachineProfile, where: str = "") -> list[str]:
    """Rules between fields: the link timers must satisfy heartbeat < degraded < lost."""
    link = profile.link
    if link.heartbeat_s < link.degraded_s < link.lost_s:
        return []
    prefix = f"{where} [link]: " if where else "[link]: "
    return [msg("{prefix}heartbeat_s ({heartbeat:g}) < degraded_s ({degraded:g}) < lost_s ({lost:g}) "
                "must hold", prefix=prefix, heartbeat=link.heartbeat_s, degraded=link.degraded_s,
                lost=link.lost_s)]


def _names(section: Any) -> list[str]:
    return [f.name for f in fields(section)]


@dataclass(frozen=True)
class ProfileRead:
    """A profile read leniently: every bad value replaced by its default, and why."""

    profile: MachineProfile
    problems: tuple[str, ...] = ()


def with_overrides(base: MachineProfile, data: dict[str, Any], where: str = "") -> MachineProfile:
    """``base`` with ``{"section": {"key": value}}`` applied; ProfileError on the first
    bad value (``read_overrides`` keeps going)."""
    read = read_overrides(base, data, where)
    if read.problems:
        raise ProfileError(read.problems[0])
    return read.profile


def read_overrides(base: MachineProfile, data: Any, where: str = "") -> ProfileRead:
    """``base`` with every good value of ``data`` applied; each bad one named (file,
    key, rule) and left at its value in ``base``; timers that contradict each other
    are all left at ``base``'s."""
    if not isinstance(data, dict):
        return ProfileRead(base, (msg("{where}: not a table of sections (found {kind})", where=where,
                                      kind=type(data).__name__),))
    sections = {f.name: f for f in fields(base)}
    problems, changes = [], {}
    for name, table in data.items():
        if name not in sections or not isinstance(table, dict):
            known = ", ".join(sections)
            problems.append(msg("{where}: unknown section {name!r}; known: {known}", where=where, name=name,
                                known=known) if name not in sections else
                            msg("{where}: not a table: {name!r}; known: {known}", where=where, name=name,
                                known=known))
            continue
        section, values = getattr(base, name), {}
        for key, value in table.items():
            try:
                values[key] = check_value(section, key, value, f"{where} [{name}]")
            except ProfileError as exc:
                problems.append(msg("{problem}; default {default!r} used", problem=exc.args[0],
                                    default=getattr(section, key, None))
                                if key in _names(section) else exc.args[0])
        changes[name] = replace(section, **values)
    profile = replace(base, **changes)
    rules = consistency_problems(profile, where)
    if rules:
        problems += [msg("{problem}; defaults used", problem=r) for r in rules]
        profile = replace(profile, link=base.link)
    return ProfileRead(profile, tuple(problems))


def parse_file(path: Path, text: str) -> Any:
    """The JSON (``.json``) or TOML data of ``text``; ProfileError if it cannot be read
    (nested deeper than ``reading.MAX_JSON_DEPTH`` included: never the parser's recursion)."""
    import json  # here: a load that reads no profile file (``cnc-gcode check``) never needs them
    import tomllib

    from app.gcode.reading import nesting_problem

    kind = "JSON" if path.suffix == ".json" else "TOML"
    deep = nesting_problem(text)
    if deep:
        raise ProfileError(msg("{path}: not valid {kind}: {error}", path=str(path), kind=kind, error=deep))
    try:
        return json.loads(text) if kind == "JSON" else tomllib.loads(text)
    except (json.JSONDecodeError, tomllib.TOMLDecodeError) as exc:
        raise ProfileError(msg("{path}: not valid {kind}: {error}", path=str(path), kind=kind,
                               error=str(exc))) from None
    except RecursionError:
        raise ProfileError(msg("{path}: not valid {kind}: nested too deeply", path=str(path),
                               kind=kind)) from None


def read_profile(path: str | Path) -> ProfileRead:
    """The default profile with the good values of a TOML or JSON file; never raises."""
    from app.gcode.reading import SourceError, read_config

    path = Path(path)
    try:
        data = parse_file(path, read_config(path))
    except SourceError as exc:
        return ProfileRead(MachineProfile(), (exc.args[0],))
    except OSError as exc:
        problem = msg("{path}: cannot read: {error}", path=str(path), error=str(exc))
        return ProfileRead(MachineProfile(), (problem,))
    except ProfileError as exc:
        return ProfileRead(MachineProfile(), (exc.args[0],))
    return read_overrides(MachineProfile(), data, str(path))


def load_profile(path: str | Path | None = None) -> MachineProfile:
    """The default profile, overridden by a TOML or JSON file if ``path`` is given;
    ProfileError naming the first problem (``read_profile`` is the lenient reader)."""
    if path is None:
        return MachineProfile()
    read = read_profile(path)
    if read.problems:
        raise ProfileError(read.problems[0])
    return read.profile
