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
