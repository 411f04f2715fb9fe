"""Issue 18 in the window: why the machine holds, in words with its source, and the
resend rate of the last minute in the link indicator's and the status bar's tooltips."""

from __future__ import annotations

from app.comm.events import HoldEvent, LinkEvent
from app.comm.holds import hold_text


def test_a_hold_shows_its_reason_and_source_until_the_machine_runs(window):
    window.binder.on_hold(HoldEvent("PANEL", "HOLD", "panel", hold_text("PANEL")))
    message = window.status.currentMessage()
    assert "the machine's panel" in message and "held from the machine's panel" in message
    window.binder.on_hold(HoldEvent("LINK", "HOLD", "link", hold_text("LINK")))
    assert "lost the link" in window.status.currentMessage()
    window.binder.on_hold(HoldEvent("", "RUN"))
    assert window.status.currentMessage() == ""


def test_the_link_tooltip_gives_the_resend_rate_of_the_last_minute(window):
    window.binder.on_link(LinkEvent("CONNECTED", 0.0, 0.125, True, "", 400, 50))
    assert "12.5 %" in window.connection.link.toolTip() and "400" in window.connection.link.toolTip()
    assert window.status.toolTip() == window.connection.link.toolTip()
    assert "12.5 % resends" in window.connection.link.text()
