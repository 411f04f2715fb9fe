"""The state table walked in the window: for every state (link x machine x homed x a
dialog waiting x a program that can run, and a machine without SD card, panel and cover)
every button, menu action (and so its shortcut) and panel control is enabled exactly as
the table says, with the reason in its tooltip when off; and a stale click the table
forbids is refused with that reason and sends nothing. Run again in Vietnamese: every
reason and refusal is translated."""

from __future__ import annotations

import itertools

import pytest

from app.ui.enabler import controls_of, reason_text
from app.ui.state_table import Inputs, Link, Machine, decide
from tests.ui.test_state_table import GRBL_LIKE
from tests.ui.untranslated import english_in_vietnamese, placeholders


def states(capabilities=None):
    both = (False, True)
    for link, machine, homed, dialog, program in itertools.product(Link, Machine, both, both, both):
        inputs = Inputs(link, machine, homed, dialog, program)
        yield inputs if capabilities is None else Inputs(link, machine, homed, dialog, program, capabilities)


def requests(window):
    """Control -> what a click on it (or its shortcut, or its signal) calls."""
    op, w = window.operator, window
    return {
        "home": lambda: op.home("NORMAL"), "home_recover": lambda: op.home("RECOVER"), "start": op.start,
        "start_here": lambda: w.start_here.ask(1), "pause": op.pause, "resume": op.resume, "stop": op.stop,
        "jog": lambda: op.jog("X", 1.0, 300.0), "spindle_on": lambda: op.spindle(1000),
        "spindle_off": lambda: op.spindle(0), "zero": lambda: op.zero("XY"),
        "check_mode": lambda: op.set_check_mode(True), "sd_save": lambda: op.upload("a.nc"),
        "sd_list": w.sd_panel.list_requested.emit,
        "sd_delete": lambda: w.sd_panel.delete_requested.emit("a.nc"),
        "sd_run": lambda: op.run_from_sd("a.nc"), "mdi": lambda: op.mdi("G0 X1"),
        "query": lambda: op.mdi("GET KP_X"),
    }


# Requests that reach the machine once allowed, whatever else the window holds (start and
# upload also need a loaded program; checked by their own tests).
SENT_WHEN_ALLOWED = {"home", "home_recover", "pause", "resume", "stop", "jog", "spindle_on", "spindle_off",
                     "zero", "check_mode", "sd_list", "sd_delete", "sd_run", "query"}


@pytest.fixture
def walked(window, monkeypatch):
    sent = []
    monkeypatch.setattr(window.link, "call", lambda name, *args: sent.append((name, args)))
    return window, sent


def _walk(window, sent, all_states, texts=None):
    from app.ui.enabler import apply

    calls = requests(window)
    for inputs in all_states:
        window.binder.inputs = lambda inputs=inputs: inputs
        window.binder.pending_motion = None
        apply(window, inputs)
        for control, targets in controls_of(window).items():
            verdict = decide(control, inputs)
            for target in targets:
                assert target.isEnabled() == verdict.allowed, (control, target, inputs)
                if not verdict.allowed:
                    assert reason_text(verdict) in target.toolTip(), (control, target.toolTip())
                    if texts is not None:
                        texts.append((control, target.toolTip()))
        for control, call in calls.items():
            verdict = decide(control, inputs)
            before, refusals = len(sent), len(window.operator.refused)
            call()
            if not verdict.allowed:
                assert len(sent) == before, (control, inputs, sent[before:])  # never sent, never queued
                assert window.operator.refused[refusals:] == [(control, verdict.reason)]
                message = window.status.currentMessage()
                assert reason_text(verdict) in message
                if texts is not None:
                    texts.append((control, message))
            elif control in SENT_WHEN_ALLOWED:
                assert len(sent) > before, (control, inputs)


def test_every_control_in_every_state_follows_the_table(walked):
    window, sent = walked
    _walk(window, sent, states())


def test_a_machine_without_sd_card_panel_or_cover(walked):
    window, sent = walked
    _walk(window, sent, (s for s in states(GRBL_LIKE) if s.link is Link.UP and s.machine is Machine.IDLE))
    assert "this machine has no SD card" in window.sd_panel.run.toolTip()
    assert window.console.counters.isHidden()  # no CRC link: no resend figures
    _walk(window, sent, [Inputs(Link.UP, Machine.IDLE, True)])
    assert not window.console.counters.isHidden()


@pytest.mark.slow
def test_the_walk_in_vietnamese_translates_every_reason(walked):
    window, sent = walked
    window.set_language("vi")
    texts = []
    _walk(window, sent, states(), texts)
    _walk(window, sent, (s for s in states(GRBL_LIKE) if s.link is Link.UP), texts)
    assert len(texts) > 1000
    assert "\n".join(english_in_vietnamese(texts)) == ""
    assert "\n".join(placeholders(texts)) == ""
