"""Runs the sections of checks in order against one port and collects the results.

``run(port, quick=False, sections=None, cover=None)`` -> list of ``Result``. A check
that raises is a failure naming the exception (a firmware that answers nothing must
not hang or crash the kit); a dead port ends the run with a failure saying so.
``--quick`` leaves out what needs homing and real motion (`motion`, `jog`) (a few seconds in all).
``cover(open)`` opens or closes the cover when the port can (the simulator's panel
through ``sim://``); without it the cover's rules are reported as not checkable.
"""

from __future__ import annotations

import traceback

from app.comm.conformance import (
    checks_commands,
    checks_cover,
    checks_errors,
    checks_frames,
    checks_jog,
    checks_link,
    checks_motion,
    checks_noisy,
    checks_overrides,
    checks_realtime,
    checks_resume,
    checks_sd,
    checks_stream,
    checks_touch_off,
)
from app.comm.conformance.kit import Kit
from app.comm.conformance.link import Link, LinkDead
from app.comm.conformance.result import FAIL, Result

SECTIONS = {
    "frames": checks_frames.CHECKS,
    "commands": checks_commands.CHECKS,
    "errors": checks_errors.CHECKS,
    "stream": checks_stream.CHECKS,
    "resume": checks_resume.CHECKS,
    "sd": checks_sd.CHECKS,
    "link": checks_link.CHECKS,
    "cover": checks_cover.CHECKS,
    "motion": checks_motion.CHECKS + checks_touch_off.CHECKS,
    "realtime": checks_realtime.CHECKS,
    "overrides": checks_overrides.OVERRIDES,
    "systems": checks_overrides.SYSTEMS,
    "jog": checks_jog.CHECKS,
    "noisy": checks_noisy.CHECKS,
}
SLOW = {"motion", "jog"}
FINAL = [checks_frames.every_frame_well_formed, checks_link.no_false_host_lost, checks_realtime.why_field]


def run(
    port, quick: bool = False, sections: list[str] | None = None, cover=None, progress=None
) -> list[Result]:
    kit = Kit(Link(port), quick=quick, cover=cover)
    chosen = [
        name
        for name in SECTIONS
        if (sections is None or name in sections) and not (quick and name in SLOW and sections is None)
    ]
    checks_frames.codec(kit)
    if kit.results[-1].outcome == FAIL:
        return kit.results
    try:
        for name in chosen:
            for check in SECTIONS[name]:
                if progress is not None:
                    progress(f"{name}: {check.__name__}")
                _run_one(kit, name, check)
        for check in FINAL:
            check(kit)
    except LinkDead as exc:
        kit.results.append(
            Result("kit.link", "Frames", "the port stays open for the whole run", FAIL, note=str(exc))
        )
    return kit.results


def _run_one(kit: Kit, section: str, check) -> None:
    try:
        check(kit)
    except LinkDead:
        raise
    except Exception as exc:  # noqa: BLE001 - a broken answer must not end the run
        where = traceback.extract_tb(exc.__traceback__)[-1]
        kit.results.append(
            Result(
                f"{section}.{check.__name__}",
                section,
                "the check runs to its end",
                FAIL,
                got=f"{type(exc).__name__}: {exc}",
                note=f"the kit stopped at {where.name}:{where.lineno} on an answer it could not read",
            )
        )
