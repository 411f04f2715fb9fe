"""What a machine can do, as its driver states it (no Qt, no I/O).

A driver (the frame protocol's session, a GRBL session) provides one ``Capabilities``;
the window's state table (``app/ui/state_table.py``) hides or disables every control
whose capability is missing and says why in its tooltip. The defaults are the frame
protocol's student mill, which has all of them.
"""

from __future__ import annotations

from dataclasses import dataclass, fields


@dataclass(frozen=True)
class Capabilities:
    sd_card: bool = True  # files on the machine's card: save, list, delete, run from it
    exact_resume: bool = True  # after a link loss the job goes on from the next line (RESUME FROM)
    crc_link: bool = True  # every frame checked: resends, link-quality figures
    oled_panel: bool = True  # the machine's own screen and buttons
    cover: bool = True  # a cover switch that forbids motion while open
    overrides: bool = True  # feed / spindle overrides while a job runs

    def missing(self) -> tuple[str, ...]:
        """The names of the capabilities this machine lacks."""
        return tuple(f.name for f in fields(self) if not getattr(self, f.name))


FRAME_PROTOCOL = Capabilities()
