"""The live modal state panel while a job runs on the simulator (issue 21)."""

from __future__ import annotations

from tests.ui.conftest import home_when_allowed, open_and_wait

SOURCE = """G21 G90 G17
G0 Z5
S8000 M03
G1 Z-0.5 F300
G92 X0
o100 repeat [3]
G91 G1 X4 F450
o100 endrepeat
G90 G0 Z5
M05
M30
"""


def test_the_panel_follows_the_job_line_by_line(qtbot, window, tmp_path):
    panel = window.live_panel
    shown = []
    original = panel.show_state

    def spy(view, feed, rpm, line, lines, context):
        original(view, feed, rpm, line, lines, context)
        shown.append({key: label.text() for key, label in panel.values.items()})

    panel.show_state = spy
    dro_g92 = []
    original_dro = window.dro_panel.show_state

    def dro_spy(systems, work, g92=""):
        original_dro(systems, work, g92)
        dro_g92.append(window.dro_panel.g92.text())

    window.dro_panel.show_state = dro_spy
    window.operator.connect_to(f"sim://?speed=20&sd={tmp_path}")
    qtbot.waitUntil(lambda: window.binder.connected and window.binder.status is not None, timeout=60_000)
    home_when_allowed(qtbot, window)
    path = tmp_path / "loop.ngc"
    path.write_text(SOURCE)
    open_and_wait(qtbot, window, path)
    window.operator.start()
    qtbot.waitUntil(lambda: window.binder.last_job_event is not None, timeout=120_000)
    assert window.binder.last_job_event.completed
    passes = {row["context"] for row in shown}
    assert {"main program, pass 2", "main program, pass 3"} <= passes, passes
    in_loop = [row for row in shown if row["context"] == "main program, pass 2"]
    assert in_loop[-1]["codes"] == "G1 G17 G21 G91 G54 G40"
    assert in_loop[-1]["feed"].startswith("450")
    assert in_loop[-1]["spindle"].startswith("8")  # 8000 or 8.000, as the language writes it
    assert in_loop[-1]["line"].startswith("7 ") and in_loop[-1]["g92"] == "X0"
    moving = [row for row in shown if row["line"].startswith("7 ") and not row["feed"].endswith("—")]
    assert moving, "an actual feed while moving"
    assert any(int(row["spindle"].split("/")[1].strip().replace(",", "").replace(".", "")) > 1000
               for row in in_loop)  # measured (the simulated spindle tops out below the S word)
    assert "G92 in force: X0" in dro_g92  # the DRO says so too
    qtbot.waitUntil(lambda: panel.values["codes"].text() == "—", timeout=10_000)  # ended: dashes again
