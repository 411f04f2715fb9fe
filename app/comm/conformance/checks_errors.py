"""Checks that each error code of "Machine conventions" comes where the document says,
and the value grammar and ranges (`SET` choices, numbers, the loader's ranges)."""

from __future__ import annotations

from app.comm.conformance.kit import Kit

CONV = "Machine conventions"
HOST = "Host -> machine"

REFUSED = [  # (check, command, code, rule)
    ("errors.unknown-verb", "FROBNICATE", "UNKNOWN_VERB", "an unknown verb: `E <id> UNKNOWN_VERB`"),
    ("errors.bad-args-exponent", "JOG X 1e1 300", "BAD_ARGS", "numbers have no exponent: `BAD_ARGS`"),
    ("errors.bad-args-underscore", "JOG X 1_0 300", "BAD_ARGS", "numbers have no `_`: `BAD_ARGS`"),
    ("errors.bad-args-nan", "SET FERR nan", "BAD_ARGS", "no `inf`/`nan`: `BAD_ARGS`"),
    (
        "errors.bad-args-home-mode",
        "HOME SIDEWAYS",
        "BAD_ARGS",
        "`HOME [NORMAL|RECOVER]`: anything else `BAD_ARGS`",
    ),
    ("errors.bad-args-job-count", "JOB x", "BAD_ARGS", "`JOB <lines>`: counts are plain digits"),
    ("errors.bad-args-job-kind", "JOB 1 FOO", "BAD_ARGS", "`JOB <lines> [MDI]`: any other second word"),
    (
        "errors.set-choice-minus-zero",
        "SET OPTSTOP -0",
        "BAD_ARGS",
        "a `SET` choice is one digit: `-0` refused",
    ),
    ("errors.set-choice-point", "SET AFTERJOB 3.0", "BAD_ARGS", "a `SET` choice is one digit: `3.0` refused"),
    (
        "errors.set-choice-leading-zero",
        "SET CHECK 01",
        "BAD_ARGS",
        "a `SET` choice is one digit: `01` refused",
    ),
    ("errors.bad-param-choice", "SET AFTERJOB 4", "BAD_PARAM", "a digit outside the choices: `BAD_PARAM`"),
    ("errors.bad-param-range", "SET FERR 0.01", "BAD_PARAM", "`FERR` 0.05-100 mm: outside `BAD_PARAM`"),
    ("errors.bad-param-name", "GET NOPE", "BAD_PARAM", "an unknown `SET`/`GET` name: `BAD_PARAM`"),
    ("errors.jog-distance-range", "JOG X 1000001 300", "BAD_VALUE", "`JOG` distance at most 1,000,000 mm"),
    ("errors.jog-feed-range", "JOG X 1 0.0001", "BAD_VALUE", "`JOG` feed at least 0.001 mm/min"),
    ("errors.spindle-range", "SPINDLE 1000000000", "BAD_VALUE", "`SPINDLE <rpm>` below 10^9"),
    ("errors.resume-from-no-job", "RESUME FROM 7", "BAD_SEQ", "`RESUME FROM <seq>` needs `seq = acc+1`"),
    ("errors.sd-unknown", "SD FORMAT", "UNKNOWN_VERB", "`SD LIST|PUT|DEL|RUN`: anything else unknown"),
]

LINES = [  # (check, line, code, rule): one line in a check-mode job, refused `E - <code> 0 ...`
    ("errors.bad-line", "G99 X1", "BAD_LINE", "a line the machine cannot read: `E - BAD_LINE <seq> ...`"),
    (
        "errors.bad-value-dwell",
        "G04 P1000000000",
        "BAD_VALUE",
        "a dwell `G04 P` 0 to 3600 s, else `BAD_VALUE`",
    ),
    (
        "errors.bad-value-feed",
        "G01 X1 F0.0001",
        "BAD_VALUE",
        "a feed `F` at least 0.001 mm/min, else `BAD_VALUE`",
    ),
    (
        "errors.bad-value-size",
        "G00 X1000000001",
        "BAD_VALUE",
        "every number below 10^9 in size, else `BAD_VALUE`",
    ),
    ("errors.no-feed", "G01 X1 Y1", "NO_FEED", "a feed move with no `F` yet: `NO_FEED`"),
    ("errors.bad-arc", "G02 X1 Y1 I0 J0 F100", "BAD_ARC", "an arc of zero radius: `BAD_ARC`"),
    (
        "errors.soft-limit",
        "G00 X100000",
        "SOFT_LIMIT",
        "a move past the travel: `E - SOFT_LIMIT <seq> <axis><+|-> <value> <</>> <limit>`",
    ),
]


def commands(kit: Kit) -> None:
    kit.ensure_idle()
    for check, text, code, rule in REFUSED:
        kit.expect_error(check, CONV, rule, text, code)


def refused_lines(kit: Kit) -> None:
    link = kit.link
    for check, line, code, rule in LINES:
        kit.ensure_idle()
        kit.check_mode(True)
        link.command("JOB 1")
        start = len(link.replies)
        link.send(f"D 0 {line}")
        refusal = link.wait(lambda r: r.kind == "E" and r.id is None, 2.0, start)
        ok = refusal is not None and refusal.fields[1] == code and refusal.text.split(" ")[0] == "0"
        if ok and code == "SOFT_LIMIT":
            ok = " X+ " in f" {refusal.text} " and ">" in refusal.text
        kit.check(
            check,
            CONV,
            rule + '; the text starts with the refused seq ("Host conventions")',
            ok,
            f"C <id> JOB 1, D 0 {line}",
            kit.got(start),
        )
    kit.check_mode(False)


def no_job_open(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    start = len(link.replies)
    link.send("D 1000 G00 X1")
    refusal = link.wait(lambda r: r.kind == "E" and r.id is None and r.text.startswith("1000 "), 2.0, start)
    kit.check(
        "errors.d-without-job",
        CONV,
        "a `D` frame while no job is open: `E - BAD_SEQ <seq> no job open`",
        refusal is not None and refusal.fields[1] == "BAD_SEQ" and refusal.text.startswith("1000"),
        "D 1000 G00 X1",
        kit.got(start),
    )


def busy(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(True)
    link.command("JOB 5")
    kit.expect_error(
        "errors.busy-check-during-job", CONV, "`SET CHECK` while a job is open: `BUSY`", "SET CHECK 0", "BUSY"
    )
    kit.expect_error(
        "errors.busy-jog-during-job", CONV, "`JOG` while a job is open: `BUSY`", "JOG X 1 100", "BUSY"
    )
    kit.expect_error("errors.busy-job-during-job", CONV, "`JOB` while a job is open: `BUSY`", "JOB 2", "BUSY")
    link.command("STOP")
    kit.check_mode(False)


def not_from_the_wire(kit: Kit) -> None:
    kit.skip(
        "errors.alarm",
        CONV,
        "`E <id> ALARM` while in alarm",
        "needs an alarm (a limit switch, a following "
        "error): no verb makes one; check by hand (trip a limit, then JOG)",
    )
    kit.skip(
        "errors.queue-full",
        CONV,
        "`QUEUE_FULL`",
        "a host that respects `free` never fills the queue "
        "(the machine answers `N expected` instead: checked in motion.credit-window)",
    )
    kit.skip("errors.sd-full", CONV, "`E <id> SD_FULL` with the partial file removed", "needs a full card")


CHECKS = [commands, refused_lines, no_job_open, busy, not_from_the_wire]
