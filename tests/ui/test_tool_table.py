"""The tool table editor in the window: range checks, saving, and the loader using it."""

from __future__ import annotations

from app.gcode.tools import FILE_NAME, Tool, load_tools
from app.ui.settings.tools_dialog import ToolTableDialog, open_tool_table
from tests.ui.conftest import open_and_wait


def _set(dialog: ToolTableDialog, row: int, column: int, text: str) -> None:
    dialog.table.item(row, column).setText(text)


def test_editor_checks_each_cell_and_names_it(qtbot):
    dialog = ToolTableDialog({1: Tool(1, 6.0, 0.0, "6 mm")})
    qtbot.addWidget(dialog)
    dialog.add_row(2, 3.0)
    _set(dialog, 1, 1, "-4")
    dialog.accept()
    assert dialog.result() == 0 and "row 2" in dialog.error.text() and "diameter -4" in dialog.error.text()
    _set(dialog, 1, 1, "abc")
    assert dialog.checked_tools()[0] is None and "'abc' is not a number" in dialog.checked_tools()[1][0]
    _set(dialog, 1, 1, "4")
    _set(dialog, 1, 0, "1")
    assert "listed twice" in dialog.checked_tools()[1][0]
    _set(dialog, 1, 0, "2")
    dialog.accept()
    assert dialog.result() == 1
    assert dialog.tools == {1: Tool(1, 6.0, 0.0, "6 mm"), 2: Tool(2, 4.0, 0.0, "")}


def test_add_and_remove_rows(qtbot):
    dialog = ToolTableDialog({})
    qtbot.addWidget(dialog)
    dialog.add_row(dialog._next_number())
    dialog.add_row(dialog._next_number())
    assert [dialog.table.item(r, 0).text() for r in range(2)] == ["1", "2"]
    dialog.table.selectRow(0)
    dialog.remove_selected()
    assert dialog.table.rowCount() == 1 and dialog.table.item(0, 0).text() == "2"


def test_window_saves_the_table_and_the_loader_uses_it(qtbot, window, tmp_path):
    dialog = open_tool_table(window)
    dialog.add_row(1, 6.0, 2.5, "test tool")
    with qtbot.waitSignal(dialog.accepted):
        dialog.accept()
    path = window.config_dir / FILE_NAME
    assert load_tools(path).tools == {1: Tool(1, 6.0, 2.5, "test tool")}
    assert window.loader.tools == window.tools == {1: Tool(1, 6.0, 2.5, "test tool")}
    program_file = tmp_path / "g43.ngc"
    program_file.write_text("T1 M6\nG43\nG0 X1 Y1 Z0\nG41 D1 G1 X20 F100\nG40 G1 X30 Y-10\nM2\n")
    open_and_wait(qtbot, window, program_file)
    program = window.loaded.program
    assert not program.errors
    assert program.moves[0]["end"] == [1.0, 1.0, 2.5]  # the tool's length shifts Z


def test_damaged_table_is_reported_at_start(make_window, tmp_path, notifier):
    config = tmp_path / "cfg"
    config.mkdir()
    (config / FILE_NAME).write_text("{broken")
    window = make_window(config_dir=config)
    assert window.tools == {}
    assert any("tool table is damaged" in text for _, _, text in notifier.messages)


def test_a_missing_tool_offers_the_tool_table_on_that_tool_and_reloads(qtbot, window, tmp_path):
    """A LinuxCNC program asks for T3 (G43 H3, G41 D3) with T1 alone in the table: the
    Problems page offers the editor on T3's row; once saved the program loads cleanly."""
    from PySide6.QtCore import Qt

    window.tools = window.loader.tools = {1: Tool(1, 6.0)}
    path = tmp_path / "t3.ngc"
    path.write_text("G21 G90 F300\nT3 M6\nG43 H3\nG0 X10 Y10 Z5\nG1 Z-1\nG41 D3\nG1 X30\nG1 Y30\n"
                    "G40\nG0 Z5\nM2\n")
    loaded = open_and_wait(qtbot, window, path)
    assert any("Requested tool 3 not found" in str(e) for e in loaded.program.errors)
    panel = window.program_panel
    assert panel.tabs.currentWidget() is panel.problems_page
    assert panel.tool_button.isVisibleTo(panel) and "T3" in panel.tool_button.text()
    qtbot.mouseClick(panel.tool_button, Qt.MouseButton.LeftButton)
    dialog = window.operator.missing_tool.dialog
    assert dialog is not None and dialog.isVisible()
    row = dialog.table.currentRow()
    assert dialog.table.item(row, 0).text() == "3" and dialog.table.currentColumn() == 1
    assert [dialog.table.item(r, 0).text() for r in range(dialog.table.rowCount())] == ["1", "3"]
    dialog.table.item(row, 1).setText("4")
    with qtbot.waitSignal(window.loader.loaded, timeout=20_000) as blocker:
        dialog.button_box.button(dialog.button_box.StandardButton.Ok).click()
    assert blocker.args[0].program.errors == []
    assert load_tools(window.config_dir / FILE_NAME).tools[3] == Tool(3, 4.0)
    assert not panel.tool_button.isVisibleTo(panel)


def test_the_editor_focuses_a_tool_it_already_has(qtbot):
    dialog = ToolTableDialog({1: Tool(1, 6.0), 5: Tool(5, 2.0)})
    qtbot.addWidget(dialog)
    dialog.focus_tool(5)
    assert dialog.table.rowCount() == 2 and dialog.table.item(dialog.table.currentRow(), 0).text() == "5"
