"""A big program's own checks come a moment after its picture (issue 24): until they
have run Start waits, saying so; then the Problems list shows their warnings and the
travel check stands in Start's way as for any program."""

import threading

from app.gcode import program as program_module
from app.gcode.program import Program
from tests.gcode.test_later_checks import SOURCE
from tests.ui.conftest import open_and_wait


def _problems(window) -> list[str]:
    model = window.program_panel.problems.model()
    return [model.index(row, 3).data() for row in range(model.rowCount())]


def test_start_waits_for_the_checks_then_they_are_shown(qtbot, window, tmp_path, monkeypatch):
    monkeypatch.setattr(program_module, "LATER_CHECKS_ROWS", 1)  # this small program counts as big
    release = threading.Event()
    real = Program.finish_checks
    monkeypatch.setattr(Program, "finish_checks", lambda self: release.wait(60) and real(self))
    path = tmp_path / "far.ngc"
    path.write_text(SOURCE)
    loaded = open_and_wait(qtbot, window, path)
    assert loaded.program.checks_pending
    assert not any("beyond travel" in text for text in _problems(window))
    assert window.preflight.blocks_start()
    assert not window.operator.can_start()
    level, title, text = window.notifier.messages[-1]
    assert (level, title) == ("error", "Program not checked yet") and "checked against the travel" in text

    with qtbot.waitSignal(window.loader.checked, timeout=60_000):
        release.set()
    qtbot.waitUntil(lambda: any("X+ beyond travel" in text for text in _problems(window)), timeout=10_000)
    assert "warning" in window.program_panel.tabs.tabText(1)
    assert [str(d) for d in window.program_panel.program.warnings] == \
        [str(d) for d in program_module.load(path).warnings]
    assert window.preflight.errors and window.preflight.title() == "Program leaves the travel"
    assert not window.operator.can_start()
    assert window.notifier.messages[-1][1] == "Program leaves the travel"


def test_checks_that_fail_are_said_and_keep_start_refused(qtbot, window, tmp_path, monkeypatch):
    monkeypatch.setattr(program_module, "LATER_CHECKS_ROWS", 1)

    def broken(*_args):
        raise RuntimeError("a bug in the checks")

    monkeypatch.setattr(program_module.checks, "run", broken)
    path = tmp_path / "far.ngc"
    path.write_text(SOURCE)
    with qtbot.waitSignal(window.loader.failed, timeout=60_000) as failed:
        window.open_file(path)
    assert "a bug in the checks" in failed.args[1]
    qtbot.waitUntil(lambda: window.loaded is not None, timeout=10_000)
    assert window.loaded.program.checks_pending and window.preflight.blocks_start()
