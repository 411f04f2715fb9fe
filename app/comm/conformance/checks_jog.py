"""Checks of "Continuous jog (hold-to-jog)": the dead man, keep-alives, `JOGEND`, the
strict grammar, `BUSY` with a job open or a change of direction.

The machine moves (a few millimetres), so the section is left out by ``--quick``. A
machine whose clock runs faster than the wall (a simulator at ``speed`` > 1) cannot be
kept alive from a host reading in 10 ms slices: the checks that hold a jog for longer
than the dead man are then reported as not checkable.
"""

from __future__ import annotations

from app.comm.conformance.kit import Kit
from app.comm.conformance.wire import Reply

JOG = "Continuous jog (hold-to-jog)"
KEEP_EVERY_S = 0.025  # "the host sends a new `R JOG` every 25 ms, two copies back to back"
STOP_WITHIN_S = 1.5  # 250 ms of the dead man, the deceleration, a busy host's reading
HOLD_S = 0.6  # how long the kit holds the key: more than twice the dead man
DEAD_MAN_S = 0.25
TRAVEL_FEED = 600.0  # mm/min in the machine's time


def _feed(kit: Kit) -> int:
    return max(1, round(TRAVEL_FEED / kit.pace))


def _start(kit: Kit, dirs: str) -> tuple[Reply | None, str]:
    """Start a jog along ``dirs`` (or its opposite at an edge): the answer, and the
    direction it was asked for."""
    _, answer = kit.link.realtime(f"JOG {dirs} {_feed(kit)}")
    if answer is not None and answer.kind == "E" and answer.fields[1] == "SOFT_LIMIT":
        dirs = dirs.replace("+", "-")
        _, answer = kit.link.realtime(f"JOG {dirs} {_feed(kit)}")
    return answer, dirs


def _held_start(kit: Kit, cid: str, rule: str, dirs: str) -> tuple[int, Reply | None, str] | None:
    """For a check that holds a jog with keep-alives: the reply index before it, the
    start's answer and direction; None (the check listed as not checkable) when the
    machine's clock runs too fast for keep-alives."""
    if kit.pace > 1.5:
        kit.skip(cid, JOG, rule, _too_fast(kit))
        return None
    kit.ensure_idle()
    start = len(kit.link.replies)
    return (start, *_start(kit, dirs))


def _idle_within(kit: Kit, seconds: float) -> bool:
    status = kit.status_until(lambda st: st.state == "IDLE", seconds)
    return status is not None and status.state == "IDLE"


def _dead_man_said(kit: Kit, start: int) -> bool:
    return any(r.kind == "L" and "no keep-alive" in r.text for r in kit.link.since(start))


def dead_man(kit: Kit) -> None:
    """A jog that hears no keep-alive stops by itself and says so."""
    kit.ensure_idle()
    before = kit.link.status()
    start = len(kit.link.replies)
    answer, dirs = _start(kit, "X+")
    started = answer is not None and answer.kind == "O" and answer.fields[1] == "JOG"
    said = kit.link.wait(lambda r: r.kind == "L" and "no keep-alive" in r.text, STOP_WITHIN_S, start)
    if answer is not None and said is not None:  # 250 ms of the machine's clock: its pace
        kit.pace = max(kit.pace, DEAD_MAN_S / max(said.t - answer.t, 1e-3))
    stopped = _idle_within(kit, STOP_WITHIN_S)
    after = kit.link.status()
    moved = before is not None and after is not None and abs(float(after.x) - float(before.x)) > 0.001
    kit.check(
        "jog.dead-man",
        JOG,
        "a continuous jog that hears no `JOG` for 250 ms decelerates and stops by itself, and "
        "the CNC MCU sends `L jog stopped: no keep-alive for 250 ms`",
        started and said is not None and stopped and moved,
        f"R <id> JOG {dirs} {_feed(kit)}, then nothing",
        kit.got(start),
    )


def keep_alive_and_end(kit: Kit) -> None:
    """Keep-alives every 25 ms hold the jog; `JOGEND` ends it, answered."""
    held = _held_start(kit, "jog.keep-alive", "keep-alives hold the jog", "Y+")
    if held is None:
        return
    start, answer, dirs = held
    ended_early = _hold(kit, dirs, HOLD_S)
    cid, end = kit.link.realtime("JOGEND")
    stopped = _idle_within(kit, STOP_WITHIN_S)
    kit.check(
        "jog.keep-alive",
        JOG,
        "a `JOG` with the same `dirs` while that jog runs keeps it alive (answered the same)",
        answer is not None and answer.kind == "O" and not ended_early and not _dead_man_said(kit, start),
        f"R <id> JOG {dirs} {_feed(kit)} every 25 ms for {HOLD_S} s (two copies each)",
        kit.got(start),
    )
    kit.check(
        "jog.jogend",
        JOG,
        "`JOGEND` ends a continuous jog: `O <id> JOGEND <state>`, the machine at rest",
        end is not None and end.kind == "O" and end.fields[1] == "JOGEND" and stopped,
        f"R {cid} JOGEND",
        kit.got(start),
    )


def _hold(kit: Kit, dirs: str, seconds: float) -> bool:
    """Send keep-alives for ``seconds`` as a host holding the key does; True when a
    keep-alive was refused or the machine left `JOG` (the jog ended early)."""
    link = kit.link
    deadline = link.clock() + seconds
    ended = False
    while link.clock() < deadline:
        cid = link.new_id()
        start = len(link.replies)
        frame = f"R {cid} JOG {dirs} {_feed(kit)}"
        sent = link.clock()
        link.send(frame)
        link.send(frame)
        answer = link.wait(lambda r, cid=cid: r.kind in "OE" and r.id == cid, KEEP_EVERY_S, start)
        ended |= answer is not None and (answer.kind == "E" or answer.text != "JOG")
        link.idle(max(0.0, sent + KEEP_EVERY_S - link.clock()))
    return ended


def change_of_direction(kit: Kit) -> None:
    """A `JOG` with other `dirs` while one runs ends it and is refused `BUSY`."""
    held = _held_start(kit, "jog.change-of-direction", "a new direction is refused `BUSY`", "X+")
    if held is None:
        return
    start, answer, dirs = held
    cid, other = kit.link.realtime(f"JOG Z- {_feed(kit)}")
    stopped = _idle_within(kit, STOP_WITHIN_S)
    kit.check(
        "jog.change-of-direction",
        JOG,
        "a `JOG` with other `dirs` while a continuous jog runs ends it (as `JOGEND`) and is "
        "refused `BUSY jog changes direction`",
        answer is not None
        and answer.kind == "O"
        and other is not None
        and other.kind == "E"
        and other.fields[1] == "BUSY"
        and stopped,
        f"R <id> JOG {dirs} {_feed(kit)}, R {cid} JOG Z- {_feed(kit)}",
        kit.got(start),
    )


def busy_with_job(kit: Kit) -> None:
    kit.ensure_idle()
    kit.check_mode(True)
    kit.link.command("JOB 2")
    start = len(kit.link.replies)
    cid, answer = kit.link.realtime(f"JOG X+ {_feed(kit)}")
    kit.check(
        "jog.busy-with-job",
        JOG,
        "a `JOG` starts only in `IDLE` with no job open: refused `E <id> BUSY` otherwise",
        answer is not None and answer.kind == "E" and answer.fields[1] == "BUSY",
        f"JOB 2 (check mode), R {cid} JOG X+ {_feed(kit)}",
        kit.got(start),
    )
    kit.link.command("STOP")
    kit.check_mode(False)


BAD_FRAMES = (
    ("axis-twice", "JOG X+X- 600"),
    ("three-axes", "JOG X+Y+Z+ 600"),
    ("unknown-axis", "JOG W+ 600"),
    ("no-sign", "JOG X 600"),
    ("zero-feed", "JOG X+ 0"),
    ("negative-feed", "JOG X+ -600"),
    ("no-feed", "JOG X+"),
    ("jog-with-why", "JOG X+ 600 HOST"),
    ("jogend-with-why", "JOGEND HOST"),
)


def grammar(kit: Kit) -> None:
    """Every malformed jog frame is a bad frame: no answer, nothing moves."""
    kit.ensure_idle()
    before = kit.link.status()
    sent = send_bad_frames(kit, BAD_FRAMES)
    after = kit.link.status()
    still = (
        before is not None
        and after is not None
        and after.state == "IDLE"
        and (after.x, after.y, after.z) == (before.x, before.y, before.z)
    )
    for name, (cid, text, answer) in sent.items():
        kit.check(
            f"jog.{name}-dropped",
            JOG,
            "grammar, strict: `dirs` is one or two of `X+ X- Y+ Y- Z+ Z-`, each axis once; "
            "`feed` above 0; no `why`; anything else is a bad frame, never carried out",
            answer is None and still,
            f"R {cid} {text}",
            f"{answer or '(no answer)'}; position {before} -> {after}",
        )


def send_bad_frames(kit: Kit, frames) -> dict[str, tuple[int, str, Reply | None]]:
    """Send every ``(name, text)`` as `R <id> text` (one id each), then listen 0.3 s:
    {name: (id, text, the answer to that id or None)}."""
    link = kit.link
    start = len(link.replies)
    ids = {}
    for name, text in frames:
        cid = link.new_id()
        link.send(f"R {cid} {text}")
        ids[name] = (cid, text)
    link.idle(0.3)
    answers = {r.id: r for r in link.since(start) if r.kind in "OE"}
    return {name: (cid, text, answers.get(cid)) for name, (cid, text) in ids.items()}


def _too_fast(kit: Kit) -> str:
    return (
        f"the machine's clock runs {kit.pace:.1f} times the wall clock: a host cannot send "
        "keep-alives often enough to hold a jog (run the machine at speed 1)"
    )


CHECKS = [grammar, busy_with_job, dead_man, keep_alive_and_end, change_of_direction]
