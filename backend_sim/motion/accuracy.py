"""Run device-dialect lines through a ``MotionController`` and measure how well it follows.

Contract: ``run_lines(lines, mode=..., profile=...)`` homes a fresh controller, feeds the
lines as the CNC MCU would (parse, enqueue while slots are free), records the encoder-
measured position every 1 ms (``ctl.trace``), and returns a ``JobResult``: job time,
contour error (distance of each measured point from the programmed path: lines exact,
arcs chorded to 1 um; max and RMS), final position error and any alarms. Used by tests and the bench;
never by the simulator itself.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from backend_sim.motion.controller import MotionController
from backend_sim.motion.dialect import DialectParser
from backend_sim.motion.events import Alarm, Finished
from backend_sim.motion.geometry import Segment


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


def run_lines(lines, mode: str = "planner", profile=None, limit_s: float = 3600.0,
              chunk_ms: int = 20) -> JobResult:
    """Home a fresh controller, run ``lines`` (device dialect, work mm) and measure."""
    ctl = MotionController(profile, mode=mode, start_mm=(0.0, 0.0, 30.0))
    home(ctl)
    parser = DialectParser(ctl.profile.travel.work_offset(), ctl.commanded_mm)
    start = ctl.commanded_mm
    moves = [parser.parse(seq, line) for seq, line in enumerate(lines)]
    trace: list = []
    ctl.trace = trace.append
    alarms, finished, t0, nxt = [], [], ctl.now_ms, 0
    while (nxt < len(moves) or not ctl.idle()) and ctl.now_ms - t0 < limit_s * 1000:
        while nxt < len(moves) and ctl.free_slots() > 0 and ctl.state != "ALARM":
            ctl.enqueue(moves[nxt])
            nxt += 1
        ctl.advance(chunk_ms)
        for ev in ctl.events():
            if isinstance(ev, Alarm):
                alarms.append(ev)
            elif isinstance(ev, Finished):
                finished.append((ev.at_ms - t0 - 1, ev.seq))
        if ctl.state == "ALARM":
            break
    ctl.trace = None
    offsets = np.array([a[6] for a in ctl.axes])  # servo.STATE "off"
    measured = np.array(trace) / ctl.model.counts_per_mm + offsets
    done = np.full(len(measured), -1)
    for tick, seq in finished:  # sample index -> last move finished by then
        done[max(0, tick):] = seq
    return _result(ctl, moves, polylines(moves, start), measured, done, alarms, ctl.now_ms - t0)


def polylines(moves, start) -> list[np.ndarray]:
    """Per move, its programmed path as points (arcs chorded to 1 um), machine mm."""
    out, pos = [], tuple(start)
    for m in moves:
        if m.moves_axes:
            out.append(np.array(Segment.from_move(pos, m).chords(0.001)))
            pos = m.target
        else:
            out.append(np.array([pos, pos]))
    return out


def _result(ctl, moves, paths, measured, done, alarms, job_ms) -> JobResult:
    end = np.array(paths[-1][-1])
    final = np.array(ctl.measured_mm) - end
    final_true = np.array(ctl.true_mm) - end
    err = contour_errors(measured, done, paths) if len(measured) else np.zeros(1)
    return JobResult(
        job_s=job_ms / 1000.0,
        contour_max_mm=float(err.max()),
        contour_rms_mm=float(np.sqrt(np.mean(err**2))),
        final_error_mm=float(np.abs(final_true).max()),
        final_error_counts=float(np.abs(final).max() * ctl.model.counts_per_mm),
        alarms=alarms,
        lines=len(moves),
    )


def contour_errors(points: np.ndarray, done: np.ndarray, paths: list[np.ndarray],
                   window: int = 8) -> np.ndarray:
    """Distance of each point from the programmed path near the move it was executing.

    ``done[i]`` is the last move finished when point ``i`` was measured; the point is
    compared with moves ``done+1-window .. done+1+window`` (the tool lags the setpoint
    by far less than that). Leaving distant moves out can only raise a distance, so
    the result errs on the safe side.
    """
    out = np.empty(len(points))
    n = len(paths)
    for d in np.unique(done):
        mask = done == d
        lo, hi = max(0, d + 1 - window), min(n, d + 2 + window)
        a = np.concatenate([p[:-1] for p in paths[lo:hi]])
        b = np.concatenate([p[1:] for p in paths[lo:hi]])
        q = points[mask]
        a, b = _near(q, a, b, margin=float(_distance(q[:1], a, b)[0]) + 0.5)
        out[mask] = _distance(q, a, b)
    return out


def _near(q: np.ndarray, a: np.ndarray, b: np.ndarray, margin: float):
    """The segments whose bounding box comes within ``margin`` of the points' box.

    A point further than ``margin`` from every segment may lose its nearest one and so
    report a larger distance: the pruning can only err on the safe side."""
    lo, hi = q.min(0) - margin, q.max(0) + margin
    keep = np.all((np.minimum(a, b) <= hi) & (np.maximum(a, b) >= lo), axis=1)
    return (a[keep], b[keep]) if keep.any() else (a, b)


def _distance(p: np.ndarray, a: np.ndarray, b: np.ndarray, chunk: int = 512) -> np.ndarray:
    """Distance of each point from the nearest of the segments a->b."""
    ab = b - a
    den = np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-18)
    out = np.empty(len(p))
    for s in range(0, len(p), chunk):
        q = p[s:s + chunk, None, :]
        t = np.clip(np.einsum("pij,ij->pi", q - a[None], ab) / den, 0.0, 1.0)
        out[s:s + chunk] = np.sqrt(((q - (a[None] + t[..., None] * ab[None])) ** 2).sum(-1).min(1))
    return out
