"""The program panel with an expanded (parametric) program: the moves each source line
produced, the machine lines behind them, and where a running job is (subprogram, pass)."""

from PySide6.QtCore import Qt

from app.gcode import load_text
from app.ui.program.program_panel import ProgramPanel

PROGRAM = """o<hole> sub
  G0 X#1 Y0
  G1 Z-1 F100
  G0 Z1
o<hole> endsub
#1 = 0
o1 while [#1 LT 3]
  o<hole> call [#1 * 10]
  #1 = [#1 + 1]
o1 endwhile
M2
"""


def test_each_source_line_shows_the_moves_it_produced(qtbot):
    panel = ProgramPanel()
    qtbot.addWidget(panel)
    program = load_text(PROGRAM)
    panel.show_program(program, "holes.ngc")
    model = panel.source_model
    assert model.columnCount() == 2
    call = model.index(7, 1)  # line 8: the call inside the loop
    assert model.data(call) == "9 moves"  # English plural forms from cnc_en.ts
    assert model.data(model.index(0, 1)) is None  # the sub's own lines run only through the call
    tip = model.data(call, Qt.ItemDataRole.ToolTipRole)
    assert "line 8" in tip and "G00 X0 Y0" in tip and "G00 X20" in tip


def test_the_status_names_subprogram_and_pass_while_cutting(qtbot):
    panel = ProgramPanel()
    qtbot.addWidget(panel)
    program = load_text(PROGRAM)
    panel.show_program(program, "holes.ngc")
    last = program.device_count - 2  # the last retract, before M2
    panel.show_device_line(program, last)
    assert panel.source_model.current_line == 8
    assert panel.context.text() == "in subprogram o<hole>, loop pass 3"
    assert not panel.context.isHidden()


def test_a_plain_program_keeps_one_column_and_no_context(qtbot):
    panel = ProgramPanel()
    qtbot.addWidget(panel)
    program = load_text("G0 X1\nG1 X2 F100\nM2\n")
    panel.show_program(program)
    assert panel.source_model.columnCount() == 1
    panel.show_device_line(program, 1)
    assert panel.source_model.current_line == 2 and panel.context.isHidden()
