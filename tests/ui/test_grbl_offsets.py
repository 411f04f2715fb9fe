"""The DRO's work systems on a GRBL machine come from ``$#`` (issue 23): a read that fails
(GRBL refuses ``$#`` in check mode or while it runs, or a reset cuts it off) is said, the
DRO shows no offsets rather than stale ones or the live offset as G54's, and they are
read again once the machine is back."""

from __future__ import annotations

from app.ui.work_offsets import WorkSystems
from tests.ui.test_grbl_features import WAIT, connect_grbl, systems_read, unlocked, with_systems_in_check_mode


def test_a_failed_read_keeps_the_systems_unknown_and_only_no_systems_means_one_offset():
    for code in ("error:8", "RESET", "TIMEOUT", "LINK_LOST"):
        systems = WorkSystems()
        assert not systems.take("GET", ("WCS",), "not now", False, code)
        assert systems.supported is None and systems.offset() == [None, None, None]
    systems = WorkSystems()
    assert systems.take("GET", ("WCS",), "", False, "BAD_PARAM") and systems.supported is False


def test_a_refused_dollar_hash_is_said_and_read_again_once_the_machine_is_back(qtbot, make_window):
    window, machine = with_systems_in_check_mode(qtbot, make_window)
    dro = window.dro
    dro.read_all()  # as after a reconnect: GRBL refuses $# in check mode (error 8)
    qtbot.waitUntil(lambda: window.grbl.unread is not None, timeout=WAIT)
    said = window.console.log
    window.console.flush()
    assert "The work offsets could not be read" in said.toPlainText()
    assert dro.systems.supported is None and dro.systems.rows[54] == [None, None, None]
    assert window.dro.panel.table.item(0, 0).text() != "0.000"  # none shown as real
    window.controls.check_mode.setChecked(False)  # GRBL resets as it leaves check mode
    qtbot.waitUntil(lambda: not machine.check_mode, timeout=WAIT)
    qtbot.waitUntil(lambda: systems_read(dro), timeout=WAIT)
    assert window.grbl.unread is None and dro.systems.rows[54] == [0.0, 0.0, 20.0]


def test_a_read_cut_off_by_the_reset_after_a_hard_limit_is_read_again_after_it(qtbot, make_window):
    window, _machine = connect_grbl(qtbot, make_window)
    unlocked(qtbot, window)
    dro, bar = window.dro, window.grbl.alarm
    qtbot.waitUntil(lambda: systems_read(dro), timeout=WAIT)
    window.link.sim.trip_limit("X")  # ALARM:1: GRBL answers nothing until it is reset
    qtbot.waitUntil(lambda: bar.shown and bar.buttons["reset"].isVisible(), timeout=WAIT)
    dro.read_all()  # as after a job the alarm ended: its $# waits in the machine's buffer
    qtbot.waitUntil(lambda: b"$#" in bytes(window.link.sim.machine.rx), timeout=WAIT)
    assert dro.systems.supported is None
    bar.buttons["reset"].click()
    qtbot.waitUntil(lambda: systems_read(dro), timeout=WAIT)
    window.console.flush()
    assert "The work offsets could not be read (the machine was reset)" in window.console.log.toPlainText()
    assert dro.systems.rows[54] == [0.0, 0.0, 20.0] and window.grbl.unread is None


def test_a_read_failing_again_and_again_is_tried_less_and_less_often(qtbot, window, monkeypatch):
    from app.comm.driver import GRBL_CAPABILITIES
    from app.comm.events import CommandResult, StatusEvent

    monkeypatch.setattr(window.link.worker.session, "capabilities", GRBL_CAPABILITIES, raising=False)
    grbl, reads = window.grbl, []
    monkeypatch.setattr(window.dro, "read_all", lambda url="": reads.append(url))
    idle = lambda t: StatusEvent("grbl-1", "IDLE", 0, 0, 0, -1, -1, -1, 0, "", time=t)  # noqa: E731
    failed = CommandResult(1, "GET", ("WCS",), False, "a reason that passes", "error:8")
    waits = []
    for now in (0.0, 100.0, 200.0, 300.0):
        window.binder.status = idle(now)
        grbl.on_command(failed)
        t = now
        while not reads:
            t += 1.0
            grbl.on_status(idle(t))
        waits.append(t - now)
        reads.clear()
    assert waits == [5.0, 10.0, 20.0, 40.0]
    grbl.on_command(CommandResult(2, "GET", ("WCS",), True, "WCS 54"))
    assert grbl.failed_reads == 0
