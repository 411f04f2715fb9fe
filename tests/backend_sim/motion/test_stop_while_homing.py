"""Found by the long fuzz run (issue 14 point 10): STOP while homing towards a switch
must not crash the simulator when the deceleration still reaches the switch."""

import pytest

from backend_sim.motion import MotionController
from backend_sim.motion.events import Alarm, Stopped


@pytest.mark.parametrize(("start_z", "stop_after_ms"), [(39.8, 100), (39.9, 50), (39.95, 50), (39.99, 20)])
def test_stop_during_homing_that_still_reaches_the_switch(start_z, stop_after_ms):
    ctl = MotionController(start_mm=(20.0, 20.0, start_z))  # the Z switch is at 40
    ctl.home("NORMAL")
    ctl.advance(stop_after_ms)
    ctl.stop()
    for _ in range(100):
        ctl.advance(20)
    events = ctl.events()
    assert ctl.state in ("IDLE", "ALARM") and not ctl.homed
    assert any(isinstance(e, Stopped) for e in events) or Alarm("LIMIT", "Z max") in events
