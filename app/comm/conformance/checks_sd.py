"""Checks of the SD verbs: `SD PUT` with its CRC32, `SD LIST` rows, `SD DEL`,
`SD RUN` (check mode), and their refusals. Files are named `ck_*`; the kit removes
the ones it made and touches no other."""

from __future__ import annotations

import zlib

from app.comm.conformance.kit import Kit

HOST = "Host -> machine"
CONV = "Machine conventions"
NAME = "ck_conform.ngc"
BAD = "ck_badcrc.ngc"
LINES = ["G00 Z5", "G00 X5 Y5", "G01 Z1 F300", "G01 X9", "G00 Z5"]


def crc32(lines: list[str]) -> str:
    """CRC32 over the lines joined with ``\\n`` plus a final ``\\n``, as hex."""
    data = ("\n".join(lines) + "\n").encode()
    return f"{zlib.crc32(data):08X}"


def put(kit: Kit, name: str, lines: list[str], crc: str) -> tuple[int, object]:
    """``SD PUT`` then its D stream; (reply index, the answer or None)."""
    link = kit.link
    start = len(link.replies)
    cid = link.send_command(f"SD PUT {name} {len(lines)} {crc}")
    for seq, line in enumerate(lines):
        link.send(f"D {seq} {line}")
    answer = link.wait(lambda r: r.kind in "OE" and r.id == cid, 5.0, start)
    return start, answer


def listing(kit: Kit) -> dict[str, tuple[str, str]] | None:
    link = kit.link
    start = len(link.replies)
    cid, answer = link.command("SD LIST")
    if answer is None or answer.kind != "O":
        return None
    rows = [r.text.split() for r in link.since(start) if r.kind == "I" and r.id == cid]
    return {row[0]: (row[1], row[2]) for row in rows if len(row) == 3}


def upload(kit: Kit) -> None:
    kit.ensure_idle()
    start, answer = put(kit, NAME, LINES, crc32(LINES))
    kit.check(
        "sd.put",
        HOST,
        "`SD PUT <name> <lines> <crc32hex>` then `D` frames acked with `A`: one `O <id> SD PUT "
        "<name>` once all lines are stored and the CRC32 matches",
        answer is not None and answer.kind == "O" and answer.text == f"PUT {NAME}",
        f"C <id> SD PUT {NAME} {len(LINES)} {crc32(LINES)}, D 0..4",
        kit.got(start),
    )
    acks = [r for r in kit.link.since(start) if r.kind == "A"]
    kit.check(
        "sd.put-acked",
        HOST,
        "the upload's `D` frames are acknowledged with `A` as usual",
        bool(acks) and acks[-1].int(0) == len(LINES) - 1,
        "D 0..4",
        kit.got(start),
    )
    rows = listing(kit)
    size = str(len(("\n".join(LINES) + "\n").encode()))
    kit.check(
        "sd.list-row",
        CONV,
        "`SD LIST`: `I <id> <name> <bytes> <lines>` rows, then `O <id> SD LIST <count>`",
        rows is not None and rows.get(NAME) == (size, str(len(LINES))),
        "C <id> SD LIST",
        f"rows {rows}; expected {NAME} {size} {len(LINES)}",
    )


def crc_mismatch(kit: Kit) -> None:
    start, answer = put(kit, BAD, LINES, "12345678" if crc32(LINES) != "12345678" else "1")
    kit.check(
        "sd.put-crc-mismatch",
        HOST,
        "a CRC32 that does not match: `E <id> CRC_MISMATCH` at the end, and no file is left",
        answer is not None and answer.kind == "E" and answer.fields[1] == "CRC_MISMATCH",
        f"C <id> SD PUT {BAD} 5 12345678, D 0..4",
        kit.got(start),
    )
    rows = listing(kit)
    kit.check(
        "sd.put-crc-mismatch-no-file",
        HOST,
        "after `CRC_MISMATCH` no file is left",
        rows is not None and BAD not in rows,
        "C <id> SD LIST",
        f"rows {rows}",
    )


def refusals(kit: Kit) -> None:
    kit.expect_error(
        "sd.bad-name-dot",
        CONV,
        "SD names must not start with `.`: `BAD_NAME`",
        "SD PUT .hidden 1 0",
        "BAD_NAME",
    )
    kit.expect_error(
        "sd.bad-name-path", HOST, "a bad name: `E` at once (`BAD_NAME`)", "SD PUT a/b 1 0", "BAD_NAME"
    )
    kit.expect_error(
        "sd.put-bad-crc-field", CONV, "`crc32hex` is 1-8 hex digits", "SD PUT ck_x.ngc 1 zz", "BAD_ARGS"
    )
    kit.expect_error(
        "sd.put-no-lines", CONV, "`SD PUT` needs at least one line", "SD PUT ck_x.ngc 0 0", "BAD_ARGS"
    )
    kit.expect_error(
        "sd.del-no-file", CONV, "`SD DEL` of a missing file: `NO_FILE`", "SD DEL ck_missing.ngc", "NO_FILE"
    )
    kit.expect_error(
        "sd.run-no-file", CONV, "`SD RUN` of a missing file: `NO_FILE`", "SD RUN ck_missing.ngc", "NO_FILE"
    )


def run_file(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(True)
    start = len(link.replies)
    cid, answer = link.command(f"SD RUN {NAME}", 5.0)
    done = link.wait(lambda r: r.kind == "L" and NAME in r.text and "done" in r.text, 10.0, start)
    flagged = [r for r in link.since(start) if r.kind == "S" and r.status().has("S")]
    kit.check(
        "sd.run",
        CONV,
        "`O <id> SD RUN <name>` once the job is open; `S` with flag `S` while it runs; `L SD <name> done`",
        answer is not None and answer.kind == "O" and answer.text == f"RUN {NAME}" and done is not None,
        f"C <id> SD RUN {NAME} (check mode)",
        kit.got(start, statuses=True),
    )
    kit.check(
        "sd.run-flag-s",
        "Machine -> host",
        "flag `S`: running from SD",
        bool(flagged),
        f"C <id> SD RUN {NAME}",
        f"{len(flagged)} statuses with S",
    )
    hidden = [r for r in link.since(start) if r.kind in "AF"]
    kit.check(
        "sd.run-traffic-kept",
        CONV,
        "during `SD RUN` the job's `A`/`N`/`F` stay between the two MCUs",
        not hidden,
        f"C <id> SD RUN {NAME}",
        " ".join(str(r) for r in hidden[:4]) or "no A/F",
    )
    kit.check_mode(False)


def delete(kit: Kit) -> None:
    kit.expect_ok(
        "sd.del",
        CONV,
        "`SD DEL <name>` -> `O <id> SD DEL <name>`",
        f"SD DEL {NAME}",
        lambda info: info == f"DEL {NAME}",
    )
    rows = listing(kit)
    kit.check(
        "sd.del-gone",
        CONV,
        "a deleted file is no longer listed",
        rows is not None and NAME not in rows,
        "C <id> SD LIST",
        f"rows {rows}",
    )


CHECKS = [upload, crc_mismatch, refusals, run_file, delete]
