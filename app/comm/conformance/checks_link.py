"""Checks of "Heartbeat, loss and resume": host lost after 3 s of silence (not
earlier, not later), the link back on the next frame, never a loss while the host
pings every second."""

from __future__ import annotations

from app.comm.conformance.kit import Kit

HEART = "Heartbeat, loss and resume"
LOST_S = 3.0
EARLY_S = 0.1  # the kit's last write lands a little after it is made
LATE_S = 0.4  # the wire, the machine's own polling and the OS's scheduling


def silence(kit: Kit, seconds: float = LOST_S + 1.5, then=None):
    """Send nothing for up to ``seconds``; the ``X HOST_LOST`` that came and when (s after
    the last write). ``then(reply)``: stay silent after the alarm until a reply matches
    (3 s at most), so what the machine does while the host is lost can be seen."""
    link = kit.link
    link.idle(0.2)
    link.heartbeat = False
    kit.expected_losses += 1
    try:
        start, last = len(link.replies), link.last_write
        alarm = link.wait(lambda r: r.kind == "X" and r.fields[0] == "HOST_LOST", seconds, start)
        if alarm is not None and then is not None:
            link.wait(then, 3.0, start)
    finally:
        link.heartbeat = True
    return start, alarm, None if alarm is None else alarm.t - last


def host_lost(kit: Kit) -> None:
    kit.ensure_idle()
    start, alarm, after = silence(kit)
    kit.check(
        "link.host-lost-after-3s",
        HEART,
        "the main MCU treats 3 s without a valid host frame as host lost (`X HOST_LOST`, flag `L`)",
        after is not None and LOST_S - EARLY_S <= after <= LOST_S + LATE_S,
        "nothing for 4.5 s",
        f"{alarm} after {after:.2f} s" if after is not None else kit.got(start),
        f"accepted {LOST_S - EARLY_S:.1f}-{LOST_S + LATE_S:.1f} s as measured at the host",
    )
    status = kit.status_until(lambda st: not st.has("L"))  # a status sent before it may be in flight
    kit.check(
        "link.back-on-next-frame",
        HEART,
        "any valid frame is a sign of life: the status after the host speaks again has no flag `L`",
        status is not None and not status.has("L"),
        "C <id> STATUS",
        str(status),
    )


def no_false_host_lost(kit: Kit) -> None:
    """Run last: the machine reported host lost only where the kit fell silent."""
    lost = [r for r in kit.link.replies if r.problem is None and r.kind == "X" and r.fields[0] == "HOST_LOST"]
    kit.check(
        "link.no-false-host-lost",
        HEART,
        "a host that sends a frame at least every second is never lost",
        len(lost) <= kit.expected_losses,
        "a PING after every 0.5 s without writing, the whole run",
        f"{len(lost)} HOST_LOST for {kit.expected_losses} deliberate silence(s)",
    )


CHECKS = [host_lost]
