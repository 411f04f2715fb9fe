"""Checks of the verbs and their answers ("Host -> machine", "Machine conventions")
that need no homing: STATUS, SET/GET of every name, PAUSE/RESUME/STOP at rest, a
repeated id, RESET and its new boot id, NOT_HOMED after it."""

from __future__ import annotations

import re

from app.comm.conformance.kit import Kit

HOST = "Host -> machine"
CONV = "Machine conventions"
NUMBER = re.compile(r"-?[0-9]+(\.[0-9]+)?")
SETTINGS = {"OPTSTOP": ("0", "1"), "STOPSPINDLE": ("1", "0"), "AFTERJOB": ("3", "1")}


def status(kit: Kit) -> None:
    link = kit.link
    start = len(link.replies)
    link.send_command("STATUS")
    reply = link.wait(lambda r: r.kind == "S", 3.0, start)
    kit.check(
        "commands.status",
        HOST,
        "`STATUS` is answered with `S`",
        reply is not None,
        "C <id> STATUS",
        kit.got(start, statuses=True),
    )


def set_get(kit: Kit) -> None:
    """Each SET name answers `O <id> SET <name> <value>` and GET reads it back."""
    kit.ensure_idle()
    for name, (value, default) in SETTINGS.items():
        kit.expect_ok(
            f"commands.set-{name.lower()}",
            CONV,
            f"`SET {name} {value}` -> `O <id> SET {name} {value}`",
            f"SET {name} {value}",
            lambda info, n=name, v=value: info == f"{n} {v}",
        )
        kit.expect_ok(
            f"commands.get-{name.lower()}",
            CONV,
            f"`GET {name}` -> `O <id> GET {name} {value}`",
            f"GET {name}",
            lambda info, n=name, v=value: _same(info, n, v),
        )
        kit.link.command(f"SET {name} {default}")
    for name in ("FERR", "OFFSET_X", "OFFSET_Y", "OFFSET_Z", "KP_X", "KI_Y", "KD_Z", "CHECK"):
        kit.expect_ok(
            f"commands.get-{name.lower()}",
            CONV,
            f"`GET {name}` -> `O <id> GET {name} <number>`",
            f"GET {name}",
            lambda info, n=name: _number_of(info, n) is not None,
        )
    _, answer = kit.link.command("GET FERR")
    ferr = _number_of(answer.text, "FERR") if answer is not None and answer.kind == "O" else None
    if ferr is not None:
        kit.expect_ok(
            "commands.set-ferr",
            CONV,
            "`SET FERR 2.5` -> `O <id> SET FERR 2.5`",
            "SET FERR 2.5",
            lambda info: info == "FERR 2.5",
        )
        kit.link.command(f"SET FERR {ferr}")


def _number_of(info: str, name: str) -> str | None:
    parts = info.split()
    if len(parts) == 2 and parts[0] == name and NUMBER.fullmatch(parts[1]):
        return parts[1]
    return None


def _same(info: str, name: str, value: str) -> bool:
    number = _number_of(info, name)
    return number is not None and float(number) == float(value)


def at_rest(kit: Kit) -> None:
    """PAUSE, RESUME and STOP with nothing moving are answered at once."""
    kit.ensure_idle()
    kit.expect_ok(
        "commands.pause-at-rest",
        CONV,
        "`O <id> PAUSE` at once, with the state as info, if nothing was moving",
        "PAUSE",
        lambda info: info in ("IDLE", "ALARM", "HOLD"),
        timeout=2.0,
    )
    kit.expect_ok(
        "commands.resume-at-rest", CONV, "`O <id> RESUME` (nothing to resume)", "RESUME", timeout=2.0
    )
    kit.expect_ok("commands.stop-at-rest", CONV, "`O <id> STOP` once stopped", "STOP", timeout=5.0)


def repeated_id(kit: Kit) -> None:
    """A repeated id is not executed again: its answer is sent again."""
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(True)
    cid, first = link.command("JOB 3")
    start = len(link.replies)
    link.send("D 0 G04 P0")
    link.wait(lambda r: r.kind == "A", 2.0, start)
    _, again = link.command("JOB 3", cid=cid)
    mark = len(link.replies)
    link.send("D 1 G04 P0")
    ack = link.wait(lambda r: r.kind in "AN", 2.0, mark)
    ok = (
        first is not None
        and again is not None
        and str(first) == str(again)
        and ack is not None
        and ack.kind == "A"
        and ack.int(0) == 1
    )
    kit.check(
        "commands.repeated-id-not-executed",
        HOST,
        "a repeated `id` is not executed again: the machine "
        "re-sends the answers it has sent for it (`JOB` repeated: the stream goes on, `D 1` is acked)",
        ok,
        f"C {cid} JOB 3, D 0, C {cid} JOB 3 again, D 1",
        kit.got(start),
    )
    link.send("D 2 G04 P0")
    link.wait(lambda r: r.kind == "F" and r.int(0) == 2, 2.0, start)
    kit.check_mode(False)


def reset(kit: Kit) -> None:
    """RESET: `O <id> RESET` then `X BOOT <new boot>`; the position is unknown (not homed)."""
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(False)
    before = link.status()
    start = len(link.replies)
    cid, answer = link.command("RESET")
    boot = link.wait(lambda r: r.kind == "X" and r.fields[0] == "BOOT", 5.0, start)
    order = [r.kind for r in link.since(start) if (r.kind == "O" and r.id == cid) or r.kind == "X"]
    kit.check(
        "commands.reset",
        CONV,
        "`O <id> RESET` then `X BOOT <new boot>`",
        answer is not None and answer.kind == "O" and boot is not None and "X" in order
        and order.index("O") < order.index("X"),  # a retried command is answered again
        "C <id> RESET",
        kit.got(start),
    )
    new_boot = boot.text.split()[0] if boot is not None and boot.text else None
    after = kit.status_until(lambda st: st.boot == new_boot)
    kit.check(
        "commands.reset-new-boot",
        "Machine -> host",
        "`boot` is a random id the CNC MCU chooses at "
        "power-up or reset: the status after RESET carries the new one, not homed",
        before is not None
        and after is not None
        and boot is not None
        and after.boot == new_boot
        and after.boot != before.boot
        and not after.has("H"),
        "C <id> RESET, C <id> STATUS (every 0.2 s, up to 1.5 s)",
        f"before {before}, X {boot}, after {after}",
    )
    kit.expect_error(
        "commands.zero-not-homed", CONV, "`ZERO` before homing: `E <id> NOT_HOMED`", "ZERO", "NOT_HOMED"
    )
    kit.expect_error(
        "commands.job-not-homed",
        CONV,
        "`JOB` outside check mode before homing: `E <id> NOT_HOMED`",
        "JOB 1",
        "NOT_HOMED",
    )


CHECKS = [status, set_get, at_rest, repeated_id, reset]
