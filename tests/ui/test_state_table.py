"""The state table alone (no Qt): its shape, its rules, and how the window's view of the
session becomes its inputs; and how an MDI line maps to a control of the table."""

from __future__ import annotations

import itertools

import pytest

from app.capabilities import Capabilities
from app.ui.mdi import classify
from app.ui.state_table import (
    CONTROLS,
    LABELS,
    SAFE,
    Inputs,
    Link,
    Machine,
    decide,
    decide_all,
    link_of,
    machine_of,
)

FRAME = Capabilities()
GRBL_LIKE = Capabilities(sd_card=False, exact_resume=False, crc_link=False, oled_panel=False, cover=False)


def every_input(capabilities=FRAME):
    both = (False, True)
    for link, machine, homed, dialog, program in itertools.product(Link, Machine, both, both, both):
        yield Inputs(link, machine, homed, dialog, program, capabilities)


def test_every_control_has_a_verdict_and_a_reason_when_off():
    for inputs in every_input():
        verdicts = decide_all(inputs)
        assert set(verdicts) == set(CONTROLS) == set(LABELS)
        for control, verdict in verdicts.items():
            assert verdict.allowed != bool(verdict.reason), (control, inputs)


def test_the_link_decides_first():
    for inputs in every_input():
        allowed = {c for c, v in decide_all(inputs).items() if v.allowed}
        if inputs.link in (Link.NONE, Link.CONNECTING, Link.LOST):
            assert allowed == {"connect"}, inputs
        elif inputs.link is Link.DEGRADED:
            assert allowed <= SAFE | {"connect"}, inputs


def test_stop_is_always_there_while_the_link_is_up_and_a_dialog_leaves_only_what_makes_safer():
    for inputs in every_input():
        if inputs.link is Link.UP:
            assert decide("stop", inputs).allowed, inputs
            if inputs.dialog:
                allowed = {c for c, v in decide_all(inputs).items() if v.allowed}
                assert allowed <= SAFE | {"connect", "query"}, inputs


@pytest.mark.parametrize("machine", [Machine.HOMING, Machine.JOG, Machine.RUN_HOST, Machine.RUN_SD,
                                     Machine.HOLD, Machine.PROGRAM_STOP, Machine.UPLOAD])
def test_nothing_that_moves_starts_while_the_machine_is_busy(machine):
    inputs = Inputs(Link.UP, machine, homed=True, has_program=True)
    moving = ("home", "home_recover", "start", "start_here", "jog", "spindle_on", "zero", "sd_run", "mdi")
    touch_off = ("jog", "zero") if machine is Machine.PROGRAM_STOP else ()
    for control in (c for c in moving if c not in touch_off):
        verdict = decide(control, inputs)
        assert not verdict.allowed and verdict.reason, (control, machine)


def test_at_a_program_stop_the_operator_may_jog_and_set_zero_then_resume():
    at_stop = Inputs(Link.UP, Machine.PROGRAM_STOP, homed=True, has_program=True)
    for control in ("jog", "jog_hold", "zero", "resume", "stop"):
        assert decide(control, at_stop).allowed, control
    unhomed = Inputs(Link.UP, Machine.PROGRAM_STOP, homed=False)
    assert decide("zero", unhomed).reason == "home the machine first"
    jogging = Inputs(Link.UP, Machine.JOG, homed=True, has_program=True)  # a touch-off jog under way
    assert not decide("resume", jogging).allowed and decide("stop", jogging).allowed


def test_run_from_sd_can_be_paused_resumed_and_stopped():
    running = Inputs(Link.UP, Machine.RUN_SD, homed=True)
    assert decide("pause", running).allowed and decide("stop", running).allowed
    assert decide("resume", Inputs(Link.UP, Machine.HOLD, homed=True)).allowed


def test_homing_is_needed_for_motion_but_not_for_the_spindle_or_a_jog_off_the_switch():
    idle = Inputs(Link.UP, Machine.IDLE, homed=False, has_program=True)
    assert decide("start", idle).reason == "home the machine first"
    assert decide("mdi", idle).reason == "home the machine first"
    assert decide("spindle_on", idle).allowed and decide("jog", idle).allowed
    assert decide("start", Inputs(Link.UP, Machine.CHECK_MODE, homed=False, has_program=True)).allowed
    no_program = Inputs(Link.UP, Machine.IDLE, homed=True)
    assert decide("start", no_program).reason == "open a program that can run first"


def test_a_missing_capability_disables_its_controls_with_a_word_why():
    for inputs in every_input(GRBL_LIKE):
        for control in ("sd_save", "sd_list", "sd_delete", "sd_run"):
            assert decide(control, inputs).reason == "this machine has no SD card"
        assert decide("cover_switch", inputs).reason == "this machine has no cover switch"
        assert decide("panel", inputs).reason == "this machine has no panel of its own"
    assert GRBL_LIKE.missing() == ("sd_card", "exact_resume", "crc_link", "oled_panel", "cover")


@pytest.mark.parametrize(("session", "status", "flags", "check", "pending", "expected"), [
    ("READY", "IDLE", "H", False, None, Machine.IDLE),
    ("READY", "IDLE", "H", True, None, Machine.CHECK_MODE),
    ("READY", "IDLE", "-", False, "HOME", Machine.HOMING),  # sent, the status not yet HOMING
    ("READY", "HOMING", "-", False, "HOME", Machine.HOMING),
    ("READY", "IDLE", "H", False, "JOG", Machine.JOG),
    ("READY", "RUN", "HP", False, "SPINDLE", Machine.SPINDLE),
    ("READY", "JOG", "H", False, None, Machine.JOG),  # the after-job lift
    ("STREAMING", "RUN", "HP", False, None, Machine.RUN_HOST),
    ("STARTING", "IDLE", "H", False, None, Machine.RUN_HOST),
    ("PAUSED", "HOLD", "H", False, None, Machine.HOLD),
    ("STREAMING", "HOLD", "HW", False, None, Machine.PROGRAM_STOP),
    ("READY", "RUN", "HS", False, None, Machine.RUN_SD),
    ("READY", "HOLD", "HS", False, None, Machine.HOLD),
    ("READY", "HOLD", "HSW", False, None, Machine.PROGRAM_STOP),
    ("STREAMING", "JOG", "HW", False, None, Machine.JOG),  # a touch-off jog at the stop
    ("STREAMING", "HOLD", "HW", False, "JOG", Machine.JOG),  # sent, its status not yet in
    ("STREAMING", "IDLE", "W", False, None, Machine.PROGRAM_STOP),  # GRBL: idle at the host-held M6
    ("UPLOADING", "IDLE", "H", False, None, Machine.UPLOAD),
    ("STREAMING", "HOLD", "HC", False, None, Machine.COVER_OPEN),
    ("READY", "ALARM", "-", False, None, Machine.ALARM),
    ("RESUME_OFFERED", "HOLD", "H", False, None, Machine.HOLD),
    ("INTERRUPTED", "RUN", "H", False, None, Machine.RUN_HOST),
])
def test_machine_of(session, status, flags, check, pending, expected):
    assert machine_of(session, status, flags, check, pending) is expected


def test_link_of():
    assert link_of(False, "DISCONNECTED", "DISCONNECTED", False) is Link.NONE
    assert link_of(False, "CONNECTING", "DISCONNECTED", False) is Link.CONNECTING
    assert link_of(True, "READY", "CONNECTED", False) is Link.CONNECTING  # no status yet
    assert link_of(True, "READY", "CONNECTED", True) is Link.UP
    assert link_of(True, "STREAMING", "DEGRADED", True) is Link.DEGRADED
    assert link_of(True, "INTERRUPTED", "LOST", True) is Link.LOST
    assert link_of(False, "DISCONNECTED", "LOST", True) is Link.LOST


@pytest.mark.parametrize(("text", "control", "command"), [
    ("M3 S3000", "spindle_on", "SPINDLE 3000"),
    ("m03s2500", "spindle_on", "SPINDLE 2500"),
    ("S1200 M3", "spindle_on", "SPINDLE 1200"),
    ("M5", "spindle_off", "SPINDLE OFF"),
    ("M05 S0", "spindle_off", "SPINDLE OFF"),
    ("M3", "mdi", None),  # no speed: a G-code line, checked by the loader
    ("M4 S100", "mdi", None),
    ("G0 X10", "mdi", None),
    ("M3 S3000 G1 X5 F100", "mdi", None),
    ("HOME", "home", "HOME"),
    ("home recover", "home_recover", "home recover"),
    ("SD RUN a.nc", "sd_run", "SD RUN a.nc"),
    ("SD LIST", "sd_list", "SD LIST"),
    ("SET CHECK 1", "check_mode", "SET CHECK 1"),
    ("GET KP_X", "query", "GET KP_X"),
    ("JOG X 1 300", "jog", "JOG X 1 300"),
    ("SPINDLE OFF", "spindle_off", "SPINDLE OFF"),
    ("STOP", "stop", "STOP"),
])
def test_mdi_lines_follow_the_rule_of_their_control(text, control, command):
    line = classify(text)
    assert (line.control, line.command) == (control, command)
