"""The simulated GRBL's status report and ``$``-query print-outs.

``status_report(machine)``: ``<State|MPos or WPos|Bf|FS|WCO|Ov|A|Pn>`` as GRBL 1.1's
interface documentation describes it: ``$10`` bit 0 picks MPos (else WPos), bit 1 adds
``Bf:``; ``WCO:`` comes in the first report after a reset, when it changed, and every
30th report (10th while moving); ``Ov:`` (with ``A:`` when anything is on) in the
second report after a reset, when an override changed, and every 20th (10th moving),
never in the same report as ``WCO:``; ``$13=1`` reports inches.
"""

from __future__ import annotations

INCH = 25.4


def _vec(values, inches: bool) -> str:
    scale = 1 / INCH if inches else 1.0
    digits = 4 if inches else 3
    return ",".join(f"{v * scale:.{digits}f}" for v in values)


def status_report(m) -> str:
    inches = bool(m.settings[13])
    mask = int(m.settings[10])
    mpos = m.mpos()
    wco = m.gcode.wco()
    fields = [m.state_name()]
    if mask & 1:
        fields.append("MPos:" + _vec(mpos, inches))
    else:
        fields.append("WPos:" + _vec([p - o for p, o in zip(mpos, wco, strict=True)], inches))
    if mask & 2:
        fields.append(f"Bf:{m.motion.free_slots()},{len(m.rx) and 128 - len(m.rx) or 128}")
    moving = m.motion.state in ("RUN", "JOG", "HOMING")
    feed = 0.0 if not moving else _speed(m)
    fields.append(f"FS:{feed / (INCH if inches else 1):.0f},{m.motion.spindle_rpm:.0f}")
    pins = _pins(m)
    if pins:
        fields.append("Pn:" + pins)
    m.report_count += 1
    if m.show_wco or wco != getattr(m, "_last_wco", None) or m.report_count % (10 if moving else 30) == 0:
        m.show_wco, m._last_wco = False, wco
        fields.append("WCO:" + _vec(wco, inches))
    elif m.show_ov or m.report_count % (10 if moving else 20) == 0:
        m.show_ov = False
        fields.append("Ov:{},{},{}".format(*m.overrides))
        accessories = ("S" if m.motion.spindle_target > 0 else "") + m.gcode.coolant
        if accessories:
            fields.append("A:" + accessories)
    return "<" + "|".join(fields) + ">"


def _speed(m) -> float:
    """The feed along the path now, mm/min (the setpoint's speed over the last service)."""
    return m.speed_mm_min


def _pins(m) -> str:
    out = "".join(axis for axis, pressed in zip("XYZ", m.motion.pressed, strict=True) if pressed)
    return out + ("D" if m.door and m.motion.cover_open else "")


def parameters(m) -> list[str]:
    """The ``$#`` print-out."""
    rows = [f"[G{54 + k}:{_vec(m.gcode.offsets[k], False)}]" for k in range(6)]
    rows += ["[G28:0.000,0.000,0.000]", "[G30:0.000,0.000,0.000]",
             f"[G92:{_vec(m.gcode.g92, False)}]", "[TLO:0.000]", "[PRB:0.000,0.000,0.000:0]"]
    return rows
