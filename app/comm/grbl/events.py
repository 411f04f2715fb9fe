"""Events only a GRBL machine has, beside the shared ones of ``app.comm.events``.

``GrblListener`` adds ``on_grbl_status`` (every report, merged with the sticky fields
GRBL sends only now and then: WCO, overrides, accessories), ``on_machine_info`` (welcome
and ``$I``) and ``on_settings`` (a complete ``$$`` table) to ``SessionListener``.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.comm.listener import SessionListener

Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class GrblStatus:
    """A status report in millimetres with both positions (``WPos = MPos - WCO``)."""

    state: str
    substate: int | None
    mpos: Vec3
    wpos: Vec3
    wco: Vec3
    feed: float
    rpm: float
    overrides: tuple[int, int, int]
    pins: str
    planner_free: int | None
    rx_free: int | None
    accessories: str
    time: float = 0.0

    @property
    def door_open(self) -> bool:
        return self.state == "Door" and self.substate in (1, 2)


@dataclass(frozen=True)
class MachineInfo:
    """What the machine said about itself: ``flavour`` "grbl" or "grblhal", the welcome's
    ``version``, ``$I``'s ``build`` and ``options`` text, the receive buffer and planner
    sizes in use by the host."""

    flavour: str
    version: str
    build: str = ""
    options: str = ""
    rx_size: int = 128
    planner_blocks: int | None = None


@dataclass(frozen=True)
class SettingsEvent:
    """The ``$$`` table as ``(number, value text)`` pairs in the machine's order."""

    values: tuple[tuple[int, str], ...]

    def as_dict(self) -> dict[int, str]:
        return dict(self.values)


class GrblListener(SessionListener):
    """``SessionListener`` plus what only GRBL reports; every method is a no-op here."""

    def on_grbl_status(self, event: GrblStatus) -> None: ...

    def on_machine_info(self, event: MachineInfo) -> None: ...

    def on_settings(self, event: SettingsEvent) -> None: ...
