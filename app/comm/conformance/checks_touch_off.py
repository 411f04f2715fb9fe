"""The touch-off at a tool change (docs/protocol.md, "Program stops and tool changes"):
at an `M06` hold a `JOG` and a `ZERO Z` are taken, another motion command is `BUSY`,
and `RESUME` returns to the held X Y (Z up first) and to the held work Z under the new
offset before the next line. Part of the `motion` section; the kit puts back the work
offset and `AFTERJOB` it changes."""

from __future__ import annotations

from app.comm.conformance.checks_motion import STOPS, _get
from app.comm.conformance.kit import Kit
from app.comm.conformance.stream import Streamer

CUT_Z = 2.0  # the work Z where the stop line is reached
LINES = ["G00 Z5", "G00 X10 Y10", f"G01 Z{CUT_Z:g} F300", "M06 T2", "G04 P1", "G01 X12 F300"]
STOP, DOWN_MM, AWAY_MM, TOL = 3, 3.0, 2.0, 0.05


def touch_off(kit: Kit) -> None:
    link = kit.link
    kit.ensure_idle()
    link.command("SET AFTERJOB 0")
    old_z = _get(kit, "OFFSET_Z")
    status = link.status()
    link.command(f"JOB {len(LINES)}")
    streamer = Streamer(link, LINES, int(status.free) if status else 1, hold_after={STOP})
    streamer.run(20.0, to_stop=True)
    held = kit.status_until(lambda st: st.has("W"), 20.0)
    if held is None or not held.has("W") or old_z is None:
        kit.check("motion.touch-off", STOPS, "a tool change holds (flag `W`)", False, "JOB ... M06 T2",
                  str(held))
        link.command("STOP", 30.0)
        return
    hx, hy, hz = float(held.x), float(held.y), float(held.z)
    _taken_at_stop(kit, hz)
    zero = kit.expect_ok(
        "motion.touch-off-zero",
        STOPS,
        "`ZERO <axes>` is taken at a program stop",
        "ZERO Z",
        lambda info: " Z" in info,
    )
    new_z = float(zero.text.split()[-1][1:]) if zero is not None else old_z
    link.command(f"JOG X {AWAY_MM:g} 600", 60.0)
    _returns(kit, streamer, (hx, hy, hz), new_z - old_z)
    out = streamer.run(40.0)
    ends = kit.status_until(lambda st: st.state == "IDLE", 20.0)
    cut = ends is not None and abs(float(ends.z) - CUT_Z) < TOL and abs(float(ends.x) - 12.0) < TOL
    kit.check(
        "motion.touch-off-new-offset",
        STOPS,
        "after a new Z zero at a stop the rest of the job runs in work coordinates under "
        "the new offset",
        out.complete and cut,
        "G01 X12 F300 after the stop",
        f"F {out.done}; {ends}",
    )
    if ends is not None:  # put the work offset back: machine Z = old offset, ZERO Z
        link.command(f"JOG Z {old_z - (float(ends.z) + new_z):.4f} 600", 60.0)
        link.command("ZERO Z")
    link.command("SET AFTERJOB 1")


def _taken_at_stop(kit: Kit, hz: float) -> None:
    """A jog is taken at the hold (state `HOLD` with `W` again after it), `SPINDLE` is not."""
    kit.expect_error(
        "motion.touch-off-busy", STOPS, "at a program stop every other motion command stays `BUSY`",
        "SPINDLE 1000", "BUSY",
    )
    jog = kit.expect_ok(
        "motion.touch-off-jog",
        STOPS,
        "`JOG` is taken at a program stop: `O <id> JOG <axis> <dist>` when it ends",
        f"JOG Z -{DOWN_MM:g} 600",
        lambda info: info == f"Z -{DOWN_MM:g}",
        timeout=60.0,
    )
    after = kit.status_until(lambda st: st.state == "HOLD" and st.has("W"))
    kit.check(
        "motion.touch-off-holds-again",
        STOPS,
        "after the jog the machine holds at the stop again (`HOLD` with `W`), the tool where the jog left it",
        jog is not None and after is not None and after.state == "HOLD" and after.has("W")
        and abs(float(after.z) - (hz - DOWN_MM)) < TOL,
        "C <id> STATUS",
        str(after),
    )


def _returns(kit: Kit, streamer: Streamer, held, delta_z: float) -> None:
    """RESUME: Z up to the top first, X Y back, Z down to the held work Z (new offset)."""
    link = kit.link
    hx, hy, hz = held
    top = hz - delta_z  # the top of the travel, in work Z under the new offset
    start = len(link.replies)
    link.command("RESUME")
    link.wait(lambda r: r.kind == "F" and r.int(0) >= STOP, 60.0, start)
    statuses = [r.status() for r in link.since(start) if r.kind == "S"]
    back = kit.status_until(lambda st: int(st.done) >= STOP and abs(float(st.x) - hx) < TOL, 5.0)
    moving_x = [st for st in statuses if hx + TOL < float(st.x) < hx + AWAY_MM - TOL and int(st.done) < STOP]
    lifted = bool(moving_x) and all(float(st.z) > min(top, hz) - TOL for st in moving_x)
    at = back is not None and abs(float(back.y) - hy) < TOL and abs(float(back.z) - CUT_Z) < TOL
    kit.check(
        "motion.touch-off-return",
        STOPS,
        "`RESUME` at a stop first returns to the held position: Z up to the top, X Y, "
        "Z down to the held work Z under the offset in force at `RESUME` (an `M06` holds at the "
        "top), then down to where the stop line was reached, before the next line",
        lifted and at,
        f"JOG Z -{DOWN_MM:g}, ZERO Z, JOG X {AWAY_MM:g}, C <id> RESUME",
        f"{back}; X moved at z {[st.z for st in moving_x][:6]}",
    )


CHECKS = [touch_off]
