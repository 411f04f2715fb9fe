"""Look-ahead planner and 1 ms interpolator (the "planner" mode of the CNC MCU).

Contract: ``add(move)`` queues a parsed ``Move`` (geometry from the end of the previous
one); ``step()`` advances 1 ms and returns the setpoint (x, y, z) in machine mm, which
always lies on the programmed path. ``hold()`` decelerates along the path and stops;
``resume()`` continues; ``flush()`` drops the queue (only at rest).

How: every queued block gets a nominal speed (feed, arc radius) and a junction speed
with its predecessor (junction deviation). A backward pass over the queue gives each
block the largest entry speed from which the rest of the queue can still stop. A raw
path distance ``s`` then runs a trapezoid online (accelerate at ``a``, never above
``sqrt(v_exit^2 + 2 a d)``), and a moving average of ``s`` over ``a/jerk`` seconds
makes it an S-curve with jerk <= ``jerk``. Smoothing ``s`` rather than x, y, z keeps
every setpoint on the path. Non-motion moves (dwell, spindle, end) are barriers: the
path stops there, the action runs, then the path continues.

Overrides (docs/protocol.md, "Overrides"): ``set_scales(feed, rapid)`` scales the
nominal speed of every block not yet finished, the one under way included, and re-runs
the junctions and the backward pass; a speed now above the new plan comes down at the
acceleration (no stop, no jump).
"""

from __future__ import annotations

import math

from backend_sim.motion.dialect import Move
from backend_sim.motion.geometry import Segment, junction_speed
from backend_sim.motion.hold import FeedHold

_EPS = 1e-9


class Block:
    __slots__ = ("move", "seg", "s0", "s1", "v_nom", "v_junc", "v_entry", "barrier", "coef", "arc",
                 "v_cap", "vj_geom", "prev")

    def __init__(self, move: Move, seg: Segment | None, s0: float):
        self.move, self.seg, self.s0 = move, seg, s0
        self.barrier = seg is None
        self.s1 = s0 + (seg.length if seg else 0.0)
        self.v_nom = self.v_junc = self.v_entry = 0.0
        self.coef = seg.coef if seg else None
        self.arc = bool(seg and seg.arc)
        self.v_cap = self.vj_geom = 0.0  # arc limit; geometric junction speed
        self.prev = None  # the block it joins (None: starts from rest)


class Planner(FeedHold):
    """Queue of blocks plus the online S-curve generator; see the module docstring."""

    def __init__(self, profile, ctx, events: list, position=(0.0, 0.0, 0.0)):
        mo = profile.motion
        self.accel = mo.accel_mm_s2
        self.deviation = mo.junction_deviation_mm
        self.rapid = mo.rapid_mm_min / 60.0
        self.max_feed = mo.max_feed_mm_min / 60.0
        self.vmax = max(self.rapid, self.max_feed)
        self.window = max(1, round(mo.accel_mm_s2 / mo.jerk_mm_s3 * 1000))
        self.ctx, self.events = ctx, events
        self.blocks: list[Block] = []
        self.holding = False
        self.feed_scale = self.rapid_scale = 1.0
        self.braking = False  # an override lowered the plan under the current speed
        self.reset_position(position)

    # -- queue -------------------------------------------------------------
    def reset_position(self, position) -> None:
        """Forget everything; the setpoint becomes ``position`` (at rest)."""
        self.blocks.clear()
        self.pos = self.tail = tuple(float(v) for v in position)
        self.s_raw = self.v_raw = 0.0
        self.raw = 0
        self.buf = [0.0] * self.window
        self.idx, self.sum, self.still, self.s_prev = 0, 0.0, self.window, 0.0
        self.s_tail = 0.0
        self.barrier_ms = 0
        self.held_flag = True
        self.holding = False
        self.braking = False

    def __len__(self) -> int:
        return len(self.blocks)

    def queued_moves(self) -> list[Move]:
        """The moves not yet finished, the one under way first."""
        return [b.move for b in self.blocks]

    def add(self, move: Move) -> None:
        seg = Segment.from_move(self.tail, move) if move.moves_axes else None
        block = Block(move, seg, self.s_tail)
        if seg is not None:
            if seg.length < 1e-6:  # zero length: transparent, finishes without stopping the path
                block.v_nom = block.v_junc = math.inf
            else:
                self._speeds(block)
            self.tail = move.target
        self.blocks.append(block)
        self.s_tail = block.s1
        self._backward_pass()

    def _speeds(self, block: Block) -> None:
        seg = block.seg
        block.v_cap = math.sqrt(self.accel * seg.radius) if seg.arc else math.inf
        prev = next((b for b in reversed(self.blocks) if b.barrier or b.s1 > b.s0), None)
        if prev is not None and not prev.barrier:
            block.prev = prev
            block.vj_geom = junction_speed(prev.seg, seg, self.accel, self.deviation)
        self._nominal(block)

    def _nominal(self, block: Block) -> None:
        """``v_nom`` and ``v_junc`` of ``block`` under the current override scales."""
        move = block.move
        if move.kind == "rapid":
            v = self.rapid * self.rapid_scale
        else:
            v = min(move.feed / 60.0 * self.feed_scale, self.max_feed)
        block.v_nom = v = min(v, block.v_cap)
        prev = block.prev
        block.v_junc = 0.0 if prev is None else min(block.vj_geom, v, prev.v_nom)

    def set_scales(self, feed: float, rapid: float) -> None:
        """Overrides: re-plan every block from the one under way on (see the docstring)."""
        self.feed_scale, self.rapid_scale = feed, rapid
        for b in self.blocks[self.raw:]:
            if b.seg is not None and b.v_nom != math.inf:
                self._nominal(b)
        self._backward_pass()
        self.braking = True

    def _backward_pass(self) -> None:
        nxt = 0.0
        for k in range(len(self.blocks) - 1, self.raw, -1):
            b = self.blocks[k]
            if b.barrier:
                b.v_entry = nxt = 0.0
                continue
            b.v_entry = nxt = min(b.v_junc, math.sqrt(nxt * nxt + 2 * self.accel * (b.s1 - b.s0)))

    # -- control -------------------------------------------------------------
    def at_rest(self) -> bool:
        return self.v_raw == 0.0 and self.still >= self.window

    def idle(self) -> bool:
        return not self.blocks and self.at_rest()

    def just_held(self) -> bool:
        """True once when a hold has brought the setpoint to rest."""
        if self.holding and not self.held_flag and self.at_rest():
            self.held_flag = True
            return True
        return False

    # -- 1 ms ------------------------------------------------------------------
    def step(self):
        blocks = self.blocks
        if not blocks and self.still >= self.window:
            return self.pos
        if blocks:
            self._raw_step(blocks)
        s = self._smooth()
        while blocks:
            b = blocks[0]
            if b.barrier:
                if self.still >= self.window and self._barrier_done(b):
                    self._finish()
                    continue
                return self.pos
            if s < b.s1 - _EPS:
                self.pos = self._point(b, s - b.s0)
                return self.pos
            self.pos = b.seg.end if b.seg else self.pos
            self._finish()
        return self.pos

    def _finish(self) -> None:
        b = self.blocks.pop(0)
        self.raw = max(0, self.raw - 1)
        if b.seg is not None and b.move.moves_axes:
            self.pos = b.seg.end
        if b.move.seq >= 0:
            self.ctx.finished(b.move)

    @staticmethod
    def _point(b: Block, d: float):
        c = b.coef
        if b.arc:
            ang = c[4] + c[5] * d
            return (c[0] + c[3] * math.cos(ang), c[1] + c[3] * math.sin(ang), c[2] + c[6] * d)
        return (c[0] + c[3] * d, c[1] + c[4] * d, c[2] + c[5] * d)

    def _raw_step(self, blocks: list[Block]) -> None:
        i = self.raw
        b = blocks[i]
        if b.barrier:
            self.v_raw = 0.0
            return
        nxt = blocks[i + 1] if i + 1 < len(blocks) else None
        exit_v = nxt.v_entry if nxt is not None else 0.0
        rem = b.s1 - self.s_raw
        allow = math.sqrt(exit_v * exit_v + 2.0 * self.accel * rem) if rem > 0 else exit_v
        dv = self.accel * 1e-3
        v = self.v_raw - dv if self.holding else self.v_raw + dv
        v = min(v, b.v_nom, allow)
        if self.braking and not self.holding:  # over a lowered plan: brake, never jump
            self.braking = v < self.v_raw - dv
            v = max(v, self.v_raw - dv)
        if v <= 0.0:
            self.v_raw = 0.0
            return
        s = self.s_raw + v * 1e-3
        while s >= b.s1:
            if nxt is None or nxt.barrier:
                s, v = b.s1, 0.0
                if nxt is not None:
                    i += 1
                break
            i += 1
            b = nxt
            nxt = blocks[i + 1] if i + 1 < len(blocks) else None
        self.raw, self.s_raw, self.v_raw = i, s, v

    def _smooth(self) -> float:
        s = self.s_raw
        idx = self.idx
        old = self.buf[idx]
        self.buf[idx] = s
        self.idx = idx + 1 if idx + 1 < self.window else 0
        if s != self.s_prev:
            self.s_prev, self.still = s, 0
        elif self.still < self.window:
            self.still += 1
        if self.still >= self.window - 1:
            self.sum = s * self.window
            return s
        self.sum += s - old
        return self.sum / self.window

    def _barrier_done(self, b: Block) -> bool:
        if self.holding:
            return False
        self.barrier_ms += 1
        done = barrier_done(self.ctx, b.move, self.barrier_ms)
        if done:
            self.barrier_ms = 0
        return done


def barrier_done(ctx, move: Move, ms: int) -> bool:
    """Run a non-motion move for its ``ms``-th millisecond; True when it has finished."""
    if move.kind == "dwell":
        return ms > round(move.seconds * 1000)
    if move.kind == "spindle":
        return ctx.spindle_command(move.rpm, ms)
    if move.kind == "end":
        return ctx.end_of_program(ms)
    if move.kind == "wait":
        return ctx.program_wait(move, ms)
    return True
