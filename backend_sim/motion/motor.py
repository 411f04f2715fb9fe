"""Brushed DC gear motor on an L298N, lead screw and encoder: constants and discrete model.

Contract: ``MotorModel.from_profile(profile)`` derives every constant of the JGA25-370
axis drive from ``MachineProfile.axis`` plus the few electrical/mechanical constants a
profile does not carry (``MotorConstants``). The back-EMF constant is solved so that
the axis (motor, gearbox, screw and 8 kg table) turns ``no_load_rpm`` at the output
with ``supply_v`` across the motor.

State per axis is ``(i, v, x)``: winding current (A), table speed (mm/s) and table
position (mm). Inputs: motor voltage and the sign of Coulomb friction. The linear part
is discretised exactly (zero-order hold of the matrix exponential) for one 1 ms tick,
so the 0.3 ms L/R time constant is stable. ``step()`` is the reference implementation;
the 1 kHz servo loop inlines the same arithmetic for speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from app.profile import MachineProfile
from backend_sim.motion.linalg import zoh


@dataclass(frozen=True)
class MotorConstants:
    """Constants of the drive that the machine profile does not carry (proposed additions)."""

    resistance_ohm: float = 8.0  # winding, stall current 1.5 A at 12 V
    inductance_h: float = 2.5e-3  # L/R = 0.31 ms
    rotor_inertia_kgm2: float = 1.0e-6  # rotor plus first gear stages, at the motor shaft
    table_mass_kg: float = 8.0  # moving mass reflected through screw and gear
    no_load_current_a: float = 0.10  # at supply_v, unloaded
    coulomb_share: float = 0.4  # part of the no-load current spent on Coulomb friction
    dt_s: float = 1e-3


@dataclass(frozen=True)
class MotorModel:
    """All numbers of one axis drive, in SI at the motor shaft and mm at the table."""

    r: float
    ind: float  # H
    ke: float  # V s/rad = N m/A
    j: float  # kg m^2 at the motor shaft
    b: float  # N m s/rad viscous
    tc: float  # N m Coulomb
    mm_per_rad: float  # table mm per motor radian
    counts_per_mm: float
    bus_v: float  # volts at duty 1 (supply minus bridge drop)
    supply_v: float
    dt: float
    moving: tuple[float, ...]  # 12 coefficients, see step()
    stuck: tuple[float, float]  # (a, b): i' = a i + b V while the shaft sticks

    @classmethod
    def from_profile(cls, profile: MachineProfile, const: MotorConstants | None = None) -> MotorModel:
        c = const or MotorConstants()
        ax = profile.axis
        w0 = ax.no_load_rpm * ax.gear_ratio * 2 * math.pi / 60.0  # motor rad/s unloaded
        ke = (ax.supply_v - c.resistance_ohm * c.no_load_current_a) / w0
        tc = ke * c.no_load_current_a * c.coulomb_share
        b = ke * c.no_load_current_a * (1 - c.coulomb_share) / w0
        mm_per_rad = ax.lead_mm / (2 * math.pi * ax.gear_ratio)
        lead_m_per_rad = ax.lead_mm * 1e-3 / (2 * math.pi)
        j = c.rotor_inertia_kgm2 + c.table_mass_kg * lead_m_per_rad**2 / ax.gear_ratio**2
        moving, stuck = _discretise(c.resistance_ohm, c.inductance_h, ke, j, b, tc, mm_per_rad, c.dt_s)
        return cls(
            r=c.resistance_ohm, ind=c.inductance_h, ke=ke, j=j, b=b, tc=tc,
            mm_per_rad=mm_per_rad, counts_per_mm=ax.counts_per_rev / ax.lead_mm,
            bus_v=ax.supply_v - ax.bridge_drop_v, supply_v=ax.supply_v, dt=c.dt_s,
            moving=moving, stuck=stuck,
        )

    def breakaway_current(self) -> float:
        return self.tc / self.ke

    def duty_for(self, v_mm_s: float, a_mm_s2: float = 0.0) -> float:
        """Steady-state feed-forward duty for table speed v and acceleration a."""
        w = v_mm_s / self.mm_per_rad
        torque = self.b * w + self.j * a_mm_s2 / self.mm_per_rad
        if v_mm_s:
            torque += math.copysign(self.tc, v_mm_s)
        return (torque / self.ke * self.r + self.ke * w) / self.bus_v

    def ff_gains(self) -> tuple[float, float, float]:
        """(duty per mm/s, duty per mm/s^2, duty for Coulomb friction)."""
        kv = (self.b * self.r / self.ke + self.ke) / self.mm_per_rad / self.bus_v
        ka = self.j * self.r / self.ke / self.mm_per_rad / self.bus_v
        kc = self.tc * self.r / self.ke / self.bus_v
        return kv, ka, kc


def _discretise(r, ind, ke, j, b, tc, mm_per_rad, dt):
    """ZOH of d/dt [i, v, x] = A [i, v, x] + B [V, dir] with friction -tc*dir."""
    k = mm_per_rad
    a = np.array([
        [-r / ind, -ke / (ind * k), 0.0],
        [ke * k / j, -b / j, 0.0],
        [0.0, 1.0, 0.0],
    ])
    bm = np.array([[1.0 / ind, 0.0], [0.0, -tc * k / j], [0.0, 0.0]])
    ad, bd = zoh(a, bm, dt)
    moving = tuple(float(x) for x in (
        ad[0, 0], ad[0, 1], bd[0, 0], bd[0, 1],
        ad[1, 0], ad[1, 1], bd[1, 0], bd[1, 1],
        ad[2, 0], ad[2, 1], bd[2, 0], bd[2, 1],
    ))
    ae = math.exp(-r / ind * dt)
    return moving, (ae, (1 - ae) / r)


def step(m: MotorModel, i: float, v: float, x: float, volts: float) -> tuple[float, float, float]:
    """One tick of the axis: returns the new (i, v, x). Coulomb friction sticks at v = 0."""
    a00, a01, b00, c0, a10, a11, b10, c1, a20, a21, b20, c2 = m.moving
    if v == 0.0:
        ae, be = m.stuck
        i_stuck = ae * i + be * volts
        if -m.tc < m.ke * i_stuck < m.tc:
            return i_stuck, 0.0, x
        d = 1.0 if i_stuck > 0 else -1.0
    else:
        d = 1.0 if v > 0 else -1.0
    i2 = a00 * i + a01 * v + b00 * volts + c0 * d
    v2 = a10 * i + a11 * v + b10 * volts + c1 * d
    x2 = x + a20 * i + a21 * v + b20 * volts + c2 * d
    if v2 * d < 0.0:  # friction stopped the shaft within the tick
        v2 = 0.0
    return i2, v2, x2
