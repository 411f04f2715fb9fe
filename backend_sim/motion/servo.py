"""The 1 kHz servo loop of all three axes: setpoint, PID, L298N, motor, encoder, switches.

Contract: ``run(ctl, n)`` advances the controller ``ctl`` by up to ``n`` ticks and
returns how many it did. It stops early after a tick in which a switch window was
left, a following error exceeded its limit or an event was queued; ``ctl`` then
handles it and calls again. State lives in locals during the call and is stored back
into ``ctl.axes`` at the end, so nothing may read the axes from inside the loop except
``ctl.errors`` (updated every tick).

Per axis and tick (all in mm, duty -1..1):

    e   = setpoint - measured                   measured = counts * mm_per_count + offset
    vff = d(setpoint)/dt, aff = d(vff)/dt       from consecutive setpoints
    u   = kp e + I + kd D + kv vff + ka aff + kc sgn(vff)      (feed-forward if enabled)
    I  += ki e dt  only outside a +-0.6 count dead band (a setpoint half-way between two
                   counts must not make the integrator hunt between them) and while u is
                   not saturated (anti-windup)
    D   = first-order filtered de/dt (2 ms)
    volts = clamp(u, -1, 1) * (supply - bridge drop); then motor.step() inlined

An axis whose setpoint has not changed and that has come to rest (shaft stuck by
Coulomb friction, current settled, error inside the integrator's dead band) is a fixed
point of this update; it is flagged ``rest`` and skipped until its setpoint changes.
Whoever changes an axis' state from outside clears ``rest`` (``ctl.wake()``).

Speed: the loop body is written once for axis ``{k}`` and expanded three times into
one generated function whose state lives in local variables (pure scalar Python is
several times faster than numpy on 3-element arrays, and locals beat attributes).
``ctl.axes[k]`` is the list the state is loaded from and stored back to.
"""

from __future__ import annotations

import math

from backend_sim.motion import fastpath

# Per-axis state, in this order, in ctl.axes[k] (a list): see STATE.
DEAD_BAND_COUNTS = 0.6
STATE = ("i", "v", "x", "c", "c0", "cpm", "off", "ig", "ep", "df", "sp", "pv", "lo", "hi",
         "kp", "ki", "kd", "rest")

_HEAD = """
def _run(ctl, n, fast=None):
    step = ctl.source_step
    trace = ctl.trace
    events = ctl._events
    ne = len(events)
    err = ctl.errors
    on = ctl.servo_on
    (kv, ka, kc, kcv, vc, q_ii, q_iv, q_iu, q_id, q_vi, q_vv, q_vu, q_vd, q_xi, q_xv, q_xu, q_xd,
     ae, be, ib, mpc, ferr, db, fb, fg) = ctl.loop_constants
    now = ctl.now_ms
    brk = 0
    e0, e1, e2 = err
    {load}
    done = 0
    while done < n:
        {guard}
        done += 1
        now += 1
        {clock}
        {setpoint}
        {body}
        if trace is not None:
            trace((c0, c1, c2))
        if brk{stop}:
            break
    {store}
    ctl.now_ms = now
    err[:] = e0, e1, e2
    ctl.brk = brk
    return done
"""

_AXIS = """
        if s{k} != sp{k} or not rest{k}:
            rest{k} = False
            e{k} = e = s{k} - c{k} * mpc - off{k}
            {err}
            vf = s{k} - sp{k}
            sp{k} = s{k}
            if on:
                df{k} = df{k} * fb + (e - ep{k}) * fg
                ep{k} = e
                u = kp{k} * e + ig{k} + kd{k} * df{k}
                if kv:
                    u += kv * vf + ka * (vf - pv{k}) + (kc if vf > vc else -kc if vf < -vc else kcv * vf)
                if not -db <= e <= db:
                    g = ig{k} + ki{k} * e
                    if -1.0 < u < 1.0 and -0.5 < g < 0.5:
                        ig{k} = g
                if u > 1.0:
                    u = 1.0
                elif u < -1.0:
                    u = -1.0
            else:
                u = 0.0
            if v{k} == 0.0:
                t_i = ae * i{k} + be * u
                if -ib < t_i < ib:
                    if not vf and not pv{k} and -1e-12 < t_i - i{k} < 1e-12 and (-db <= e <= db or not on):
                        rest{k} = -1e-9 < df{k} < 1e-9
                    i{k} = t_i
                    d = 0.0
                else:
                    d = 1.0 if t_i > 0.0 else -1.0
            else:
                d = 1.0 if v{k} > 0.0 else -1.0
            pv{k} = vf
            if d:
                t_i = i{k}
                t_v = v{k}
                i{k} = q_ii * t_i + q_iv * t_v + q_iu * u + q_id * d
                x{k} += q_xi * t_i + q_xv * t_v + q_xu * u + q_xd * d
                t_v = q_vi * t_i + q_vv * t_v + q_vu * u + q_vd * d
                v{k} = 0.0 if t_v * d < 0.0 else t_v
                c{k} = (x{k} * cpm{k}) // 1.0 - c0{k}
                if not lo{k} < x{k} < hi{k}:
                    brk = brk or {k} + 1
            if not -ferr <= e <= ferr:
                brk = brk or {k} + 11
"""

def constants(ctl) -> tuple:
    """The loop's constants, in per-tick units (see ``_HEAD``); recomputed on changes."""
    m = ctl.model
    kv, ka, kc, vc = ctl.ff
    bus = m.bus_v
    q = list(m.moving)
    for n in (2, 6, 10):  # voltage inputs: take the duty directly
        q[n] *= bus
    ae, be = m.stuck
    mpc = 1.0 / m.counts_per_mm
    return (kv * 1000.0, ka * 1e6, kc, kc / (vc * 1e-3), vc * 1e-3, *q, ae, be * bus, m.tc / m.ke,
            mpc, ctl.ferr, DEAD_BAND_COUNTS * mpc, 1.0 - ctl.d_alpha, ctl.d_alpha * 1000.0)


def _generate(fused: bool):
    load = "\n    ".join(
        f"{', '.join(n + str(k) for n in STATE)} = ctl.axes[{k}]" for k in range(3)
    )
    store = "\n    ".join(
        f"ctl.axes[{k}][:] = ({', '.join(n + str(k) for n in STATE)})" for k in range(3)
    )
    parts = {
        "{load}": load + (fastpath.LOAD if fused else ""),
        "{store}": store + (fastpath.STORE if fused else ""),
        "{guard}": fastpath.GUARD.strip() if fused else "",
        "{setpoint}": fastpath.SETPOINT.strip() if fused else "s0, s1, s2 = step()",
        # the fused loop calls nothing that reads the clock, the errors or queues events
        "{stop}": " or p_still" if fused else " or len(events) != ne",
        "{clock}": "" if fused else "ctl.now_ms = now",
        "{body}": "".join(_AXIS.replace("{err}", "" if fused else "err[{k}] = e").format(k=k)
                          for k in range(3)),
    }
    source = _HEAD
    for key, text in parts.items():
        source = source.replace(key, text)
    namespace = {"math": math}
    exec(compile(source, "<servo loop>", "exec"), namespace)  # noqa: S102 - generated once, fixed text
    return namespace["_run"], source


run, SOURCE = _generate(False)
run_fused, SOURCE_FUSED = _generate(True)
