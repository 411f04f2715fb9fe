"""The full DRO against the simulator (issue 21): the six work systems read on connect,
a system chosen and a row typed into reach the machine, the preflight follows the
active system, "go to" rapids at the top of Z first, and the state table governs it."""

from __future__ import annotations

from PySide6.QtCore import Qt

from app.ui.work_offsets import SYSTEMS
from tests.ui.conftest import home_when_allowed, open_and_wait

SPEED = 20
SOURCE = "G21 G90\nG0 Z5\nG0 X0 Y0\nG1 Z-1 F600\nG1 X120\nG1 Y20\nG0 Z5\n"


def _idle(window) -> bool:
    status = window.binder.status
    return status is not None and status.state == "IDLE" and window.binder.state == "READY"


def _connect_and_home(qtbot, window, tmp_path) -> None:
    window.operator.connect_to(f"sim://?speed={SPEED}&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    qtbot.waitUntil(lambda: window.binder.status.homed and _idle(window), timeout=60_000)


def test_the_dro_reads_every_system_and_changes_reach_the_machine(qtbot, window, tmp_path):
    panel, dro = window.dro_panel, window.dro
    _connect_and_home(qtbot, window, tmp_path)
    qtbot.waitUntil(lambda: all(None not in row for row in dro.systems.rows.values()), timeout=20_000)
    assert dro.systems.active == 54 and panel.wcs.currentText() == "G54"
    assert panel.table.item(0, 2).text().replace(",", ".") == "20.000"  # the profile's default Z
    status = window.binder.status
    assert panel.machine["Z"].text().replace(",", ".") == f"{status.z + 20.0:.3f}"
    path = tmp_path / "wide.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    qtbot.waitUntil(lambda: None not in window.preflight.offset, timeout=10_000)
    assert not window.preflight.errors
    panel.table.item(SYSTEMS.index(55), 0).setText("50")  # typed into G55's X
    qtbot.waitUntil(lambda: dro.systems.rows[55][0] == 50.0, timeout=10_000)
    assert not window.preflight.errors  # G54 still active
    panel.wcs.activated.emit(SYSTEMS.index(55))  # the operator picks G55
    qtbot.waitUntil(lambda: dro.systems.active == 55, timeout=10_000)
    qtbot.waitUntil(lambda: bool(window.preflight.errors), timeout=10_000)  # X0..120 from machine X50
    assert "X+" in window.preflight.message()
    qtbot.waitUntil(lambda: abs(window.binder.status.x - (0.0 - 50.0)) < 0.01, timeout=10_000)
    assert window.preview3d._travel[1][0] == 50.0  # the travel box drawn around G55's zero
    assert panel.work["X"].text().replace(",", ".") == "-50.000"
    assert panel.machine["X"].text().replace(",", ".") == "0.000"
    panel.wcs.activated.emit(SYSTEMS.index(54))
    qtbot.waitUntil(lambda: not window.preflight.errors, timeout=10_000)


def test_go_to_a_typed_position_and_work_zero(qtbot, window, tmp_path):
    panel, dro = window.dro_panel, window.dro
    _connect_and_home(qtbot, window, tmp_path)
    qtbot.waitUntil(lambda: None not in dro.systems.offset(), timeout=20_000)
    window.link.call("send_command", "SET AFTERJOB 0")  # no lift after each job: Z stays where sent
    panel.target["X"].setText("12,5")  # a decimal comma, as typed in Vietnamese
    panel.target["Y"].setText("7")
    qtbot.mouseClick(panel.go_to, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    qtbot.waitUntil(lambda: _idle(window), timeout=60_000)
    status = window.binder.status
    assert abs(status.x - 12.5) < 0.01 and abs(status.y - 7.0) < 0.01
    assert abs(status.z - (window.profile.travel.z_max - 20.0)) < 0.01  # stayed at the top of Z
    panel.target["Z"].setText("-2")
    window.binder.last_job_event = None
    qtbot.mouseClick(panel.go_to, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    qtbot.waitUntil(lambda: _idle(window), timeout=60_000)
    assert abs(window.binder.status.z + 2.0) < 0.01
    window.binder.last_job_event = None
    qtbot.mouseClick(panel.go_zero, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=60_000)
    qtbot.waitUntil(lambda: _idle(window), timeout=60_000)
    status = window.binder.status
    assert max(abs(status.x), abs(status.y), abs(status.z)) < 0.01


def test_bad_input_is_named_and_nothing_is_sent(qtbot, window):
    panel = window.dro_panel
    said = []
    panel.refused.connect(said.append)
    panel.target["X"].setText("abc")
    moves = []
    panel.move_requested.connect(moves.append)
    panel.go_to.setEnabled(True)
    qtbot.mouseClick(panel.go_to, Qt.MouseButton.LeftButton)
    assert moves == [] and "X" in said[-1] and "abc" in said[-1]
    panel._showing = False
    panel.show_state(window.dro.systems, None)
    panel.table.item(1, 2).setText("1..2")
    assert "G55" in said[-1] and "Z" in said[-1]


def test_the_state_table_governs_the_dro(qtbot, window):
    panel = window.dro_panel
    assert not panel.wcs.isEnabled() and not panel.table.isEnabled()  # not connected
    assert not panel.go_to.isEnabled() and not panel.go_zero.isEnabled()
    assert not panel.zero["X"].isEnabled()
    assert "Not now" in panel.go_to.toolTip()
    window.dro.move_to({"X": 1.0})  # a stale request is refused, with the reason
    assert window.operator.refused[-1][0] == "go_to"


def test_a_program_s_g55_is_where_the_machine_holds_g55(qtbot, window, tmp_path):
    panel, dro = window.dro_panel, window.dro
    _connect_and_home(qtbot, window, tmp_path)
    qtbot.waitUntil(lambda: dro.systems.for_programs() is not None, timeout=20_000)
    path = tmp_path / "g55.ngc"
    path.write_text("G21 G90\nG55\n" + SOURCE.split("\n", 1)[1])
    open_and_wait(qtbot, window, path)
    qtbot.waitUntil(lambda: None not in window.preflight.offset, timeout=10_000)
    assert not window.preflight.errors  # G55 = G54 on this machine so far
    before = window.loaded
    panel.table.item(SYSTEMS.index(55), 0).setText("50")
    qtbot.waitUntil(lambda: window.loaded is not before, timeout=30_000)  # read again with the new G55
    qtbot.waitUntil(lambda: bool(window.preflight.errors), timeout=10_000)
    assert "X+" in window.preflight.message()
    assert window.loaded.program.ops.end[:, 0].max() > 150.0  # the preview draws it there too


def test_a_cell_being_typed_into_is_not_overwritten_by_the_next_status(qtbot, window):
    from app.ui.work_offsets import WorkSystems

    panel = window.dro_panel
    window.show()
    systems = WorkSystems()
    for name, value in (("WCS", 54), ("G54_X", 1.0), ("G55_X", 2.0)):
        systems.take("GET", (name,), f"{name} {value}", True)
    panel.show_state(systems, (0.0, 0.0, 0.0))
    item = panel.table.item(SYSTEMS.index(55), 0)
    panel.table.setEnabled(True)
    panel.table.setCurrentItem(item)
    panel.table.editItem(item)
    assert panel.table.state() == panel.table.State.EditingState
    systems.take("GET", ("G55_X",), "G55_X 3", True)
    systems.take("GET", ("G54_X",), "G54_X 4", True)
    panel.show_state(systems, (0.0, 0.0, 0.0))
    assert item.text().replace(",", ".") == "2.000"  # left to the operator
    assert panel.table.item(0, 0).text().replace(",", ".") == "4.000"
