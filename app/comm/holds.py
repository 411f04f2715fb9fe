"""Why the machine holds, as the host tells the operator (docs/protocol.md, "Why the
machine holds").

``REASONS`` maps each ``why`` code of the status to its source and its reason in words
(marked for translation; ``app.i18n.localize`` gives the operator's language).
``HoldWatch.update(status, asked)`` reports a hold, stop or alarm once, when its cause
first shows in a status, and once more (``why`` "") when the machine runs again.
"""

from __future__ import annotations

from app.comm.events import HoldEvent, StatusEvent
from app.i18n import N_, msg

REASONS: dict[str, tuple[str, str]] = {
    "HOST": ("host", N_("held by a command from the computer")),
    "PANEL": ("panel", N_("held from the machine's panel")),
    "COVER": ("cover", N_("the cover is open")),
    "LINK": ("link", N_("the machine lost the link to the computer")),
    "UART": ("link", N_("the link between the machine's two boards was lost")),
    "PROG": ("program", N_("program stop (M00, M01 or M06)")),
    "SOFT": ("program", N_("a line past the soft limits was refused")),
    "LINE": ("program", N_("a line was refused")),
    "LIMIT": ("machine", N_("a limit switch was hit")),
    "FAULT": ("machine", N_("a machine fault (following error or homing)")),
}
SOURCE_WORDS = {"host": N_("this computer"), "panel": N_("the machine's panel"), "cover": N_("the cover"),
                "link": N_("the link"), "program": N_("the program"), "machine": N_("the machine")}
"""Each source in words, for the log line of a hold (``source_words``)."""
QUIET_STATES = frozenset({"RUN", "JOG", "HOMING"})


def hold_text(why: str) -> str:
    """The reason of ``why`` in words (the code itself if unknown)."""
    return msg(REASONS[why][1]) if why in REASONS else why


def hold_source(why: str) -> str:
    return REASONS.get(why, ("machine", ""))[0]


def source_words(source: str) -> str:
    """``source`` (``host``, ``panel`` ...) in words (a message)."""
    return msg(SOURCE_WORDS[source]) if source in SOURCE_WORDS else source


class HoldWatch:
    """Reports each hold cause once (``seen``: the last ``(why, state)`` reported)."""

    def __init__(self) -> None:
        self.seen: tuple[str, str] | None = None

    def update(self, status: StatusEvent, asked: bool) -> HoldEvent | None:
        """The event to report for ``status`` (``asked``: this host asked for a hold or
        stop), else None: a new cause, or the machine running again after one."""
        why = status.why if status.state not in QUIET_STATES else ""
        if not why:
            if self.seen is None:
                return None
            self.seen = None
            return HoldEvent("", status.state)
        key = (why, status.state)
        if key == self.seen:
            return None
        self.seen = key
        return HoldEvent(why, status.state, hold_source(why), hold_text(why), asked and why == "HOST")

    def forget(self) -> None:
        """Report the current cause again (after a reconnect)."""
        self.seen = None
