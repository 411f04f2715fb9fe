"""A one-column table model over the program's source lines, built lazily: a million
lines cost nothing until they scroll into view (a QTableView with fixed row heights
never lays out every row, unlike a QListView). Shows ``line number  text`` and marks the line
being executed. For an expanded (parametric) program a second column gives the moves each
line produced (a loop or a call: all of them), with the first machine lines as a tooltip."""

from __future__ import annotations

from collections.abc import Sequence

from PySide6.QtCore import QAbstractTableModel, QModelIndex, Qt
from PySide6.QtGui import QBrush, QColor

CURRENT_BRUSH = QBrush(QColor(255, 200, 0, 90))
ERROR_BRUSH = QBrush(QColor(255, 60, 60, 70))


class SourceModel(QAbstractTableModel):
    def __init__(self, parent=None):
        super().__init__(parent)
        self._lines: Sequence[str] = []
        self._width = 1
        self._current = -1  # 0-based row of the executing line
        self._errors: frozenset[int] = frozenset()
        self._moves = None  # per 1-based line, moves produced (expanded programs only)
        self._device_lines = None  # fn(line) -> the first machine lines it produced

    def set_lines(self, lines: Sequence[str], error_lines=(), moves=None, device_lines=None) -> None:
        """Show ``lines``; ``moves`` (per 1-based line) and ``device_lines(line)`` add the
        column of expanded moves."""
        self.beginResetModel()
        self._moves, self._device_lines = moves, device_lines
        self._lines = lines
        self._width = len(str(len(lines)))
        self._current = -1
        self._errors = frozenset(line - 1 for line in error_lines)
        self.endResetModel()

    def rowCount(self, parent=QModelIndex()) -> int:  # noqa: B008 (Qt signature)
        return 0 if parent.isValid() else len(self._lines)

    def columnCount(self, parent=QModelIndex()) -> int:  # noqa: B008 (Qt signature)
        return 0 if parent.isValid() else (1 if self._moves is None else 2)

    def data(self, index: QModelIndex, role: int = Qt.ItemDataRole.DisplayRole):
        row = index.row()
        if index.column() == 1:
            return self._moves_data(row, role)
        if role == Qt.ItemDataRole.DisplayRole:
            return f"{row + 1:>{self._width}}  {self._lines[row]}"
        if role == Qt.ItemDataRole.BackgroundRole:
            if row == self._current:
                return CURRENT_BRUSH
            if row in self._errors:
                return ERROR_BRUSH
        return None

    def _moves_data(self, row: int, role: int):
        count = int(self._moves[row + 1]) if row + 1 < len(self._moves) else 0
        if role == Qt.ItemDataRole.DisplayRole and count:
            return self.tr("%n move(s)", "", count)
        if role == Qt.ItemDataRole.TextAlignmentRole:
            return int(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
        if role == Qt.ItemDataRole.ToolTipRole and count and self._device_lines is not None:
            lines = self._device_lines(row + 1)
            more = count - len(lines)
            tail = ["", self.tr("… and %n more", "", more)] if more > 0 else []
            return "\n".join([self.tr("Machine lines made by line %1:").replace("%1", str(row + 1)),
                              *lines, *tail])
        return None

    @property
    def current_line(self) -> int:
        """1-based source line being executed (0 for none)."""
        return self._current + 1

    def set_current_line(self, line: int) -> None:
        """Mark 1-based ``line`` as the executing one (0 clears the mark)."""
        row = line - 1
        if row == self._current:
            return
        old, self._current = self._current, row
        for changed in (old, row):
            if 0 <= changed < len(self._lines):
                where = self.index(changed, 0)
                self.dataChanged.emit(where, where, [Qt.ItemDataRole.BackgroundRole])
