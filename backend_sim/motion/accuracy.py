"""Run device-dialect lines through a ``MotionController`` and measure how well it follows.

Contract: ``run_lines(lines, mode=..., profile=...)`` homes a fresh controller, feeds the
lines as the CNC MCU would (parse, enqueue while slots are free), records the encoder-
measured position every 1 ms, and returns a ``JobResult``: job time, contour error
(distance of each measured point from the programmed path: lines exact, arcs chorded
to 1 um; max and RMS), final position error and any alarms. Used by tests and the bench;
never by the simulator itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from backend_sim.motion.controller import MotionController
from backend_sim.motion.dialect import DialectParser
from backend_sim.motion.events import Alarm, Finished
from backend_sim.motion.geometry import Segment

_WINDOW = 6  # moves either side of the one being executed that may be nearest


@dataclass
class JobResult:
    job_s: float
    contour_max_mm: float
    contour_rms_mm: float
    final_error_mm: float
    final_error_counts: float
    alarms: list = field(default_factory=list)
    lines: int = 0


def home(ctl: MotionController, limit_ms: int = 200_000) -> None:
    ctl.home()
    for _ in range(limit_ms // 10):
        ctl.advance(10)
        if ctl.homed and ctl.state == "IDLE":
            ctl.events()
            return
    raise RuntimeError(f"homing did not finish: {ctl.events()}")


def run_lines(lines, mode: str = "planner", profile=None, record: bool = True,
              limit_s: float = 3600.0) -> JobResult:
    ctl = MotionController(profile, mode=mode, start_mm=(0.0, 0.0, 30.0))
    home(ctl)
    parser = DialectParser(ctl.profile.travel.work_offset(), ctl.commanded_mm)
    moves = [parser.parse(seq, line) for seq, line in enumerate(lines)]
    polylines = _polylines(moves, ctl.commanded_mm)
    samples, seqs, alarms = [], [], []
    t0, nxt, done = ctl.now_ms, 0, -1
    while (nxt < len(moves) or not ctl.idle()) and ctl.now_ms - t0 < limit_s * 1000:
        while nxt < len(moves) and ctl.free_slots() > 0 and ctl.state != "ALARM":
            ctl.enqueue(moves[nxt])
            nxt += 1
        ctl.advance(1)
        for ev in ctl.events():
            if isinstance(ev, Finished):
                done = ev.seq
            elif isinstance(ev, Alarm):
                alarms.append(ev)
        if ctl.state == "ALARM":
            break
        if record:
            samples.append(ctl.measured_mm)
            seqs.append(done)
    return _result(ctl, moves, polylines, samples, seqs, alarms, ctl.now_ms - t0)


def _polylines(moves, start) -> list[np.ndarray]:
    """Per move, its programmed path as points (arcs chorded to 1 um)."""
    out, pos = [], tuple(start)
    for m in moves:
        if m.moves_axes:
            out.append(np.array(Segment.from_move(pos, m).chords(0.001)))
            pos = m.target
        else:
            out.append(np.array([pos, pos]))
    return out


def _result(ctl, moves, polylines, samples, seqs, alarms, job_ms) -> JobResult:
    end = np.array(moves[-1].target if moves else ctl.commanded_mm)
    final = np.array(ctl.measured_mm) - end
    final_true = np.array(ctl.true_mm) - end
    err = contour_errors(np.array(samples), np.array(seqs), polylines) if samples else np.zeros(1)
    return JobResult(
        job_s=job_ms / 1000.0,
        contour_max_mm=float(err.max()),
        contour_rms_mm=float(np.sqrt(np.mean(err**2))),
        final_error_mm=float(np.abs(final_true).max()),
        final_error_counts=float(np.abs(final).max() * ctl.model.counts_per_mm),
        alarms=alarms,
        lines=len(moves),
    )


def contour_errors(points: np.ndarray, seqs: np.ndarray, polylines: list[np.ndarray]) -> np.ndarray:
    """Distance of each point from the path of the moves near the one it was executing."""
    out = np.empty(len(points))
    n = len(polylines)
    for d in np.unique(seqs):
        mask = seqs == d
        lo, hi = max(0, d + 1 - _WINDOW), min(n, d + 2 + _WINDOW)
        segs_a = np.concatenate([p[:-1] for p in polylines[lo:hi]])
        segs_b = np.concatenate([p[1:] for p in polylines[lo:hi]])
        out[mask] = _distance(points[mask], segs_a, segs_b)
    return out


def _distance(p: np.ndarray, a: np.ndarray, b: np.ndarray, chunk: int = 2048) -> np.ndarray:
    ab = b - a
    den = np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-18)
    out = np.empty(len(p))
    for s in range(0, len(p), chunk):
        q = p[s:s + chunk, None, :]
        t = np.clip(np.einsum("pij,ij->pi", q - a[None], ab) / den, 0.0, 1.0)
        nearest = a[None] + t[..., None] * ab[None]
        out[s:s + chunk] = np.sqrt(((q - nearest) ** 2).sum(-1)).min(1)
    return out
