"""Checks of the real-time commands (docs/protocol.md, "Real-time commands")."""

from __future__ import annotations

from app.comm.conformance.kit import Kit


def realtime(kit: Kit) -> None:
    kit.skip(
        "realtime.commands",
        "Real-time commands",
        "hold, resume, stop and reset act at once and no corruption can forge one",
        "not implemented by this kit yet",
    )


CHECKS = [realtime]
