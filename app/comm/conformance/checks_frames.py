"""Checks of "Frames" and of the shape of every frame the machine sends."""

from __future__ import annotations

from app.comm.conformance.kit import Kit
from app.comm.conformance.wire import MAX_FRAME, seal, self_test

FRAMES = "Frames"
MACHINE = "Machine -> host"


def codec(kit: Kit) -> None:
    problems = self_test()
    kit.check(
        "frames.crc-check-values",
        FRAMES,
        "CRC-16/CCITT-FALSE: `123456789` -> 29B1, `D 0 G00 X10 Y10` -> 904C (the kit's own codec)",
        not problems,
        got="; ".join(problems),
    )


def ping(kit: Kit) -> None:
    link = kit.link
    start = len(link.replies)
    link.send_command("PING")
    reply = link.wait(lambda r: r.kind == "S", 3.0, start)
    kit.check(
        "frames.ping-answered-with-s",
        "Host -> machine",
        "`C <id> PING` is answered with `S <boot> <state> <x> <y> <z> <acc> <done> <free> <rpm> <flags>`",
        reply is not None,
        "C <id> PING",
        kit.got(start, statuses=True),
    )


def bad_crc(kit: Kit) -> None:
    """A command with a bad CRC is dropped (not carried out) and answered N."""
    link = kit.link
    fresh = kit.fresh_stretch()
    cid = link.new_id()
    good = seal(f"C {cid} SET OPTSTOP 0")
    bad = good[:-5] + (b"0000" if good[-5:-1] != b"0000" else b"1111") + b"\n"
    start = len(link.replies)
    link.write(bad)
    nak = link.wait(lambda r: r.kind == "N", 1.0, start)
    kit.check(
        "frames.bad-crc-answered-n",
        FRAMES,
        "a frame with a bad CRC is dropped and answered "
        '`N expected` ("Errors and resends": a bad CRC, N once per bad stretch)',
        nak is not None,
        bad.decode().strip(),
        kit.got(start),
        "" if fresh else "could not end an earlier bad stretch first (one-line check-mode job)",
    )
    answered = link.wait(lambda r: r.id == cid, 0.5, start)
    _, now = link.command("GET OPTSTOP")
    kit.check(
        "frames.bad-crc-not-executed",
        FRAMES,
        "a frame with a bad CRC is never carried out",
        answered is None and now is not None and now.text.endswith(" 1"),
        f"{bad.decode().strip()} then C <id> GET OPTSTOP",
        kit.got(start),
        "expects OPTSTOP still at its default 1",
    )


def malformed(kit: Kit) -> None:
    """No `*`, over-length, a bad field, a lower-case CRC: each dropped, never carried out."""
    link = kit.link
    ferr = "SET FERR 2." + "0" * MAX_FRAME  # a valid command but for its length
    cases = {
        "frames.no-star-dropped": (lambda i: b"C %d GET OPTSTOP\n" % i, "a frame with no `*` is dropped"),
        "frames.over-length-dropped": (
            lambda i: seal(f"C {i} {ferr}"),
            f"a frame over {MAX_FRAME} bytes is dropped whole",
        ),
        "frames.bad-field-dropped": (
            lambda i: seal(f"C {i}x GET OPTSTOP"),
            "a frame with a bad field (the id `<n>x`) is dropped",
        ),
        "frames.lowercase-crc-dropped": (
            lambda i: _lower_crc(f"C {i} GET OPTSTOP"),
            "`CCCC` is 4 upper-case hex digits: lower case is a bad frame",
        ),
    }
    for check, (make, rule) in cases.items():
        cid = link.new_id()
        raw = make(cid)
        while check == "frames.lowercase-crc-dropped" and raw[-5:-1].isdigit():
            cid = link.new_id()
            raw = make(cid)
        start = len(link.replies)
        link.write(raw)
        executed = link.wait(
            lambda r, cid=cid: r.kind in "OE" and (r.id == cid or r.fields[1] in ("GET", "SET")), 0.6, start
        )
        _, alive = link.command("GET AFTERJOB")
        kit.check(
            check,
            FRAMES,
            rule + " (never carried out; the machine answers the next good frame)",
            executed is None and alive is not None,
            raw.decode("ascii", "replace").strip()[:80] + " then C <id> GET AFTERJOB",
            kit.got(start),
        )


def _lower_crc(body: str) -> bytes:
    """``body`` sealed with its CRC in lower case (an id whose CRC has a letter is chosen
    by the caller's retry: a CRC of digits only is returned as it is)."""
    raw = seal(body)
    return raw[:-5] + raw[-5:-1].lower() + b"\n"


def carriage_return(kit: Kit) -> None:
    link = kit.link
    start = len(link.replies)
    cid = link.new_id()
    link.write(seal(f"C {cid} GET OPTSTOP")[:-1] + b"\r\n")
    answer = link.wait(lambda r: r.id == cid, 2.0, start)
    kit.check(
        "frames.cr-ignored",
        FRAMES,
        "`\\r` is ignored",
        answer is not None and answer.kind == "O",
        f"C {cid} GET OPTSTOP*CCCC\\r\\n",
        kit.got(start),
    )


def partial_timeout(kit: Kit) -> None:
    """A partial frame with no newline for 500 ms is dropped: what follows is read alone."""
    link = kit.link
    link.heartbeat = False
    try:
        start = len(link.replies)
        stale = link.new_id()
        link.write(seal(f"C {stale} GET FERR")[:9])
        link.idle(0.8)
        cid = link.new_id()
        link.send(f"C {cid} GET OPTSTOP")
        answer = link.wait(lambda r: r.id == cid, 1.5, start)
    finally:
        link.heartbeat = True
    kit.check(
        "frames.partial-dropped-after-500ms",
        FRAMES,
        "a partial frame with no `\\n` for 500 ms is dropped (the next frame is read on its own)",
        answer is not None and answer.kind == "O",
        f"9 bytes of C {stale} GET FERR, 800 ms of silence, C {cid} GET OPTSTOP",
        kit.got(start),
    )


def every_frame_well_formed(kit: Kit) -> None:
    """Run last: every line the machine sent in the whole run."""
    bad = [r for r in kit.link.replies if r.problem is not None]
    shown = "; ".join(f"{r} -> {r.problem}" for r in bad[:4])
    kit.check(
        "frames.machine-frames-valid",
        MACHINE,
        "every frame the machine sends is `BODY*CCCC\\n` with "
        "a correct CRC (mandatory in both directions), at most 96 bytes, in the grammar of its kind",
        not bad,
        got=shown or f"{len(kit.link.replies)} lines, all valid",
        note=f"{len(bad)} bad of {len(kit.link.replies)}" if bad else "",
    )


CHECKS = [codec, ping, bad_crc, malformed, carriage_return, partial_timeout]
