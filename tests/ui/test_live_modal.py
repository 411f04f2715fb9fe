"""The live modal state from the source at the line done (app/ui/live_modal.py)."""

from __future__ import annotations

from app.comm.events import StatusEvent
from app.ui.live_modal import ModalTracker, actual_feed

SOURCE = """(header)
G20 G91 G18
G55 T3 M06
g1 x1 F12.5 S9000
G92 X10 Y0
G2 X2 Z1 I1
G41 D1 G0 X0
G92.2
G92.3
G92.1 G40
#1 = 5
G3 X1 I1 G19
"""


def test_each_group_the_feed_the_speed_the_tool_and_g92_follow_the_lines():
    tracker = ModalTracker(SOURCE.splitlines())
    view = tracker.advance_to(1)
    assert view.codes == {"motion": "", "plane": "G17", "units": "G21", "distance": "G90",
                          "wcs": "G54", "compensation": "G40"}
    view = tracker.advance_to(4)
    assert view.codes["units"] == "G20" and view.codes["distance"] == "G91" and view.codes["plane"] == "G18"
    assert view.codes["wcs"] == "G55" and view.codes["motion"] == "G1"
    assert view.tool == 3 and view.feed == 12.5 and view.speed == 9000
    assert tracker.advance_to(5).g92 == "X10 Y0"
    view = tracker.advance_to(7)
    assert view.codes["motion"] == "G0" and view.codes["compensation"] == "G41" and view.g92 == "X10 Y0"
    assert tracker.advance_to(8).g92 == ""  # G92.2 suspends
    assert tracker.advance_to(9).g92 == "X10 Y0"  # G92.3 restores
    view = tracker.advance_to(11)  # G92.1 clears; a parameter line changes nothing
    assert view.g92 == "" and view.codes["compensation"] == "G40"
    view = tracker.advance_to(12)
    assert view.codes["motion"] == "G3" and view.codes["plane"] == "G19"


def test_a_jump_back_reads_only_that_line_and_keeps_the_state():
    lines = ["G90", "G1 X1 F100", "G0 X2", "G91 G2 X1 I1"]
    tracker = ModalTracker(lines)
    assert tracker.advance_to(4).codes["distance"] == "G91"
    view = tracker.advance_to(2)  # the loop's next pass starts again at line 2
    assert view.codes["motion"] == "G1" and view.codes["distance"] == "G91"
    assert tracker.advance_to(3).codes["motion"] == "G0"
    assert tracker.advance_to(99).codes["motion"] == "G2"  # past the end: the last line


def test_actual_feed_from_two_statuses():
    def status(x, t):
        return StatusEvent("1", "RUN", x, 0.0, 0.0, 0, 0, 16, 0, "H", time=t)

    assert abs(actual_feed(status(0.0, 1.0), status(1.0, 1.1)) - 600.0) < 1e-6
    assert actual_feed(None, status(1.0, 1.1)) is None
    assert actual_feed(status(0.0, 1.0), status(1.0, 1.0)) is None
