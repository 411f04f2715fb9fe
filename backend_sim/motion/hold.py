"""Feed hold shared by both interpolators (``Planner`` and ``SimpleInterpolator``).

Contract: ``hold()`` asks the interpolator to stop on the path (how is its own
business, seen through ``holding``); ``resume()`` continues and re-arms the one-shot
"held" report; ``flush()`` drops the queue at rest, keeping the setpoint where it is.
Subclasses provide ``reset_position(position)`` and ``pos``.
"""

from __future__ import annotations


class FeedHold:
    holding: bool = False
    held_flag: bool = True

    def hold(self) -> None:
        self.holding = True

    def resume(self) -> None:
        self.holding = False
        self.held_flag = False

    def flush(self) -> None:
        """Drop every queued move; call at rest (the setpoint stays where it is)."""
        self.reset_position(self.pos)
