"""The tool table editor: one row per tool (number, diameter, length, comment),
range-checked with ``app.gcode.tools.check_tool``; a bad cell is marked and named
(row and field) and the dialog stays open until it is fixed. On OK the table is
saved next to the settings and handed to the loader, so the next program opened
uses it (T, G43 H, G41 D)."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtGui import QBrush, QColor
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
)

from app.gcode.tools import FILE_NAME, Tool, ToolError, check_tool, save_tools
from app.i18n import localize
from app.ui.numbers import fill, general, parse_number

COLUMNS = 4  # number, diameter, length, comment
_BAD = QBrush(QColor(255, 60, 60, 80))


class ToolTableDialog(QDialog):
    """Edits a copy of ``tools``; ``self.tools`` is the checked table after OK."""

    def __init__(self, tools: dict[int, Tool], parent=None):
        super().__init__(parent)
        self.setWindowTitle(self.tr("Tool table"))
        self.tools = dict(tools)
        self.table = QTableWidget(0, COLUMNS)
        self.table.setHorizontalHeaderLabels(
            [self.tr("Tool"), self.tr("Diameter (mm)"), self.tr("Length (mm)"), self.tr("Comment")])
        self.table.horizontalHeader().setStretchLastSection(True)
        for number in sorted(tools):
            tool = tools[number]
            self.add_row(tool.number, tool.diameter, tool.length, tool.comment)
        add, remove = QPushButton(self.tr("Add tool")), QPushButton(self.tr("Remove tool"))
        add.clicked.connect(lambda: self.add_row(self._next_number()))
        remove.clicked.connect(self.remove_selected)
        self.error = QLabel("")
        self.error.setStyleSheet("color: #e05050;")
        self.error.setWordWrap(True)
        ok, cancel = QDialogButtonBox.StandardButton.Ok, QDialogButtonBox.StandardButton.Cancel
        buttons = QDialogButtonBox(ok | cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        self.button_box = buttons
        row = QHBoxLayout()
        row.addWidget(add)
        row.addWidget(remove)
        row.addStretch(1)
        layout = QVBoxLayout(self)
        layout.addWidget(self.table)
        layout.addLayout(row)
        layout.addWidget(self.error)
        layout.addWidget(buttons)
        self.resize(560, 360)

    def _next_number(self) -> int:
        numbers = [int(t) for t in (self._text(r, 0) for r in range(self.table.rowCount())) if t.isdigit()]
        return max(numbers, default=0) + 1

    def add_row(self, number: int, diameter: float = 0.0, length: float = 0.0, comment: str = "") -> None:
        row = self.table.rowCount()
        self.table.insertRow(row)
        for column, text in enumerate((f"{number}", general(diameter), general(length), comment)):
            self.table.setItem(row, column, QTableWidgetItem(text))

    def focus_tool(self, number: int) -> None:
        """Select tool ``number``'s row (added when the table lacks it) and edit its diameter."""
        rows = [r for r in range(self.table.rowCount()) if self._text(r, 0) == str(number)]
        if not rows:
            self.add_row(number)
        row = rows[0] if rows else self.table.rowCount() - 1
        self.table.setCurrentCell(row, 1)
        self.table.editItem(self.table.item(row, 1))

    def remove_selected(self) -> None:
        for row in sorted({i.row() for i in self.table.selectedIndexes()}, reverse=True):
            self.table.removeRow(row)

    def _text(self, row: int, column: int) -> str:
        item = self.table.item(row, column)
        return item.text().strip() if item is not None else ""

    def _row_tool(self, row: int) -> Tool:
        texts = [self._text(row, c) for c in range(3)]
        names = (self.tr("tool number"), self.tr("diameter"), self.tr("length"))
        values = []
        for column, (text, name) in enumerate(zip(texts, names, strict=True)):
            try:
                values.append(int(text) if column == 0 else float(parse_number(text)))
            except ValueError:
                self._mark(row, column)
                message = fill(self.tr("row %1: %2 '%3' is not a number"), row + 1, name, text)
                raise ToolError(message) from None
        try:
            check_tool(*values)
        except ToolError as exc:
            self._mark(row, 1 if "diameter" in str(exc) else 2 if "length" in str(exc) else 0)
            message = fill(self.tr("row %1: %2"), row + 1, localize(exc.args[0]))
            raise ToolError(message) from None
        return Tool(values[0], values[1], values[2], self._text(row, 3))

    def _mark(self, row: int, column: int) -> None:
        item = self.table.item(row, column)
        if item is not None:
            item.setBackground(_BAD)

    def checked_tools(self) -> tuple[dict[int, Tool] | None, list[str]]:
        """The table the rows describe, or None and the problems found."""
        problems, tools = [], {}
        for row in range(self.table.rowCount()):
            for column in range(COLUMNS):
                item = self.table.item(row, column)
                if item is not None:
                    item.setBackground(QBrush())
            try:
                tool = self._row_tool(row)
            except ToolError as exc:
                problems.append(str(exc))
                continue
            if tool.number in tools:
                self._mark(row, 0)
                problems.append(fill(self.tr("row %1: tool %2 is listed twice"), row + 1, tool.number))
            tools[tool.number] = tool
        return (None, problems) if problems else (tools, [])

    def accept(self) -> None:
        tools, problems = self.checked_tools()
        if problems:
            self.error.setText(fill(self.tr("Not saved: %1"), "; ".join(problems)))
            return
        self.tools = tools
        super().accept()


def open_tool_table(window, focus: int | None = None, then=None) -> ToolTableDialog:
    """Show the editor for ``window.tools`` (``focus``: that tool's row, added when
    missing); on OK save it, give it to the loader, then call ``then()`` if given."""
    dialog = ToolTableDialog(window.tools, window)
    if focus is not None:
        dialog.focus_tool(focus)

    def apply() -> None:
        window.tools = dialog.tools
        window.loader.tools = dialog.tools
        try:
            save_tools(Path(window.config_dir) / FILE_NAME, dialog.tools)
        except OSError as exc:
            why = QCoreApplication.translate("ToolTableDialog", "Cannot write the tool table: %1")
            window.notifier.error(QCoreApplication.translate("ToolTableDialog", "Tool table not saved"),
                                  fill(why, exc.strerror or exc))
            return
        saved = QCoreApplication.translate("ToolTableDialog",
                                           "Tool table saved: it applies to the next program opened")
        window.status.showMessage(saved, 5000)
        if then is not None:
            then()

    dialog.accepted.connect(apply)
    dialog.open()
    return dialog
