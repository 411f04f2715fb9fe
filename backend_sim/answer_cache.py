"""The last command id a receiver carried out and the frames that answered it.

docs/protocol.md: a repeated id (the same as the last) is not executed again; it is
answered with the answers already sent, and an answer still to come is sent when it
comes. ``PING`` and ``STATUS`` are never remembered: they are idempotent and may be
sent while another command is outstanding, so they must not make its retry look new.
"""

from __future__ import annotations

from app.comm.frame import Command, Error, Frame, Info, Ok

UNREMEMBERED = frozenset({"PING", "STATUS"})


class AnswerCache:
    """One remembered id and its answer frames (encoded, in the order sent)."""

    def __init__(self) -> None:
        self.id: int | None = None
        self.frames: list[bytes] = []

    def remembers(self, cmd: Command) -> bool:
        """True if ``cmd`` repeats the remembered id (a retry, not a new command)."""
        return cmd.verb not in UNREMEMBERED and cmd.id == self.id

    def start(self, cmd: Command) -> None:
        """``cmd`` is about to be carried out: remember its id, forget older answers."""
        if cmd.verb not in UNREMEMBERED:
            self.id, self.frames = cmd.id, []

    def record(self, frame: Frame, raw: bytes) -> None:
        """Keep ``raw`` if ``frame`` answers the remembered id."""
        if isinstance(frame, Ok | Error | Info) and frame.id is not None and frame.id == self.id:
            self.frames.append(raw)

    @property
    def answered(self) -> bool:
        return bool(self.frames)
