"""The planner's 1 ms step, fused into the servo loop for the stretches where it is simple.

Contract: ``entry(planner)`` returns the locals the fused loop needs, or None when the
next tick must go through ``Planner.step()`` (a block boundary within one tick's
travel, a barrier, a stop at rest). ``STORE`` writes the state back. The
loop text ``SETPOINT`` computes exactly what ``Planner._raw_step``, ``_smooth`` and
``_point`` compute for a tick that crosses no boundary, and breaks out *before* any
tick that could cross one, so block bookkeeping stays in ``Planner`` (plain Python).
"""

from __future__ import annotations

from backend_sim.motion.planner import Planner

NAMES = ("p_sraw", "p_v", "p_buf", "p_idx", "p_sum", "p_w", "p_invw", "p_dv", "p_acc2",
         "p_hold", "p_vnom", "p_exit2", "p_rs1", "p_ms0", "p_ms1", "p_arc", "p_coef",
         "p_marg", "p_still")

GUARD = """
        if p_ssm + p_marg >= p_ms1 or p_sraw + p_marg >= p_rs1:
            break
"""

SETPOINT = """
        p_nv = p_v - p_dv if p_hold else p_v + p_dv
        if p_nv > p_vnom:
            p_nv = p_vnom
        if p_sraw > p_sdec or p_hold:
            p_lim = p_exit2 + p_acc2 * (p_rs1 - p_sraw)
            if p_nv * p_nv > p_lim:
                p_nv = sqrt(p_lim)
        if p_nv > 0.0:
            p_v = p_nv
            p_sraw += p_nv * 0.001
            p_still = 0
        else:
            p_v = 0.0
            p_still += 1
        p_old = p_buf[p_idx]
        p_buf[p_idx] = p_sraw
        p_idx += 1
        if p_idx == p_w:
            p_idx = 0
        p_sum += p_sraw - p_old
        p_ssm = p_sum * p_invw
        p_d = p_ssm - p_ms0
        if p_arc:
            p_ang = p_c4 + p_c5 * p_d
            s0 = p_c0 + p_c3 * cos(p_ang)
            s1 = p_c1 + p_c3 * sin(p_ang)
            s2 = p_c2 + p_c6 * p_d
        else:
            s0 = p_c0 + p_c3 * p_d
            s1 = p_c1 + p_c4 * p_d
            s2 = p_c2 + p_c5 * p_d
"""

LOAD = """
    p_sraw, p_v, p_buf, p_idx, p_sum, p_w, p_invw, p_dv, p_acc2, p_hold, p_vnom, p_exit2, \\
        p_rs1, p_ms0, p_ms1, p_arc, p_coef, p_marg, p_still = fast
    p_c0, p_c1, p_c2, p_c3, p_c4, p_c5, p_c6 = p_coef
    p_ssm = p_sum * p_invw
    # below p_sdec even full speed can still stop in time: no need for the braking curve
    p_sdec = p_rs1 - max(0.0, p_vnom * p_vnom - p_exit2) / p_acc2 - 2e-3 * (p_vnom + p_dv)
    cos = math.cos
    sin = math.sin
    sqrt = math.sqrt
    s0 = s1 = s2 = 0.0
"""

STORE = """
    pl = ctl.planner
    pl.s_raw = pl.s_prev = p_sraw
    pl.v_raw = p_v
    pl.idx = p_idx
    pl.sum = p_sum
    pl.still = p_still if p_still < p_w else p_w
    if done:
        pl.pos = (s0, s1, s2)
"""


def entry(p: Planner):
    """Locals for the fused loop (in ``NAMES`` order) or None."""
    blocks = p.blocks
    if not blocks or p.raw >= len(blocks):
        return None
    b0, br = blocks[0], blocks[p.raw]
    if b0.barrier or br.barrier or (p.holding and p.v_raw <= 0.0):
        return None
    marg = p.vmax * 1e-3 * 1.001 + 1e-9
    s_sm = p.sum / p.window if p.still < p.window - 1 else p.s_raw
    if s_sm + marg >= b0.s1 or p.s_raw + marg >= br.s1:
        return None
    nxt = blocks[p.raw + 1] if p.raw + 1 < len(blocks) else None
    exit_v = nxt.v_entry if nxt is not None else 0.0
    if p.braking:  # an override lowered the plan: Planner.step() brakes to it
        return None
    if p.still >= p.window - 1:
        p.sum = p.s_raw * p.window
    return (p.s_raw, p.v_raw, p.buf, p.idx, p.sum, p.window, 1.0 / p.window, p.accel * 1e-3,
            2.0 * p.accel, p.holding, br.v_nom, exit_v * exit_v, br.s1, b0.s0, b0.s1, b0.arc,
            b0.coef, marg, p.still)
