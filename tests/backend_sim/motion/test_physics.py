"""Motor model and servo loop: unloaded speed, exact discretisation, step and ramp responses."""

import math

import pytest

from app.profile import MachineProfile
from backend_sim.motion import MotionController
from backend_sim.motion.motor import MotorModel, step

PROFILE = MachineProfile()
MODEL = MotorModel.from_profile(PROFILE)
COUNT = 1.0 / MODEL.counts_per_mm * 1.0001  # one count, with float slack


def spin(volts: float, ms: int = 1500) -> float:
    """Output shaft rpm after ``ms`` at ``volts`` across the motor, unloaded."""
    i = v = x = 0.0
    for _ in range(ms):
        i, v, x = step(MODEL, i, v, x, volts)
    return v / PROFILE.axis.lead_mm * 60.0


def test_unloaded_speed_is_130_rpm_at_12_volts():
    assert spin(12.0) == pytest.approx(130.0, rel=0.02)


def test_l298n_drop_lowers_top_speed():
    top = spin(MODEL.bus_v)  # duty 1 through the bridge: 10 V
    assert 100.0 < top < 115.0
    assert top / 60 * PROFILE.axis.lead_mm > 10.0  # still above the 600 mm/min rapid


def test_stiction_holds_below_breakaway_torque():
    i = v = x = 0.0
    small = MODEL.breakaway_current() * MODEL.r * 0.8
    for _ in range(200):
        i, v, x = step(MODEL, i, v, x, small)
    assert v == 0.0 and x == 0.0


def test_electrical_time_constant_is_below_one_tick_and_stable():
    assert MODEL.ind / MODEL.r < 1e-3
    i = v = x = 0.0
    for _ in range(5):
        i, v, x = step(MODEL, i, v, x, 10.0)
        assert 0.0 < i < 10.0 / MODEL.r  # no overshoot of the stall current


def test_servo_loop_inlines_the_reference_motor_step():
    ctl = MotionController()
    ctl.servo_on = False
    axis = ctl.axes[0]
    axis[1] = 12.0  # coasting at 12 mm/s
    ctl.wake()
    i, v, x = axis[0], axis[1], axis[2]
    for _ in range(30):
        i, v, x = step(MODEL, i, v, x, 0.0)
    ctl.advance(30)
    assert ctl.axes[0][2] == pytest.approx(x, abs=1e-12)
    assert ctl.axes[0][1] == pytest.approx(v, abs=1e-9)


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_step_settles_within_one_count(axis):
    ctl = MotionController()
    target = [0.0, 0.0, 0.0]
    target[axis] = 1.0
    measured = ctl.drive([tuple(target)] * 400)
    assert max(p[axis] for p in measured) < 1.1  # overshoot < 10 %
    assert all(abs(p[axis] - 1.0) <= COUNT for p in measured[250:])
    assert abs(ctl.measured_mm[axis] - 1.0) <= COUNT


@pytest.mark.parametrize("axis", [0, 1, 2])
def test_ramp_tracks_and_settles_within_one_count(axis):
    ctl = MotionController()
    ramp = []
    for t in range(1, 801):  # 5 mm/s for 0.8 s, then hold at 4 mm
        p = [0.0, 0.0, 0.0]
        p[axis] = min(t, 800) * 0.005
        ramp.append(tuple(p))
    measured = ctl.drive(ramp + [ramp[-1]] * 300)
    lag = max(abs(m[axis] - r[axis]) for m, r in zip(measured[100:800], ramp[100:], strict=True))
    assert lag < 0.05  # tracks a 5 mm/s ramp
    assert all(abs(p[axis] - 4.0) <= COUNT for p in measured[-150:])
    true_move = ctl.true_mm[axis] - (50.0, 50.0, 20.0)[axis]
    assert true_move == pytest.approx(4.0, abs=2 * COUNT)


def test_counts_quantise_the_true_position():
    ctl = MotionController()
    ctl.drive([(0.3, 0.0, 0.0)] * 300)
    counts = ctl.counts[0]
    assert isinstance(counts, int)
    assert ctl.measured_mm[0] == pytest.approx(counts / MODEL.counts_per_mm)
    assert ctl.measured_mm[0] != ctl.true_mm[0] - 50.0
    assert math.floor(ctl.true_mm[0] * MODEL.counts_per_mm) - math.floor(50.0 * MODEL.counts_per_mm) == counts


@pytest.mark.parametrize("target", [(0.00202, -0.00202, 0.00606), (1.2345, -2.5, 0.5), (-0.99, 0.25, -1.75)])
def test_comes_to_rest_without_hunting(target):
    """Setpoints between counts (even exactly half-way) end at rest: idle() turns true."""
    ctl = MotionController()
    ctl.drive([target] * 300)
    for _ in range(200):
        if ctl.idle():
            break
        ctl.advance(10)
    assert ctl.idle()
    assert max(abs(e) for e in ctl.following_error_mm) <= COUNT
