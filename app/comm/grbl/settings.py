"""GRBL's ``$$`` settings as a table, a backup file and a diff.

A backup file is GRBL's own ``$$`` print-out: one ``$n=value`` per line (comments after
``;`` or ``(``, blank lines allowed), so a file saved by another sender reads too.
``read_backup(text, name)`` -> ``{n: value}``, ``ValueError`` naming the file and line of
a bad line, of a setting given twice, or a file with no setting at all;
``write_backup(settings)`` -> text; ``diff_settings(current, wanted)`` ->
``SettingChange`` rows (``old``/``new`` None for a setting only one side has), values
compared as numbers; ``table(settings)`` -> rows of number, value, name, unit, meaning;
``homing_enabled(settings)``: whether the machine homes (``$22`` bit 0).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from app.comm.grbl.codes import setting_info
from app.i18n import msg

_LINE = re.compile(r"^\$(\d+)\s*=\s*([-+]?(?:\d+\.?\d*|\.\d+))\s*$")


def homing_enabled(settings: dict[int, str]) -> bool:
    """Whether the machine has a homing cycle: ``$22`` bit 0 (GRBL's 0/1, grblHAL's mask).
    A machine without one starts unlocked and has nothing to home: its position is the
    one it powered up at. Unknown before ``$$`` is read: assumed to home."""
    try:
        return int(float(settings.get(22, "1"))) & 1 == 1
    except ValueError:
        return True


@dataclass(frozen=True)
class SettingChange:
    number: int
    old: str | None
    new: str | None

    def describe(self) -> str:
        info = setting_info(self.number)
        old = self.old if self.old is not None else "-"
        new = self.new if self.new is not None else "-"
        return msg("${number} ({name}): {old} -> {new}", number=self.number, name=info.name, old=old, new=new)


@dataclass(frozen=True)
class SettingRow:
    number: int
    value: str
    name: str
    unit: str
    meaning: str


def format_value(value) -> str:
    """A setting value as GRBL takes it (ValueError for text or a non-finite number)."""
    number = float(value)
    if not math.isfinite(number):
        raise ValueError(msg("a setting value must be a finite number, not {value}", value=value))
    return str(int(number)) if number == int(number) and abs(number) < 1e9 else f"{number:.3f}"


def read_backup(text: str, name: str = "<backup>") -> dict[int, str]:
    out: dict[int, str] = {}
    where: dict[int, int] = {}
    for n, raw in enumerate(text.splitlines(), 1):
        line = re.split(r"[;(]", raw, maxsplit=1)[0].strip()
        if not line or line == "ok":
            continue
        match = _LINE.match(line)
        if match is None:
            raise ValueError(msg("{name}, line {line}: not a '$n=value' setting: {text}", name=name, line=n,
                                 text=raw.strip()[:60]))
        number = int(match[1])
        if number in where:
            raise ValueError(msg("{name}, line {line}: ${number} is given again (first on line {first})",
                                 name=name, line=n, number=number, first=where[number]))
        out[number], where[number] = match[2], n
    if not out:
        raise ValueError(msg("{name}: no '$n=value' setting in the file", name=name))
    return out


def write_backup(settings: dict[int, str]) -> str:
    return "".join(f"${n}={settings[n]}\n" for n in sorted(settings))


def same_value(a: str, b: str) -> bool:
    """Two setting values alike (as numbers when both are; else as text)."""
    try:
        return math.isclose(float(a), float(b), rel_tol=0, abs_tol=1e-6)
    except ValueError:
        return a == b


def diff_settings(current: dict[int, str], wanted: dict[int, str]) -> list[SettingChange]:
    out = []
    for number in sorted(set(current) | set(wanted)):
        old, new = current.get(number), wanted.get(number)
        if old is None or new is None or not same_value(old, new):
            out.append(SettingChange(number, old, new))
    return out


def table(settings: dict[int, str]) -> list[SettingRow]:
    rows = []
    for number in sorted(settings):
        info = setting_info(number)
        rows.append(SettingRow(number, settings[number], info.name, info.unit, info.meaning))
    return rows
