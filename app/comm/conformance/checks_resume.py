"""Checks of `RESUME FROM <seq>` ("Heartbeat, loss and resume"; "Machine conventions":
`seq = acc+1`, else `BAD_SEQ`), in check mode."""

from __future__ import annotations

from app.comm.conformance.checks_stream import finish, send
from app.comm.conformance.kit import Kit

RESUME = "Heartbeat, loss and resume"


def resume_from(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(True)
    link.command("JOB 10")
    lines = [f"G01 X{k + 1} F500" for k in range(10)]
    start = send(kit, lines, range(5))
    link.wait(lambda r: r.kind == "A" and r.int(0) == 4, 2.0, start)
    status = kit.status_until(lambda st: st.acc == "4")
    kit.check(
        "resume.status-acc",
        "Machine conventions",
        "`acc` in `S` is the last accepted seq (the main MCU's answer to `STATUS` is at most 1 s old)",
        status is not None and status.acc == "4",
        "D 0..4, C <id> STATUS every 0.2 s",
        str(status),
    )
    kit.expect_error(
        "resume.from-wrong-seq",
        "Machine conventions",
        "`RESUME FROM <seq>` needs `seq = acc+1`, else `BAD_SEQ`",
        "RESUME FROM 3",
        "BAD_SEQ",
    )
    kit.expect_ok(
        "resume.from-acc-plus-one",
        RESUME,
        "`C <id> RESUME FROM <acc+1>` -> `O <id> RESUME FROM <seq>`",
        "RESUME FROM 5",
        lambda info: info == "FROM 5",
    )
    finish(
        kit,
        "resume.then-missing-frames",
        "after `RESUME FROM`, the missing frames: no line runs twice or is lost (`F 9`, no refusal)",
        lines,
        range(5, 10),
        RESUME,
    )
    kit.expect_error(
        "resume.from-after-job",
        "Machine conventions",
        "`RESUME FROM` with no job open: `BAD_SEQ`",
        "RESUME FROM 10",
        "BAD_SEQ",
    )
    kit.check_mode(False)


CHECKS = [resume_from]
