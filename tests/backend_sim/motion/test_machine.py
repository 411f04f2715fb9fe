"""MotionController as the CNC MCU sees it: homing, limits, faults, hold, stop, cover, spindle."""

import math

import pytest

from backend_sim.motion import DialectParser, MotionController, MotionError
from backend_sim.motion.accuracy import home
from backend_sim.motion.events import Alarm, Finished, Held, Homed, StateChanged, Stopped

COUNT = 8.0 / 1980 * 1.0001


def run_until(ctl, predicate, limit_ms=60_000, step=5):
    for _ in range(limit_ms // step):
        ctl.advance(step)
        if predicate():
            return
    raise AssertionError(f"timed out in state {ctl.state}")


@pytest.fixture(scope="module")
def homed_state():
    """A homed controller is cheap to re-create by copying the homing result."""
    ctl = MotionController(start_mm=(30.0, 40.0, 10.0))
    home(ctl)
    return ctl


def homed():
    ctl = MotionController(start_mm=(0.0, 0.0, 30.0))
    home(ctl)
    return ctl


def queue(ctl, lines, first=0):
    parser = DialectParser(position=ctl.tail_mm)
    for seq, line in enumerate(lines, first):
        ctl.enqueue(parser.parse(seq, line))


def kinds(events, kind):
    return [e for e in events if isinstance(e, kind)]


# -- homing -------------------------------------------------------------------------
def test_homing_ends_ten_mm_from_each_switch(homed_state):
    ctl = homed_state
    assert ctl.homed and ctl.state == "IDLE"
    assert ctl.measured_mm == pytest.approx((0.0, 0.0, 30.0), abs=1e-9)
    switches = (-10.0, -10.0, 40.0)
    for k in range(3):
        assert abs(ctl.true_mm[k] - switches[k]) == pytest.approx(10.0, abs=2 * COUNT)


def test_homing_reports_events_in_order():
    ctl = MotionController(start_mm=(5.0, 5.0, 25.0))
    ctl.home()
    run_until(ctl, lambda: ctl.homed)
    events = ctl.events()
    assert events[0] == StateChanged("HOMING")
    assert kinds(events, Homed) and events[-1] == StateChanged("IDLE")


def test_recover_backs_off_a_pressed_switch_then_homes():
    ctl = MotionController(start_mm=(-10.5, 20.0, 20.0))  # X switch pressed at power-on
    ctl.home("RECOVER")
    run_until(ctl, lambda: ctl.homed)
    assert ctl.true_mm == pytest.approx((0.0, 0.0, 30.0), abs=2 * COUNT)
    assert not kinds(ctl.events(), Alarm)


def test_normal_homing_from_a_pressed_switch_fails_cleanly():
    ctl = MotionController(start_mm=(20.0, 20.0, 40.5))  # Z switch already pressed
    ctl.home("NORMAL")
    run_until(ctl, lambda: ctl.state == "ALARM", limit_ms=1000)
    assert kinds(ctl.events(), Alarm)[0] == Alarm("HOMING_FAILED", "Z switch pressed: home with RECOVER")


def test_homing_refused_while_cover_open():
    ctl = MotionController()
    ctl.cover_open = True
    with pytest.raises(MotionError) as info:
        ctl.home()
    assert info.value.code == "COVER_OPEN"


# -- limits and faults ----------------------------------------------------------------
def test_hitting_a_switch_outside_homing_is_a_limit_alarm():
    ctl = MotionController(start_mm=(-5.0, 20.0, 20.0))
    ctl.jog("X", -10.0, 300.0)  # allowed before homing; runs into the X min switch
    run_until(ctl, lambda: ctl.state == "ALARM")
    alarm = kinds(ctl.events(), Alarm)[0]
    assert (alarm.code, alarm.text) == ("LIMIT", "X min")
    assert not ctl.homed and ctl.free_slots() == ctl.capacity
    assert -13.0 < ctl.true_mm[0] < -10.0  # stopped between switch and hard stop
    with pytest.raises(MotionError):
        queue(ctl, ["G01 X1 F100"])
    ctl.home("RECOVER")
    run_until(ctl, lambda: ctl.homed)


def test_z_switch_sits_at_the_top():
    ctl = MotionController(start_mm=(20.0, 20.0, 38.0))
    ctl.jog("Z", 5.0, 300.0)
    run_until(ctl, lambda: ctl.state == "ALARM")
    assert kinds(ctl.events(), Alarm)[0].text == "Z max"


def test_trip_limit_injection():
    ctl = homed()
    queue(ctl, ["G01 X20 F300"])
    ctl.advance(200)
    ctl.trip_limit("Y")
    events = ctl.events()
    assert Alarm("LIMIT", "Y min") in events and ctl.state == "ALARM" and not ctl.homed
    ctl.advance(500)
    assert not kinds(ctl.events(), Finished)


def test_lost_encoder_raises_following_error():
    ctl = homed()
    ctl.lose_encoder("X")
    queue(ctl, ["G01 X30 F300"])
    run_until(ctl, lambda: ctl.state == "ALARM", limit_ms=10_000)
    alarm = kinds(ctl.events(), Alarm)[0]
    assert alarm.code == "FOLLOWING_ERROR" and alarm.text.startswith("X ")
    run_until(ctl, ctl.idle)  # the drives are off: the axis coasts to rest
    ctl.reset()
    assert ctl.counts == (0, 0, 0) and not ctl.homed and ctl.state == "IDLE"


def test_following_error_limit_is_settable():
    ctl = MotionController(mode="simple", start_mm=(0.0, 0.0, 30.0))  # PID alone, no feed-forward
    home(ctl)
    ctl.set_param("FERR", 0.05)
    queue(ctl, ["G01 Y30 F600"])
    run_until(ctl, lambda: ctl.state == "ALARM", limit_ms=10_000)
    alarm = kinds(ctl.events(), Alarm)[0]
    assert alarm.code == "FOLLOWING_ERROR" and alarm.text.startswith("Y ")


# -- parameters ------------------------------------------------------------------------
def test_set_param_changes_gains_and_refuses_nonsense():
    ctl = MotionController()
    ctl.set_param("KP_X", 12.5)
    ctl.set_param("kd_z", 0.1)
    assert ctl.get_param("KP_X") == 12.5 and ctl.get_param("KD_Z") == pytest.approx(0.1)
    assert ctl.get_param("KP_Y") == 8.0
    with pytest.raises(ValueError, match="unknown parameter"):
        ctl.set_param("KQ_X", 1)
    with pytest.raises(ValueError, match="out of range"):
        ctl.set_param("KP_X", -1)
    with pytest.raises(ValueError, match="out of range"):
        ctl.set_param("FERR", math.inf)


# -- hold, resume, stop, cover -----------------------------------------------------------
def distance_from_line(p, a, b):
    ab = [b[k] - a[k] for k in range(3)]
    t = sum((p[k] - a[k]) * ab[k] for k in range(3)) / sum(v * v for v in ab)
    t = min(1.0, max(0.0, t))
    return math.dist(p, [a[k] + t * ab[k] for k in range(3)])


def test_feed_hold_stops_on_the_path_and_resume_completes():
    ctl = homed()
    queue(ctl, ["G01 X60 Y40 F600"])
    ctl.advance(1500)
    ctl.feed_hold()
    assert ctl.state == "HOLD"
    run_until(ctl, lambda: kinds(ctl.events(), Held), limit_ms=2000, step=1)
    stop_at = ctl.measured_mm
    a, b = (0.0, 0.0, 30.0), (60.0, 40.0, 30.0)
    assert distance_from_line(ctl.commanded_mm, a, b) < 1e-9
    assert distance_from_line(stop_at, a, b) < 0.01
    ctl.advance(3000)
    assert ctl.measured_mm == pytest.approx(stop_at, abs=2 * COUNT)  # stays put
    ctl.resume()
    run_until(ctl, ctl.idle)
    assert [(e.seq, e.source) for e in kinds(ctl.events(), Finished)] == [(0, "G01 X60 Y40 F600")]
    assert ctl.done_seq == 0
    assert ctl.measured_mm == pytest.approx((60.0, 40.0, 30.0), abs=COUNT)


def test_hold_decelerates_across_segment_ends():
    ctl = homed()
    points = [(0.0, 0.0)] + [(1 + k * 0.2, k * 0.1) for k in range(16)]
    queue(ctl, [f"G01 X{x:.1f} Y{y:.1f} F600" for x, y in points[1:]])
    ctl.advance(300)
    ctl.feed_hold()
    run_until(ctl, lambda: kinds(ctl.events(), Held), limit_ms=2000, step=1)
    assert 0 <= ctl.done_seq < 15  # it needed more than one short segment to stop
    pos = ctl.commanded_mm
    pairs = zip(points[:-1], points[1:], strict=True)
    assert min(distance_from_line(pos, (*p, 30.0), (*q, 30.0)) for p, q in pairs) < 1e-9


def test_stop_flushes_the_queue_and_stops_the_spindle():
    ctl = homed()
    queue(ctl, ["M03 S3000", "G01 X50 F600", "G01 Y50", "G01 X0", "G01 Y0"])
    run_until(ctl, lambda: ctl.spindle_rpm > 2000, limit_ms=5000)
    ctl.advance(500)
    ctl.stop()
    run_until(ctl, lambda: ctl.state == "IDLE", limit_ms=3000, step=1)
    events = ctl.events()
    assert kinds(events, Stopped)
    assert ctl.free_slots() == ctl.capacity and not ctl.spindle_on
    done = ctl.done_seq
    ctl.advance(5000)
    assert ctl.done_seq == done and not kinds(ctl.events(), Finished)
    assert ctl.measured_mm[1] == pytest.approx(0.0, abs=COUNT)  # never reached the Y move


def test_cover_open_holds_a_job_and_forbids_motion():
    ctl = homed()
    queue(ctl, ["G01 X30 F600"])
    ctl.advance(500)
    ctl.cover_open = True
    assert Alarm("COVER_OPEN", "cover opened") in ctl.events() and ctl.state == "HOLD"
    run_until(ctl, lambda: ctl.source_quiet(), limit_ms=2000, step=1)
    with pytest.raises(MotionError):
        ctl.resume()
    with pytest.raises(MotionError):
        ctl.jog("X", 1, 100)
    ctl.cover_open = False
    ctl.resume()
    run_until(ctl, ctl.idle)
    assert ctl.measured_mm[0] == pytest.approx(30.0, abs=COUNT)


def test_queue_refuses_when_full():
    ctl = homed()
    queue(ctl, [f"G01 X{k + 1} F100" for k in range(ctl.capacity)])
    assert ctl.free_slots() == 0
    with pytest.raises(MotionError) as info:
        queue(ctl, ["G01 X40 F100"], first=ctl.capacity)
    assert info.value.code == "QUEUE_FULL"


# -- spindle, dwell, jog, time ---------------------------------------------------------
def test_spindle_speed_is_measured_from_its_encoder():
    ctl = homed()
    queue(ctl, ["M03 S3000", "G04 P0.5", "M05", "M02"])
    run_until(ctl, lambda: ctl.done_seq >= 1, limit_ms=10_000, step=1)
    rpm = ctl.spindle_rpm
    assert rpm == pytest.approx(3000, rel=0.05)
    assert rpm % 30 == 0  # 20 pulses/rev over a 100 ms gate: 30 rpm steps
    run_until(ctl, ctl.idle)
    ctl.advance(3000)
    assert ctl.spindle_rpm < 100


def test_dwell_waits():
    ctl = homed()
    queue(ctl, ["G04 P0.75"])
    t0 = ctl.now_ms
    run_until(ctl, lambda: ctl.done_seq == 0, step=1)
    assert 750 <= ctl.now_ms - t0 <= 800


def test_jog_is_soft_limited_once_homed():
    ctl = homed()
    with pytest.raises(MotionError) as info:
        ctl.jog("X", -1.0, 300)
    assert info.value.text == "X- -1.000 < 0"
    ctl.jog("Y", 2.5, 300)
    run_until(ctl, ctl.idle)
    assert ctl.measured_mm[1] == pytest.approx(2.5, abs=COUNT)


def test_idle_fast_forward_is_exact_and_cheap():
    a, b = homed(), homed()
    run_until(a, a.idle, limit_ms=2000, step=1)
    run_until(b, b.idle, limit_ms=2000, step=1)
    b.now_ms = a.now_ms
    a.advance(3_600_000)  # an hour at rest
    for _ in range(100):
        b.advance(1)
    assert a.true_mm == b.true_mm and a.counts == b.counts
    assert a.now_ms - b.now_ms == 3_600_000 - 100


def test_jog_works_after_an_alarm_during_homing():
    ctl = MotionController(start_mm=(20.0, 20.0, 20.0))
    ctl.home()
    ctl.advance(1000)
    ctl.trip_limit("Z")
    assert ctl.state == "ALARM"
    ctl.clear_alarm()
    ctl.jog("X", 1.0, 300)
    run_until(ctl, ctl.idle)
    assert ctl.measured_mm[0] == pytest.approx(1.0, abs=COUNT)


def test_simple_mode_holds_on_the_path_and_resumes():
    ctl = MotionController(mode="simple", start_mm=(0.0, 0.0, 30.0))
    home(ctl)
    queue(ctl, ["G01 X30 Y20 F600"])
    ctl.advance(1000)
    ctl.feed_hold()
    run_until(ctl, lambda: kinds(ctl.events(), Held), limit_ms=500, step=1)
    assert distance_from_line(ctl.commanded_mm, (0, 0, 30), (30, 20, 30)) < 0.5 * COUNT * 2
    ctl.resume()
    run_until(ctl, ctl.idle)
    assert ctl.done_seq == 0


def test_fused_fast_path_matches_the_plain_planner_step(monkeypatch):
    """The planner's tick inlined into the servo loop gives the same motion as step()."""
    lines = ["G01 X5 Y3 F600", "G02 X9 Y3 I2 J0", "G01 X9 Y0.5 Z-19", "G01 X2 Y2 F300"]

    def run():
        ctl = MotionController(start_mm=(20.0, 20.0, 5.0))  # measured (0, 0, 0) at power-on
        queue(ctl, lines)
        trace = []
        ctl.trace = trace.append
        run_until(ctl, ctl.idle, step=7)
        assert ctl.done_seq == 3 and not kinds(ctl.events(), Alarm)
        return ctl, trace

    fused, fused_trace = run()
    import backend_sim.motion.controller as controller_module
    monkeypatch.setattr(controller_module.fastpath, "entry", lambda planner: None)
    plain, plain_trace = run()
    assert abs(len(fused_trace) - len(plain_trace)) <= 2
    worst = max(max(abs(a - b) for a, b in zip(p, q, strict=True))
                for p, q in zip(fused_trace, plain_trace, strict=False))
    assert worst <= 1.0  # counts
    assert fused.measured_mm == pytest.approx(plain.measured_mm, abs=COUNT)
