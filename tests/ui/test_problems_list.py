"""The Problems list: every finding listed, each row made only when it is shown."""

from PySide6.QtCore import Qt

from app.gcode import load_text
from app.gcode.diagnostics import ERROR, WARNING, Diagnostic
from app.ui.program import problems_model
from app.ui.program.program_panel import ProgramPanel


def _findings(n: int) -> tuple[list[Diagnostic], list[Diagnostic]]:
    errors = [Diagnostic(2, 7, ERROR, "Q word with no G5, G64, G73, G83 or M61 to use it")]
    warnings = [Diagnostic(10 + k, 0, WARNING, f"X {200 + k} mm beyond travel") for k in range(n)]
    return errors, warnings


def test_every_finding_is_listed_and_only_shown_rows_are_made(qtbot, monkeypatch):
    said = []
    real = problems_model.localize
    monkeypatch.setattr(problems_model, "localize", lambda text: said.append(text) or real(text))
    panel = ProgramPanel()
    qtbot.addWidget(panel)
    panel.resize(600, 400)
    panel.show()
    panel.tabs.setCurrentWidget(panel.problems_page)
    errors, warnings = _findings(20_000)
    panel._fill_problems(errors, warnings)
    qtbot.waitExposed(panel)
    qtbot.waitUntil(lambda: len(said) > 0, timeout=10_000)  # the rows on the screen are made
    panel.problems.viewport().repaint()  # and once more, laid out: still only those rows
    model = panel.problems.model()
    assert model.rowCount() == 20_001  # no cap, no "... and N more" row
    assert len(said) < 2_000, "messages were made for rows nobody sees"
    last = model.index(20_000, 3)
    assert last.data() == "X 20199 mm beyond travel"
    assert last.data(Qt.ItemDataRole.ToolTipRole) == "X 20199 mm beyond travel"
    assert model.index(20_000, 0).data() == "20009" and model.index(20_000, 1).data() == ""
    assert model.index(0, 1).data() == "7" and model.index(0, 2).data() == "error"
    assert model.index(0, 2).data(Qt.ItemDataRole.ForegroundRole).color() == Qt.GlobalColor.red
    assert model.index(1, 2).data(Qt.ItemDataRole.ForegroundRole).color() == Qt.GlobalColor.darkYellow
    assert panel.tabs.tabText(1) == "Problems (1 error, 20000 warnings)"


def test_activating_a_problem_goes_to_its_line(qtbot):
    panel = ProgramPanel()
    qtbot.addWidget(panel)
    program = load_text("G21 G90\nG0 X10 Y10\nG1 X20 Q5 F100\nG1 X30\nM2\n")
    panel.show_program(program, "q.ngc")
    chosen = []
    panel.line_activated.connect(chosen.append)
    model = panel.problems.model()
    assert [model.index(0, c).data() for c in range(3)] == ["3", str(program.errors[0].column), "error"]
    panel.problems.activated.emit(model.index(0, 3))
    assert chosen == [3] and panel.source.currentIndex().row() == 2
    assert panel.tabs.currentWidget() is panel.source


def test_headers_follow_the_language(qtbot):
    panel = ProgramPanel()
    qtbot.addWidget(panel)
    header = panel.problems.model().headerData
    assert [header(c, Qt.Orientation.Horizontal) for c in range(4)] == ["Line", "Col", "", "Message"]
    assert header(0, Qt.Orientation.Vertical) is None
