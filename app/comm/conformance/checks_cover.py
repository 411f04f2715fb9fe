"""Checks of "The cover interlock". The wire has no verb that opens the cover: the
kit opens it through the port when the port can (``sim://``: the simulator's panel),
else it reports the rules as not checkable from the wire (check them by hand)."""

from __future__ import annotations

from app.comm.conformance.kit import Kit

COVER = "The cover interlock"
REFUSED = ["HOME", "JOG X 1 100", "SPINDLE 1000", "JOB 1", "RESUME"]
AS_USUAL = ["GET OPTSTOP", "SET OPTSTOP 1", "SD LIST", "SPINDLE OFF", "PAUSE", "STOP"]


def cover(kit: Kit) -> None:
    if kit.cover is None:
        kit.skip(
            "cover.interlock",
            COVER,
            "no motion and no spindle while the cover is open (flag `C`, "
            "`X COVER_OPEN`); `HOME`, `JOG`, `SPINDLE <rpm>`, `JOB`, `RESUME` refused `E <id> COVER_OPEN`",
            "the wire has no command to open the cover: open it by hand and send those verbs, or run the "
            "kit against sim:// (it opens the simulator's cover)",
        )
        return
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(False)
    start = len(link.replies)
    kit.cover(True)
    try:
        alarm = link.wait(lambda r: r.kind == "X" and r.fields[0] == "COVER_OPEN", 2.0, start)
        status = kit.status_until(lambda st: st.has("C"))
        kit.check(
            "cover.open-alarm-and-flag",
            COVER,
            "opening the cover: `X COVER_OPEN`, flag `C`",
            alarm is not None and status is not None and status.has("C"),
            "(cover opened)",
            kit.got(start, statuses=True),
        )
        for text in REFUSED:
            kit.expect_error(
                f"cover.refuses-{text.split()[0].lower()}",
                COVER,
                f"while open, `{text.split()[0]}` is answered `E <id> COVER_OPEN` at once",
                text,
                "COVER_OPEN",
                timeout=2.0,
            )
        for text in AS_USUAL:
            kit.expect_ok(
                f"cover.allows-{'-'.join(text.split()[:2]).lower()}",
                COVER,
                f"while open, `{text}` is answered as usual",
                text,
                timeout=5.0,
            )
    finally:
        kit.cover(False)
    status = kit.status_until(lambda st: not st.has("C"))
    kit.check(
        "cover.close-restarts-nothing",
        COVER,
        "closing it restarts nothing (flag `C` gone, state as before)",
        status is not None and not status.has("C") and status.state == "IDLE",
        "(cover closed), C <id> STATUS",
        str(status),
    )


CHECKS = [cover]
