"""The OLED's overrides page (docs/protocol.md, "Overrides"): the panel sets the same
feed, spindle and rapid overrides as the host, as the main MCU's own ``R`` frames.

Contract: ``OverridesPage(main, cnc)``; ``press(button)`` returns False when EXIT leaves
the page. UP/DOWN move between the rows (Feed, Spindle, Rapid, Reset all); OK on a value
row starts editing it: UP/DOWN then step it (feed and spindle by 10 within their range,
rapid through 25/50/100) and send it at once; OK or EXIT ends the edit. OK on "Reset
all" sends 100 for all three. ``lines()`` gives the rows to draw (cursor row marked
with ``oled.INVERT``, the row being edited with ``>``).
"""

from __future__ import annotations

from app.comm.frame import OVERRIDE_RANGES
from backend_sim.oled import INVERT

ROWS = ("FEED", "SPINDLE", "RAPID")
LABELS = {"FEED": "Feed", "SPINDLE": "Spindle", "RAPID": "Rapid"}
STEP = 10


def stepped(verb: str, percent: int, direction: int) -> int:
    """The next value of ``verb``'s override one step up (+1) or down (-1), clamped."""
    allowed = tuple(OVERRIDE_RANGES[verb])
    if verb == "RAPID":
        at = allowed.index(percent) if percent in allowed else len(allowed) - 1
        return allowed[min(max(at + direction, 0), len(allowed) - 1)]
    return min(max(percent + STEP * direction, allowed[0]), allowed[-1])


class OverridesPage:
    def __init__(self, main, cnc) -> None:
        self.main, self.cnc = main, cnc
        self.cursor = 0
        self.editing = False

    def values(self) -> dict[str, int]:
        return dict(zip(ROWS, self.cnc.mc.overrides.as_tuple(), strict=True))

    def press(self, button: str) -> bool:
        if self.editing:
            if button in ("UP", "DOWN"):
                verb = ROWS[self.cursor]
                self._send(verb, stepped(verb, self.values()[verb], 1 if button == "UP" else -1))
            else:
                self.editing = False
            return True
        if button == "EXIT":
            self.cursor = 0
            return False
        if button in ("UP", "DOWN"):
            self.cursor = min(max(self.cursor + (1 if button == "DOWN" else -1), 0), len(ROWS))
        elif self.cursor == len(ROWS):
            for verb in ROWS:
                self._send(verb, 100)
        else:
            self.editing = True
        return True

    def _send(self, verb: str, percent: int) -> None:
        self.main.send_urgent_own(verb, percent=percent)
        self.main.notice = f"{verb} {percent}%"

    def lines(self) -> list[str]:
        values = self.values()
        rows = ["OVERRIDES"]
        for i, verb in enumerate(ROWS):
            mark = ">" if self.editing and i == self.cursor else " "
            rows.append((INVERT if i == self.cursor else "") + f"{mark}{LABELS[verb]:<8}{values[verb]:>4}%")
        rows.append((INVERT if self.cursor == len(ROWS) else "") + " Reset all")
        rows += ["", "OK edit  EXIT back", self.main.notice[:21]]
        return rows
