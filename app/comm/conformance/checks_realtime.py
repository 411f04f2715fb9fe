"""Checks of "Real-time commands" (`R` frames) and "Why the machine holds": answered
once per id, idempotent, strict grammar, kept apart from the remembered `C` id, the
legacy bytes `!` and 0x18 never acted on, `RESET`; with motion (not `--quick`) a
hold, resume and stop of a moving job, with their latency and the status's `why`."""

from __future__ import annotations

from app.comm.conformance.checks_stream import send
from app.comm.conformance.kit import Kit
from app.comm.conformance.wire import STATES

RT = "Real-time commands"
WHY = "Why the machine holds"
ANSWER_S = 0.25  # the rule is 50 ms from the operator's click; a host on a busy computer measures coarser


def _check_job(kit: Kit, count: int) -> list[str]:
    """A check-mode job of ``count`` lines open, line 0 accepted."""
    kit.ensure_idle()
    kit.check_mode(True)
    kit.link.command(f"JOB {count}")
    lines = [f"G01 X{k + 1} F600" for k in range(count)]
    mark = send(kit, lines, (0,))
    kit.link.wait(lambda r: r.kind == "A" and r.int(0) == 0, 2.0, mark)
    return lines


def _acked(kit: Kit, lines: list[str], seq: int) -> bool:
    mark = send(kit, lines, (seq,))
    reply = kit.link.wait(lambda r: r.kind in "ANE" and (r.kind != "E" or r.id is None), 2.0, mark)
    return reply is not None and reply.kind == "A" and reply.int(0) == seq


def answered(kit: Kit) -> None:
    kit.ensure_idle()
    for verb in ("HOLD", "RESUME", "STOP"):
        start = len(kit.link.replies)
        cid, answer = kit.link.realtime(verb)
        ok = answer is not None and answer.kind == "O" and answer.fields[1] == verb and answer.text in STATES
        kit.check(
            f"realtime.{verb.lower()}-answered",
            RT,
            f"`R <id> {verb}` is answered `O <id> {verb} <state>` as soon as the machine has acted",
            ok,
            f"R {cid} {verb} (twice, then every 10 ms)",
            kit.got(start),
        )


def idempotent(kit: Kit) -> None:
    """`R STOP` ends a job; the same id again (a repeat) is answered and stops nothing."""
    link = kit.link
    lines = _check_job(kit, 5)
    cid, first = link.realtime("STOP")
    ended = not _acked(kit, lines, 1)
    kit.check(
        "realtime.stop-ends-job",
        RT,
        "`R STOP` as `C STOP`: the queue is flushed, the job ends (a `D` after it is refused)",
        first is not None and first.kind == "O" and ended,
        f"JOB 5, D 0, R {cid} STOP, D 1",
        kit.got(len(link.replies) - 6),
    )
    lines = _check_job(kit, 3)
    start = len(link.replies)
    _, again = link.realtime("STOP", cid=cid)
    kept = _acked(kit, lines, 1)
    kit.check(
        "realtime.repeat-not-executed",
        RT,
        "an `R` frame whose id the machine remembers is a repeat: not "
        "carried out again, its answer sent again",
        again is not None and again.kind == "O" and kept,
        f"JOB 3, D 0, R {cid} STOP again (same id), D 1",
        kit.got(start),
    )
    link.command("STOP")
    kit.check_mode(False)


def grammar(kit: Kit) -> None:
    """A verb outside the four, or a `why` from the host: a bad frame, never carried out."""
    link = kit.link
    for check, text in (
        ("realtime.unknown-verb-dropped", "R {id} JUMP"),
        ("realtime.why-from-host-dropped", "R {id} HOLD HOST"),
        ("realtime.bad-id-dropped", "R x{id} HOLD"),
    ):
        kit.ensure_idle()
        cid = link.new_id()
        start = len(link.replies)
        body = text.format(id=cid)
        link.send(body)
        done = link.wait(lambda r, cid=cid: r.kind == "O" and r.id == cid, 0.5, start)
        _, alive = link.command("GET OPTSTOP")
        kit.check(
            check,
            RT,
            "grammar, strict: exactly `R`, the id, one of `HOLD RESUME STOP RESET` (and `why` only "
            "from the main MCU); anything else is a bad frame, never carried out",
            done is None and alive is not None,
            body,
            kit.got(start),
        )


def apart_from_c(kit: Kit) -> None:
    """An `R` never makes the machine forget the last `C` id."""
    link = kit.link
    kit.ensure_idle()
    kit.check_mode(True)
    cid, first = link.command("JOB 3")
    lines = [f"G01 X{k + 1} F600" for k in range(3)]
    send(kit, lines, (0,))
    start = len(link.replies)
    link.realtime("RESUME")
    _, again = link.command("JOB 3", cid=cid)
    kept = _acked(kit, lines, 1)
    kit.check(
        "realtime.apart-from-c-id",
        RT,
        "`R` ids and the remembered `C` id are kept apart: the `C` repeated "
        "after an `R` is still answered from memory, not carried out again",
        first is not None and again is not None and str(first) == str(again) and kept,
        f"C {cid} JOB 3, D 0, R RESUME, C {cid} JOB 3 again, D 1",
        kit.got(start),
    )
    link.command("STOP")
    kit.check_mode(False)


def legacy_bytes(kit: Kit) -> None:
    """`!` and 0x18 at the start of a line are taken off, counted, logged, never acted on."""
    link = kit.link
    lines = _check_job(kit, 4)
    start = len(link.replies)
    link.write(b"!")
    link.write(b"\x18")
    link.write(b"!\x18!")
    link.idle(0.3)
    status = link.status()
    kept = _acked(kit, lines, 1)
    logged = [r for r in link.since(start) if r.kind == "L" and r.text.startswith("ignored ")]
    kit.check(
        "realtime.legacy-bytes-ignored",
        RT,
        "the bytes `!` and 0x18 are no command: a job open is neither "
        "held nor stopped (the next `D` is acked)",
        kept and status is not None and status.state != "HOLD",
        "JOB 4, D 0, then ! 0x18 !0x18! between frames, D 1",
        kit.got(start, statuses=True),
    )
    kit.check(
        "realtime.legacy-bytes-logged",
        RT,
        "`L ignored <n> real-time byte(s) (use R frames)` at most once a second while they come",
        1 <= len(logged) <= 2,
        "! 0x18 !0x18!",
        kit.got(start),
    )
    link.command("STOP")
    kit.check_mode(False)


def reset(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    start = len(link.replies)
    cid, answer = link.realtime("RESET")
    boot = link.wait(lambda r: r.kind == "X" and r.fields[0] == "BOOT", 3.0, start)
    order = [r.kind for r in link.since(start) if (r.kind == "O" and r.id == cid) or (r.kind == "X")]
    kit.check(
        "realtime.reset",
        RT,
        "`R RESET` as `C RESET`: `O <id> RESET` comes before `X BOOT`",
        answer is not None and answer.kind == "O" and boot is not None and "X" in order
        and order.index("O") < order.index("X"),  # the host's second copy may be answered too
        f"R {cid} RESET",
        kit.got(start),
    )


def why_field(kit: Kit) -> None:
    statuses = [r.status() for r in kit.link.replies if r.problem is None and r.kind == "S"]
    ten = sum(st.why is None for st in statuses)
    kit.check(
        "realtime.status-has-why",
        WHY,
        "the status's eleventh field `why` (one word, `-` for none)",
        bool(statuses) and ten == 0,
        "every status of the run",
        f"{ten} of {len(statuses)} statuses of ten fields",
    )


def moving(kit: Kit) -> None:
    """With motion: `R HOLD` holds a moving job fast, `why` HOST; `R RESUME`; `R STOP`."""
    if kit.quick:
        kit.skip("realtime.hold-moving-job", RT, "a hold of a moving job within 50 ms", "left out by --quick")
        return
    link = kit.link
    if not kit.ensure_homed():
        kit.check("realtime.hold-moving-job", RT, "a hold of a moving job", False, "HOME", "homing failed")
        return
    kit.ensure_idle()
    kit.check_mode(False)
    link.command("SET AFTERJOB 0")
    feed = max(1, round(60 * 60 / (8.0 * kit.pace)))
    lines = ["G00 X30 Y30", f"G01 X90 F{feed}", "G00 X30"]
    link.command(f"JOB {len(lines)}")
    send(kit, lines, range(3))
    link.wait(lambda r: r.kind == "S" and r.status().state == "RUN", 5.0)
    link.idle(0.3)
    start = len(link.replies)
    sent_at = link.clock()
    cid, answer = link.realtime("HOLD")
    held = link.wait(lambda r: r.kind == "S" and r.status().state == "HOLD", 2.0, start)
    took = None if answer is None else answer.t - sent_at
    kit.check(
        "realtime.hold-moving-job",
        RT,
        "`R HOLD` holds a moving job at once (within 50 ms of the click): "
        "`O <id> HOLD <state>`, then a status in `HOLD`",
        answer is not None
        and answer.kind == "O"
        and held is not None
        and took is not None
        and took <= ANSWER_S,
        f"R {cid} HOLD during a move",
        kit.got(start, statuses=True, limit=4),
        f"answered after {took:.3f} s" if took is not None else "",
    )
    kit.check(
        "realtime.why-host",
        WHY,
        "a host's `R HOLD` holds with `why` `HOST`",
        held is not None and held.status().why == "HOST",
        f"R {cid} HOLD",
        str(held),
    )
    start = len(link.replies)
    _, answer = link.realtime("RESUME")
    running = link.wait(lambda r: r.kind == "S" and r.status().state == "RUN", 2.0, start)
    kit.check(
        "realtime.resume-moving-job",
        RT,
        "`R RESUME` leaves the hold (`why` back to `-`)",
        answer is not None and running is not None and running.status().why in (None, "-"),
        "R <id> RESUME",
        kit.got(start, statuses=True, limit=4),
    )
    start = len(link.replies)
    _, answer = link.realtime("STOP")
    idle = link.wait(lambda r: r.kind == "S" and r.status().state == "IDLE", 10.0, start)
    kit.check(
        "realtime.stop-moving-job",
        RT,
        "`R STOP` decelerates, flushes the queue, ends the job: a status in `IDLE` with `why` `HOST`",
        answer is not None and idle is not None and idle.status().why == "HOST",
        "R <id> STOP",
        kit.got(start, statuses=True, limit=4),
    )
    link.command("SET AFTERJOB 1")


CHECKS = [answered, idempotent, grammar, apart_from_c, legacy_bytes, moving, reset]
