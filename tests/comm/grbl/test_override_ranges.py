"""The overrides a GRBL session sends stay within the ranges of its capabilities, the
object the window's sliders take (``OverridesPanel.set_ranges``), not a range of its
own: a grblHAL build with other limits is one ``Capabilities`` away (issue 23)."""

from __future__ import annotations

import dataclasses

import pytest

from app.comm.driver import GRBL_CAPABILITIES, make_session
from app.comm.grbl import protocol as p
from tests.comm.grbl.harness import Harness

NARROW = dataclasses.replace(GRBL_CAPABILITIES, feed_override=range(50, 151), spindle_override=range(80, 121),
                             rapid_override=(50, 100))


def _sent(h: Harness) -> bytes:
    return h.take().replace(b"?", b"")


def test_make_session_gives_the_session_the_capabilities_the_window_reads():
    session = make_session("grbl")
    assert session.capabilities is GRBL_CAPABILITIES
    assert session.capabilities.override_range("FEED") == range(10, 201)


@pytest.mark.parametrize("asked, expected", [(5, p.FEED_MINUS_10 * 9), (250, p.FEED_PLUS_10 * 10)])
def test_grbls_own_ranges_bound_the_feed_override(asked, expected):
    h = Harness()
    h.answer_refresh()
    h.session.set_feed_override(asked)
    assert _sent(h) == expected  # 10 % and 200 %, GRBL's limits


def test_a_narrower_machine_is_never_asked_past_its_range():
    h = Harness()
    h.session.capabilities = NARROW
    h.answer_refresh()
    h.session.set_feed_override(10)
    assert _sent(h) == p.FEED_MINUS_10 * 5  # down to 50 %, no lower
    h.feed("<Idle|MPos:0,0,0|FS:0,0|Ov:50,100,100>")
    h.session.set_spindle_override(200)
    assert _sent(h) == p.SPINDLE_PLUS_10 * 2  # up to 120 %
    with pytest.raises(ValueError):
        h.session.set_rapid_override(25)  # a rate this machine does not take
    assert _sent(h) == b""
