"""Checks of "Errors and resends": a clean stream, gaps and selective repeat,
duplicates, a bad CRC inside a stream, the credit window (check mode: no homing)."""

from __future__ import annotations

from app.comm.conformance.kit import Kit
from app.comm.conformance.stream import Streamer
from app.comm.conformance.wire import Reply, seal

RESENDS = "Errors and resends"


def _open_job(kit: Kit, count: int) -> tuple[int, int]:
    """A check-mode job of ``count`` lines; (reply index after O JOB, free from the status)."""
    kit.ensure_idle()
    kit.check_mode(True)
    status = kit.link.status()
    kit.link.command(f"JOB {count}")
    return len(kit.link.replies), int(status.free) if status is not None else 1


def _lines(count: int) -> list[str]:
    return [f"G01 X{k % 50 + 1} Y{k % 30 + 1} F1000" for k in range(count)]


def _kinds(replies: list[Reply], kinds: str = "ANFE") -> str:
    return " ".join(
        f"{r.kind}{(' ' + r.fields[0]) if r.kind in 'ANF' else ''}" for r in replies if r.kind in kinds
    )


def send(kit: Kit, lines: list[str], seqs) -> int:
    """Send ``D <seq>`` for each of ``seqs``; the reply index before them."""
    mark = len(kit.link.replies)
    for seq in seqs:
        kit.link.send(f"D {seq} {lines[seq]}")
    return mark


def finish(kit: Kit, check: str, rule: str, lines: list[str], seqs, section: str = RESENDS) -> None:
    """Send ``seqs``; the job must end with ``F`` of its last line and no refusal."""
    mark = send(kit, lines, seqs)
    last = len(lines) - 1
    done = kit.link.wait(lambda r: r.kind == "F" and r.int(0) == last, 2.0, mark)
    refused = [r for r in kit.link.since(mark) if r.kind == "E"]
    sent = ", ".join(f"D {seq}" for seq in seqs)
    kit.check(check, section, rule, done is not None and not refused, sent, kit.got(mark))
    kit.check_mode(False)


def clean_stream(kit: Kit) -> None:
    start, free = _open_job(kit, 60)
    out = Streamer(kit.link, _lines(60), free).run(30.0)
    got = kit.got(start)
    kit.check(
        "stream.clean-job-completes",
        RESENDS,
        "a job streamed within the credit window ends with `F <last seq>` (cumulative `A` and `F`)",
        out.complete and out.refused is None,
        "C <id> JOB 60, D 0..59 within min(free, 16)",
        got,
    )
    kit.check(
        "stream.no-n-on-a-clean-wire",
        RESENDS,
        "with no frame lost the machine asks for no resend (`N` only for a bad frame or a gap)",
        not out.naks,
        "D 0..59 in order",
        f"N for {out.naks[:8]}",
    )
    acks = [r for r in kit.link.since(start) if r.kind == "A"]
    monotonic = all(a.int(0) <= b.int(0) for a, b in zip(acks, acks[1:], strict=False))
    kit.check(
        "stream.ack-cumulative",
        "Machine -> host",
        "`A <seq> <free>`: every `D` up to `seq` has arrived (cumulative: seqs never go back)",
        bool(acks) and monotonic,
        "D 0..59",
        _kinds(kit.link.since(start)),
    )
    kit.check_mode(False)


def gap(kit: Kit) -> None:
    """D0 D1 D3 D4: `N 2` at once; D2: `A 2` and one `A 4` for the kept 3 and 4 (selective repeat)."""
    link, lines = kit.link, _lines(6)
    start, _ = _open_job(kit, 6)
    send(kit, lines, (0, 1, 3, 4))
    nak = link.wait(lambda r: r.kind == "N", 1.0, start)
    kit.check(
        "stream.gap-answered-n",
        RESENDS,
        "seq > expected: keep it and answer `N expected`",
        nak is not None and nak.int(0) == 2,
        "D 0, D 1, D 3, D 4",
        _kinds(link.since(start)),
    )
    mark = send(kit, lines, (2,))
    link.wait(lambda r: r.kind == "A" and r.int(0) >= 4, 1.0, mark)
    link.idle(0.1)
    above = {r.int(0) for r in link.since(mark) if r.kind == "A" and r.int(0) > 2}
    kit.check(
        "stream.selective-repeat",
        RESENDS,
        "seq == expected: queue it and answer `A`; then queue every frame "
        "kept above it and answer one `A` for them all (`A 4`, no `A 3`; 3 and 4 not asked for again)",
        above == {4} and not [r for r in link.since(mark) if r.kind == "N"],
        "D 2 (3 and 4 not resent)",
        _kinds(link.since(mark)),
    )
    finish(kit, "stream.gap-job-completes", "no line runs twice or is lost: `F 5` ends the job", lines, (5,))


def holes(kit: Kit) -> None:
    """D0 D2 D5: `N 1`, then `N 3` `N 4` (every seq seen missing named at once)."""
    link, lines = kit.link, _lines(7)
    start, _ = _open_job(kit, 7)
    send(kit, lines, (0, 2))
    link.wait(lambda r: r.kind == "N", 1.0, start)
    mark = send(kit, lines, (5,))
    link.idle(0.3)
    naks = sorted(r.int(0) for r in link.since(mark) if r.kind == "N")
    kit.check(
        "stream.every-missing-seq-named",
        RESENDS,
        "a kept frame more than one above the highest seen is "
        "answered `N` for each seq between them (at most 4)",
        naks == [3, 4],
        "D 0, D 2, then D 5",
        _kinds(link.since(start)),
    )
    mark = send(kit, lines, (1,))
    after = link.wait(lambda r: r.kind == "N", 1.0, mark)
    kit.check(
        "stream.new-gap-named-at-once",
        RESENDS,
        "once a gap is filled, if frames are still kept above a new gap, `N <new expected>` at once",
        after is not None and after.int(0) == 3,
        "D 1",
        _kinds(link.since(mark)),
    )
    finish(kit, "stream.holes-job-completes", "the job ends with `F 6`", lines, (3, 4, 6))


def duplicate(kit: Kit) -> None:
    link, lines = kit.link, _lines(4)
    start, _ = _open_job(kit, 4)
    send(kit, lines, (0, 1, 2))
    link.wait(lambda r: r.kind == "A" and r.int(0) == 2, 1.0, start)
    mark = send(kit, lines, (1,))
    again = link.wait(lambda r: r.kind in "AN", 1.0, mark)
    kit.check(
        "stream.duplicate-reacked",
        RESENDS,
        "seq < expected: a duplicate; drop it, answer `A` again",
        again is not None and again.kind == "A" and again.int(0) == 2,
        "D 0..2, then D 1 again",
        _kinds(link.since(mark)),
    )
    finish(
        kit,
        "stream.duplicate-not-run-twice",
        "a duplicate never runs twice: `F 3` ends the job (no refusal)",
        lines,
        (3,),
    )


def bad_crc_in_stream(kit: Kit) -> None:
    link, lines = kit.link, _lines(3)
    start, _ = _open_job(kit, 3)
    send(kit, lines, (0,))
    link.wait(lambda r: r.kind == "A", 1.0, start)
    raw = seal(f"D 1 {lines[1]}")
    bad = raw[:4] + bytes([raw[4] ^ 0x01]) + raw[5:]
    mark = len(link.replies)
    link.write(bad)
    nak = link.wait(lambda r: r.kind == "N", 1.0, mark)
    kit.check(
        "stream.bad-crc-answered-n",
        RESENDS,
        "a bad CRC: drop it and answer `N expected`",
        nak is not None and nak.int(0) == 1,
        bad.decode("ascii", "replace").strip(),
        _kinds(link.since(mark)),
    )
    finish(
        kit,
        "stream.bad-crc-line-not-run",
        "the corrupted line never runs; its resend does (`F 2`)",
        lines,
        (1, 2),
    )


def go_back_n(kit: Kit) -> None:
    """A go-back-N host (resends everything from n on `N n`) still works."""
    link, lines = kit.link, _lines(6)
    start, _ = _open_job(kit, 6)
    send(kit, lines, (0, 2, 3))
    link.wait(lambda r: r.kind == "N", 1.0, start)
    finish(
        kit,
        "stream.go-back-n-host-works",
        "a host that resends everything from `n` on `N n` still works: the "
        "frames the machine has are duplicates",
        lines,
        range(1, 6),
    )


CHECKS = [clean_stream, gap, holes, duplicate, bad_crc_in_stream, go_back_n]
