"""Checks that need homing and real motion (left out by ``--quick``): HOME, JOG,
SPINDLE, ZERO (the work offset is put back), statuses while moving, `SPINDLE OFF`
during a jog, program stops, the credit window with a full queue, a host lost during
a streamed job and its `RESUME FROM`, `SD PUT`/`SD DEL` of the running file, the
after-job lift (not after `JOB <n> MDI`)."""

from __future__ import annotations

from app.comm.conformance import checks_link, checks_sd
from app.comm.conformance.kit import HOME_TIMEOUT_S, Kit
from app.comm.conformance.stream import Streamer

CONV = "Machine conventions"
STOPS = "Program stops and tool changes"
STATUS_GAP_S = 0.25  # the document's 50 ms, as a host on a busy computer can measure it


def home(kit: Kit) -> None:
    kit.ensure_idle()
    kit.check_mode(False)
    answer = kit.expect_ok(
        "motion.home",
        CONV,
        "`O <id> HOME <NORMAL|RECOVER>` once homed",
        "HOME",
        lambda info: info == "NORMAL",
        timeout=HOME_TIMEOUT_S,
    )
    status = kit.status_until(lambda st: st.has("H") and st.state == "IDLE")
    kit.check(
        "motion.homed-flag",
        "Machine -> host",
        "flag `H` once homed",
        answer is not None and status is not None and status.has("H") and status.state == "IDLE",
        "C <id> STATUS",
        str(status),
    )


def jog_and_statuses(kit: Kit) -> None:
    link = kit.link
    before = link.status()
    start = len(link.replies)
    began = link.clock()
    answer = kit.expect_ok(
        "motion.jog",
        CONV,
        "`O <id> JOG <axis> <dist>` when the jog ends",
        "JOG X 20 600",
        lambda info: info == "X 20",
        timeout=60.0,
    )
    if answer is not None:  # 20 mm at 10 mm/s: 2 s of the machine's time (a little more with ramps)
        kit.pace = max(1.0, 2.0 / max(answer.t - began, 1e-3))
    after = link.status()
    moved = before is not None and after is not None and abs(float(after.x) - float(before.x) - 20) < 0.05
    kit.check(
        "motion.jog-moves",
        "Machine -> host",
        "the status position follows the jog (work mm, 3 decimals)",
        moved,
        "C <id> JOG X 20 600",
        f"x {before.x if before else '?'} -> {after.x if after else '?'}",
    )
    times = [r.t for r in link.since(start) if r.kind == "S" and r.status().state == "JOG"]
    gap = max((b - a for a, b in zip(times, times[1:], strict=False)), default=None)
    kit.check(
        "motion.status-while-moving",
        "Machine -> host",
        "`S` at least every 50 ms while moving",
        gap is not None and gap <= STATUS_GAP_S,
        "C <id> JOG X 20 600",
        f"{len(times)} statuses in JOG, longest gap {gap:.3f} s" if gap is not None else "no status in JOG",
        f"accepted up to {STATUS_GAP_S} s as measured at the host",
    )


def spindle(kit: Kit) -> None:
    link = kit.link
    kit.expect_ok(
        "motion.spindle-on",
        CONV,
        "`O <id> SPINDLE <rpm>` when carried out",
        "SPINDLE 1000",
        lambda info: info == "1000",
        timeout=20.0,
    )
    status = link.status()
    kit.check(
        "motion.spindle-flag",
        "Machine -> host",
        "flag `P` spindle on, `rpm` its speed",
        status is not None and status.has("P") and int(status.rpm) > 0,
        "C <id> STATUS",
        str(status),
    )
    cid = link.send_command("JOG Y 30 300")
    link.wait(lambda r: r.kind == "S" and r.status().state == "JOG", 3.0)
    kit.expect_ok(
        "motion.spindle-off-during-jog",
        CONV,
        "`SPINDLE OFF` is always allowed: while anything moves it "
        "stops the spindle at once and is answered at once",
        "SPINDLE OFF",
        lambda info: info == "OFF",
        timeout=2.0,
    )
    link.wait(lambda r: r.kind in "OE" and r.id == cid, 30.0, 0)


def pause_moving(kit: Kit) -> None:
    """`PAUSE` while a jog moves: answered once the machine has stopped on the path."""
    link = kit.link
    cid = link.send_command("JOG X -15 300")
    link.wait(lambda r: r.kind == "S" and r.status().state == "JOG", 3.0)
    answer = kit.expect_ok(
        "motion.pause-moving",
        CONV,
        "`O <id> PAUSE` once held (the machine has stopped on the path; a jog is cancelled)",
        "PAUSE",
        timeout=10.0,
    )
    status = link.status()
    kit.check(
        "motion.pause-at-rest-after",
        CONV,
        "after `O PAUSE` nothing moves",
        answer is not None and status is not None and status.state in ("IDLE", "HOLD"),
        "C <id> STATUS",
        str(status),
    )
    link.wait(lambda r: r.kind in "OE" and r.id == cid, 10.0, 0)


def zero(kit: Kit) -> None:
    """ZERO answers the new offset; the old one is put back (jog there, ZERO again).
    Run right after homing, where the position is exact (the answer has 3 decimals)."""
    link = kit.link
    old = [_get(kit, f"OFFSET_{a}") for a in "XYZ"]
    answer = kit.expect_ok(
        "motion.zero",
        CONV,
        "`O <id> ZERO X<off> Y<off> Z<off>` (the new offset, machine mm)",
        "ZERO XYZ",
        lambda info: info.startswith("X") and " Y" in info and " Z" in info,
    )
    if answer is None or None in old:
        return
    new = [float(part[1:]) for part in answer.text.split()]
    got = [_get(kit, f"OFFSET_{a}") for a in "XYZ"]
    kit.check(
        "motion.zero-get-offset",
        CONV,
        "`GET OFFSET_X|Y|Z` is the work offset in machine mm, as `ZERO` answers it",
        got == [round(v, 3) for v in new]
        or all(g is not None and abs(g - v) < 1e-3 for g, v in zip(got, new, strict=True)),
        "C <id> GET OFFSET_X (Y, Z)",
        f"{got} vs {new}",
    )
    for axis, target, here in zip("XYZ", old, new, strict=True):  # machine position now = new offset
        if abs(target - here) > 1e-4:
            link.command(f"JOG {axis} {target - here:.6f} 600", 60.0)
    link.command("ZERO XYZ")
    restored = [_get(kit, f"OFFSET_{a}") for a in "XYZ"]
    kit.check(
        "motion.zero-restored",
        CONV,
        "(the kit puts the work offset back, within 0.001 mm)",
        all(v is not None and abs(v - w) <= 1e-3 for v, w in zip(restored, old, strict=True)),
        "JOG back, C <id> ZERO XYZ",
        f"offset {restored}, before {old}",
    )


def _get(kit: Kit, name: str) -> float | None:
    _, answer = kit.link.command(f"GET {name}")
    try:
        return float(answer.text.split()[1]) if answer is not None and answer.kind == "O" else None
    except (IndexError, ValueError):
        return None


def program_stop(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    link.command("SET AFTERJOB 0")
    lines = ["G00 Z5", "G00 X10 Y10", "M00", "G00 X12", "M06 T2", "G00 X14"]
    status = link.status()
    link.command(f"JOB {len(lines)}")
    start = len(link.replies)
    streamer = Streamer(link, lines, int(status.free) if status else 1, hold_after={2, 4})
    streamer.run(8.0, to_stop=True)
    held = link.wait(lambda r: r.kind == "S" and r.status().has("W"), 20.0, start)
    notice = [r for r in link.since(start) if r.kind == "L" and r.text.startswith("STOP 2 ")]
    kit.check(
        "motion.stop-holds",
        STOPS,
        "at `M00` the machine holds: `S` state `HOLD` with flag `W`, `done` the "
        "seq before the stop line, `L STOP <seq> <line>` once",
        held is not None and held.status().state == "HOLD" and held.status().done == "1" and len(notice) == 1,
        "JOB 6 ... D 2 M00",
        kit.got(start, statuses=True),
    )
    mark = len(link.replies)
    kit.expect_ok("motion.stop-resume", STOPS, "`C <id> RESUME` continues: `O <id> RESUME` at once", "RESUME")
    finished = link.wait(lambda r: r.kind == "F" and r.int(0) >= 2, 20.0, mark)
    kit.check(
        "motion.stop-f-after-resume",
        STOPS,
        "`F <seq>` of the stop line follows the resume",
        finished is not None,
        "C <id> RESUME",
        kit.got(mark),
    )
    streamer.run(8.0, to_stop=True)
    notice = link.wait(lambda r: r.kind == "L" and r.text == "STOP 4 M06 T2", 30.0, mark)
    status = kit.status_until(lambda st: st.has("W"))  # a status from before the notice may be old
    kit.check(
        "motion.tool-change",
        STOPS,
        "`M06`: the spindle stops and Z rises to the top of its travel; `L STOP 4 M06 T2`",
        notice is not None and status is not None and status.has("W") and not status.has("P"),
        "D 4 M06 T2",
        f"{status}; {kit.got(mark)}",
    )
    link.command("RESUME")
    out = streamer.run(40.0)
    kit.check(
        "motion.stops-job-completes",
        STOPS,
        "the job goes on to its end after each `RESUME`",
        out.complete,
        "C <id> RESUME",
        f"F {out.done}",
    )
    link.command("SET AFTERJOB 1")


def after_job(kit: Kit) -> None:
    """`AFTERJOB 1` lifts Z once a job ends (first a job 3 mm down, which ends at the top),
    not once a `JOB <n> MDI` ends (then 3 mm down from there, where it must stay)."""
    link = kit.link
    kit.ensure_idle()
    link.command("SET AFTERJOB 1")
    start = ends = link.status()
    top = None
    for kind in ("", "MDI"):
        if ends is None:
            break
        lines = [f"G01 Z{float(ends.z) - 3.0:.3f} F300"]
        link.command(f"JOB {len(lines)} {kind}".rstrip())
        out = Streamer(link, lines, int(ends.free)).run(30.0)
        top, ends = ends, kit.status_until(lambda st: st.state == "IDLE", 20.0) if out.complete else None
    rose = start is not None and top is not None and float(top.z) > float(start.z) - 3.0 + 0.5
    stayed = ends is not None and top is not None and abs(float(ends.z) - (float(top.z) - 3.0)) < 0.05
    kit.check(
        "motion.after-job",
        "After the job",
        "`AFTERJOB 1`: Z rises to the top once a job's last line has finished; a job opened "
        "with `JOB <lines> MDI` ends where its last line ends",
        rose and stayed,
        "SET AFTERJOB 1; JOB 1: G01 Z<z-3>; JOB 1 MDI: G01 Z<top-3>",
        f"z {start.z if start else '?'}; after the job {top.z if top else '?'}; "
        f"after the MDI job {ends.z if ends else '?'}",
    )


def credit_window(kit: Kit) -> None:
    """A queue with no free slot answers `N expected` instead of `A`."""
    link = kit.link
    kit.ensure_idle()
    link.command("SET AFTERJOB 0")
    status = link.status()
    near = status is not None and float(status.x) < 50  # every move 60 mm long, the first one too
    lines = [f"G01 X{80 if (k % 2 == 0) == near else 20} F60" for k in range(40)]
    link.command(f"JOB {len(lines)}")
    start = len(link.replies)
    seq, free = 0, None
    while seq < len(lines) - 1 and free != 0:
        mark = len(link.replies)
        link.send(f"D {seq} {lines[seq]}")
        ack = link.wait(lambda r, s=seq: (r.kind == "A" and r.int(0) == s) or r.kind == "N", 2.0, mark)
        if ack is None or ack.kind == "N":
            break
        free, seq = ack.int(1), seq + 1
    over, mark = None, len(link.replies)
    if free == 0:
        link.send(f"D {seq} {lines[seq]}")
        over = link.wait(lambda r: r.kind in "AN", 2.0, mark)
    freed = [r for r in link.since(mark) if r.kind == "F"]  # a line finished meanwhile: a slot is free again
    ok = (
        free == 0
        and over is not None
        and (over.kind == "N" and over.int(0) == seq or over.kind == "A" and freed)
    )
    kit.check(
        "motion.credit-window",
        "Errors and resends",
        "with no free slot the machine answers `N expected` "
        "instead of `A` (and the `A` before said `free` 0)",
        ok,
        f"D 0..{seq} of a slow job, past free 0",
        kit.got(max(start, mark - 3), limit=6),
    )
    link.command("STOP", 30.0)
    link.command("SET AFTERJOB 1")


def host_lost_job(kit: Kit) -> None:
    """A job streamed from the host feed-holds when the host is lost; `RESUME FROM` goes on."""
    link = kit.link
    kit.ensure_idle()
    link.command("SET AFTERJOB 0")
    long_feed = max(1, round(60 * 60 / (8.0 * kit.pace)))  # 60 mm that last 8 wall seconds
    lines = ["G00 X30 Y30", f"G01 X90 F{long_feed}", *[f"G01 Y{30 + (k % 3) * 10} F600" for k in range(8)]]
    status = link.status()
    link.command(f"JOB {len(lines)}")
    streamer = Streamer(link, lines[:2], int(status.free) if status else 1)
    streamer.run(1.0)
    holding = lambda r: r.kind == "S" and r.status().state == "HOLD"  # noqa: E731
    start, alarm, after = checks_link.silence(kit, then=holding)
    held = link.wait(holding, 3.0, start)
    lflag = [r for r in link.since(start) if r.kind == "S" and r.status().has("L")]
    kit.check(
        "motion.host-lost-holds-job",
        "Heartbeat, loss and resume",
        "host lost: flag `L`, a job streamed from the host feed-holds on the path",
        alarm is not None and held is not None and bool(lflag),
        "silence during a job",
        kit.got(start, statuses=True, limit=6),
    )
    now = link.status()
    if now is None:
        return
    acc = int(now.acc)
    kit.expect_ok(
        "motion.resume-from-after-loss",
        "Heartbeat, loss and resume",
        "same `boot` after the loss: `RESUME FROM <acc+1>` is accepted, then the missing frames",
        f"RESUME FROM {acc + 1}",
        lambda info: info == f"FROM {acc + 1}",
    )
    rest = Streamer(link, lines, int(now.free))
    rest.next, rest.out.acked, rest.out.done = acc + 1, acc, int(now.done)
    out = rest.run(60.0)
    kit.check(
        "motion.resumed-job-completes",
        "Heartbeat, loss and resume",
        "no line runs twice or is lost: the job ends with `F` of its last line",
        out.complete and out.refused is None,
        f"D {acc + 1}..",
        f"F {out.done}, refused {out.refused}",
    )
    link.command("SET AFTERJOB 1")


def sd_running_file(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    lines = [f"G01 X{20 + (k % 2) * 40} F120" for k in range(20)]
    checks_sd.put(kit, "ck_slow.ngc", lines, checks_sd.crc32(lines))
    _, answer = link.command("SD RUN ck_slow.ngc", 10.0)
    if answer is None or answer.kind != "O":
        kit.check(
            "motion.sd-run", CONV, "`SD RUN` of a real job", False, "C <id> SD RUN ck_slow.ngc", str(answer)
        )
        return
    kit.expect_error(
        "motion.sd-put-running-busy",
        CONV,
        "`SD PUT` of the file an `SD RUN` is running: `BUSY`",
        "SD PUT ck_slow.ngc 1 0",
        "BUSY",
    )
    kit.expect_error(
        "motion.sd-del-running-busy",
        CONV,
        "`SD DEL` of the file an `SD RUN` is running: `BUSY`",
        "SD DEL ck_slow.ngc",
        "BUSY",
    )
    link.command("STOP", 30.0)
    link.wait(lambda r: r.kind == "S" and not r.status().has("S"), 5.0)
    link.command("SD DEL ck_slow.ngc")


CHECKS = [
    home,
    zero,
    jog_and_statuses,
    spindle,
    pause_moving,
    program_stop,
    after_job,
    credit_window,
    host_lost_job,
    sd_running_file,
]
