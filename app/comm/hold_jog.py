"""Hold-to-jog on the host (docs/protocol.md, "Continuous jog (hold-to-jog)").

``HoldToJog(ids)`` turns the jog keys the operator holds into keep-alives: ``hold(keys,
feed)`` says which keys are held now (``()``: none; ``"X+"``, ``"Y-"``... as
``directions`` combines them), ``due(now)`` gives the ``R <id> JOG <dirs> <feed>``
frames to write now (two copies of a new id every ``KEEP_ALIVE_S``, an older one never
again), ``on_answer(frame)`` takes the answers of those ids: a refusal other than
``BUSY`` (soft limit, cover, alarm) ends the keep-alives until the keys change.
``cancel()`` ends them at once (stop, hold, lost link). The caller sends ``R JOGEND``
(repeated until answered) when ``hold`` says the keys were released.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterable

from app.comm.frame import Error, Ok, RealtimeCommand

KEEP_ALIVE_S = 0.025
COPIES = 2
AXES = "XYZ"
MAX_AXES = 2
KEEP_GOING = frozenset({"BUSY"})  # a refusal that the next keep-alive may overcome
REMEMBERED = 64  # ids of recent keep-alives whose answers are ours


def directions(keys: Iterable[str]) -> str:
    """The ``dirs`` of the held ``keys`` (``"X+"``, ``"Y-"``...): opposite keys of one
    axis cancel out, axes in X, Y, Z order, at most two (``"X+Y-"``); "" for none."""
    held = set(keys)
    out = ""
    for axis in AXES:
        plus, minus = f"{axis}+" in held, f"{axis}-" in held
        if plus != minus and len(out) < 2 * MAX_AXES:
            out += f"{axis}{'+' if plus else '-'}"
    return out


def plain_feed(value: float) -> str:
    """A feed in the protocol's number grammar (mm/min, to 0.1, at least 0.1)."""
    text = f"{max(value, 0.1):.1f}".rstrip("0").rstrip(".")
    return text


class HoldToJog:
    """The keep-alives of a continuous jog while keys are held (module docstring)."""

    def __init__(self, ids: Callable[[], int]) -> None:
        self.ids = ids
        self.dirs = ""
        self.feed = 0.0
        self.refused: Error | None = None  # the refusal that ended the keep-alives
        self._last: float | None = None
        self._sent: deque[int] = deque(maxlen=REMEMBERED)

    @property
    def jogging(self) -> bool:
        """True while keep-alives go out."""
        return bool(self.dirs) and self.refused is None

    def hold(self, keys: Iterable[str], feed: float) -> bool:
        """The keys held now at ``feed`` mm/min; True if this released a jog (send JOGEND)."""
        dirs = directions(keys)
        released = self.jogging and not dirs
        if dirs != self.dirs:
            self.refused, self._last = None, None
        self.dirs, self.feed = dirs, feed
        return released

    def due(self, now: float) -> list[RealtimeCommand]:
        """The keep-alive frames to write at ``now`` (none while nothing is held)."""
        if not self.jogging or (self._last is not None and now - self._last < KEEP_ALIVE_S - 1e-9):
            return []
        self._last = now
        frame = RealtimeCommand(self.ids(), "JOG", "", args=(self.dirs, plain_feed(self.feed)))
        self._sent.append(frame.id)
        return [frame] * COPIES

    def on_answer(self, frame: Ok | Error) -> bool:
        """True if ``frame`` answers one of our keep-alives (then it is handled here)."""
        if frame.id not in self._sent:
            return False
        if isinstance(frame, Error) and frame.code not in KEEP_GOING and self.jogging:
            self.refused = frame
        return True

    def cancel(self) -> bool:
        """Stop the keep-alives now; True if a jog was going on."""
        was = self.jogging
        self.dirs, self._last = "", None
        return was
