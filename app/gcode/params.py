"""The parameter table shared by the expander and the modal interpreter.

Numbered parameters ``#1``..``#5602`` (LinuxCNC's range; the issue's ``#1``..``#5399``
plus the machine's tool and position block) and named globals ``#<_name>`` live here; the
expander keeps each call level's locals (Fanuc ``#1``-``#33``, LinuxCNC ``#<name>``)
in its own frames. The interpreter owns the machine's numbered parameters and keeps
them here as LinuxCNC does (see ``docs/architecture.md``): 5161-5169 G28, 5181-5189
G30, 5210 G92 on, 5211-5219 G92 offsets, 5220 active coordinate system (1-9),
5221-5389 the nine work offsets (X Y Z A B C U V W, 20 apart), 5400 tool number,
5401-5409 tool length offsets, 5410 tool diameter, 5420-5428 current position.

A parameter never set reads as ``None``; what that means (0, an error, Fanuc's
vacant value) is the reader's dialect rule, not this table's.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from app.i18n import msg

FIRST, LAST = 1, 5602  # RS274NGC_MAX_PARAMETERS


class ParamError(ValueError):
    """A parameter number or name that cannot exist."""


def check_number(number: int) -> int:
    """``number`` if it names a numbered parameter, else ``ParamError``."""
    if not FIRST <= number <= LAST:
        raise ParamError(msg("parameter #{number} does not exist (#{first}..#{last})", number=number,
                             first=FIRST, last=LAST))

    return number


@dataclass
class Params:
    """Numbered parameters and named globals; names are stored lower case, without ``<>``."""

    numbered: dict[int, float] = field(default_factory=dict)
    named: dict[str, float] = field(default_factory=dict)

    def get(self, number: int) -> float | None:
        """The value of ``#number``, or ``None`` when it was never set."""
        return self.numbered.get(check_number(number))

    def set(self, number: int, value: float | None) -> None:
        """Set ``#number``; ``None`` makes it unset again (Fanuc's ``#i = #0``)."""
        check_number(number)
        if value is None:
            self.numbered.pop(number, None)
        else:
            self.numbered[number] = float(value)

    def get_named(self, name: str) -> float | None:
        """The value of the global ``#<name>`` (``name`` starts with ``_``), or ``None``."""
        return self.named.get(name.lower())

    def set_named(self, name: str, value: float) -> None:
        self.named[name.lower()] = float(value)

    def copy(self) -> Params:
        return Params(dict(self.numbered), dict(self.named))
