"""Checks of "Overrides" and of the work coordinate systems ("Machine conventions").

Overrides: each verb answered and shown in the status's `ovr` field, a repeated id
never taken again, the strict grammar (an out-of-range or malformed percentage, a
`why` with a percentage: bad frames, never taken). Work systems: `GET`/`SET` of `WCS`
and a row, the status's work position following the active system, `BAD_ARGS` out of
range, `BUSY` while a job is open. Everything is put back as it was found.
"""

from __future__ import annotations

from app.comm.conformance.checks_jog import send_bad_frames
from app.comm.conformance.kit import Kit

OVR = "Overrides"
CONV = "Machine conventions"


def _ovr(kit: Kit) -> str | None:
    status = kit.link.status()
    return None if status is None else status.ovr


def _ovr_when(kit: Kit, match) -> str | None:
    """The `ovr` of the first status whose `ovr` ``match``es, asked for as long as a
    status may be old ("Machine conventions"), else of the last one. A value that must
    not change is judged this way too: only once a change would have shown."""
    status = kit.status_until(lambda st: match(st.ovr))
    return None if status is None else status.ovr


def answered_and_reported(kit: Kit) -> None:
    """Each verb is answered `O <id> <VERB> <state>` and its value shows in `ovr`."""
    kit.ensure_idle()
    for verb, pct, shown in (
        ("FEED", 150, "150/100/100"),
        ("SPINDLE", 120, "150/120/100"),
        ("RAPID", 25, "150/120/25"),
    ):
        start = len(kit.link.replies)
        cid, answer = kit.link.realtime(f"{verb} {pct}")
        ovr = _ovr_when(kit, lambda ovr, shown=shown: ovr == shown)
        kit.check(
            f"overrides.{verb.lower()}-taken",
            OVR,
            f"`R <id> {verb} <pct>` is answered `O <id> {verb} <state>` and the status's twelfth "
            "field `ovr` (`<feed>/<spindle>/<rapid>`) shows the new value",
            answer is not None and answer.kind == "O" and answer.fields[1] == verb and ovr == shown,
            f"R {cid} {verb} {pct}; C <id> STATUS",
            f"{kit.got(start)} | ovr {ovr}",
        )
    _put_back(kit)


def repeat_not_taken(kit: Kit) -> None:
    """A repeat (same id) with another value is answered again and changes nothing.

    Sent once the first id's copies have all been answered (one the main MCU still
    forwarded made it drop the repeat: a machine that takes repeats passed, 1 run in 3 of
    the suite), and judged on a status known to be newer than the repeat: a fresh id's
    `RAPID 50` follows it, and the first status that shows rapid 50 shows the feed after
    the repeat (no wait for a change that may never come)."""
    kit.ensure_idle()
    cid, _ = kit.link.realtime("FEED 120")
    _settle(kit, cid)
    start = len(kit.link.replies)
    _, again = kit.link.realtime("FEED 180", cid=cid)
    later, _ = kit.link.realtime("RAPID 50")
    ovr = _ovr_when(kit, lambda ovr: ovr is not None and ovr.endswith("/50"))
    kit.check(
        "overrides.repeat-not-taken",
        OVR,
        "absolute, so idempotent: an `R` frame whose id the machine remembers is a repeat, "
        "answered again and not taken",
        again is not None and again.kind == "O" and ovr is not None and ovr.startswith("120/")
        and ovr.endswith("/50"),
        f"R {cid} FEED 120, then R {cid} FEED 180 (same id), then R {later} RAPID 50",
        f"{kit.got(start)} | ovr {ovr}",
    )
    _put_back(kit)


def _settle(kit: Kit, cid: int, quiet: float = 0.2, most: float = 2.0) -> None:
    """Wait until the answers to copies of ``cid`` still on their way have come (none for
    ``quiet`` s, at most ``most``): a repeat sent while the main MCU still forwards one of
    them is dropped there ("Real-time commands") and never reaches the rule it tests."""
    deadline = kit.link.clock() + most
    while kit.link.clock() < deadline:
        start = len(kit.link.replies)
        if kit.link.wait(lambda r: r.kind in "OE" and r.id == cid, quiet, start) is None:
            return


BAD_FRAMES = (
    ("feed-over-range", "FEED 201"),
    ("feed-under-range", "FEED 9"),
    ("feed-leading-zero", "FEED 0150"),
    ("feed-point", "FEED 150.0"),
    ("feed-sign", "FEED +150"),
    ("feed-missing", "FEED"),
    ("feed-fourth-field", "FEED 150 150"),
    ("feed-with-why", "FEED 150 HOST"),
    ("spindle-over-range", "SPINDLE 151"),
    ("spindle-under-range", "SPINDLE 49"),
    ("rapid-not-a-step", "RAPID 75"),
    ("hold-with-pct", "HOLD 50"),
)


def grammar(kit: Kit) -> None:
    """Every malformed override is a bad frame: no answer, the value unchanged."""
    kit.ensure_idle()
    found = _ovr(kit)
    sent = send_bad_frames(kit, BAD_FRAMES)
    ovr = _ovr_when(kit, lambda ovr: ovr != found)
    for name, (cid, text, answer) in sent.items():
        kit.check(
            f"overrides.{name}-dropped",
            OVR,
            "grammar, strict: `pct` is 1-3 digits, no sign, no leading zero, no point, within "
            "the verb's range (`RAPID`: 25, 50 or 100), no fourth field, no `why`; anything else "
            "is a bad frame, never taken",
            answer is None and ovr == found,
            f"R {cid} {text}",
            f"{answer or '(no answer)'}; ovr {found} -> {ovr}",
        )


def _put_back(kit: Kit) -> None:
    for verb in ("FEED", "SPINDLE", "RAPID"):
        kit.link.realtime(f"{verb} 100")


def _get(kit: Kit, name: str) -> str | None:
    _, answer = kit.link.command(f"GET {name}")
    if answer is None or answer.kind != "O":
        return None
    parts = answer.text.split()
    return parts[1] if len(parts) == 2 and parts[0] == name else None


def systems(kit: Kit) -> None:
    """`SET`/`GET` of a row and of `WCS`; the work position follows the active system."""
    link = kit.link
    kit.ensure_idle()
    active, row = _get(kit, "WCS"), _get(kit, "G55_X")
    active_x = _float(_get(kit, f"G{active}_X")) if active is not None else None
    if active is None or row is None:
        kit.skip(
            "systems.get",
            CONV,
            "`GET WCS`, `GET G55_X`",
            "the machine does not know the names (`BAD_PARAM`): a host shows its one work offset",
        )
        return
    kit.check(
        "systems.default",
        CONV,
        "`WCS` is one of `54`-`59`",
        active in {str(n) for n in range(54, 60)},
        "C <id> GET WCS",
        active,
    )
    start = len(link.replies)
    kit.expect_ok("systems.set-row", CONV, "`O <id> SET <name> <value>`", "SET G55_X 12.5")
    kit.check(
        "systems.row-read-back",
        CONV,
        "`GET G55_X` reads what `SET` wrote",
        _float(_get(kit, "G55_X")) == 12.5,
        "SET G55_X 12.5; GET G55_X",
        kit.got(start),
    )
    before = link.status()
    kit.expect_ok("systems.set-active", CONV, "`SET WCS 55` switches the active system", "SET WCS 55")
    expected = None if before is None else float(before.x) + active_x - 12.5
    after = kit.status_until(lambda st: expected is not None and abs(float(st.x) - expected) < 0.002)
    offset = _float(_get(kit, "OFFSET_X"))
    moved = after is not None and expected is not None and abs(float(after.x) - expected) < 0.002
    kit.check(
        "systems.work-position-follows",
        CONV,
        "`SET WCS` switches every work position at once (a status may be a second old); "
        "`OFFSET_X` is the active system's",
        moved and offset == 12.5,
        "SET WCS 55; C <id> STATUS; GET OFFSET_X",
        f"x before {None if before is None else before.x}, after {None if after is None else after.x} "
        f"(expected {expected}); OFFSET_X {offset}",
    )
    kit.expect_error(
        "systems.wcs-out-of-range",
        CONV,
        "`SET WCS` other than `54`-`59` is `BAD_ARGS`",
        "SET WCS 60",
        "BAD_ARGS",
    )
    kit.expect_error(
        "systems.row-out-of-range",
        CONV,
        "a row value with |value| > 100000 is `BAD_ARGS`",
        "SET G56_Y 100001",
        "BAD_ARGS",
    )
    _busy_while_job(kit)
    link.command(f"SET WCS {active}")
    link.command(f"SET G55_X {row}")
    if before is not None:  # the next sections read positions: wait until the status is back
        kit.status_until(lambda st: st.x == before.x)


def _busy_while_job(kit: Kit) -> None:
    kit.check_mode(True)
    kit.link.command("JOB 2")
    kit.expect_error(
        "systems.busy-with-job", CONV, "`SET WCS` is refused `BUSY` while a job is open", "SET WCS 56", "BUSY"
    )
    kit.link.command("STOP")
    kit.check_mode(False)


def _float(text: str | None) -> float:
    try:
        return float(text) if text is not None else float("nan")
    except ValueError:
        return float("nan")


OVERRIDES = [answered_and_reported, repeat_not_taken, grammar]
SYSTEMS = [systems]
