"""A one-column table model over the program's source lines, built lazily: a million
lines cost nothing until they scroll into view (a QTableView with fixed row heights
never lays out every row, unlike a QListView). Shows ``line number  text`` and marks the line
being executed."""

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

    def set_lines(self, lines: Sequence[str], error_lines=()) -> None:
        self.beginResetModel()
        self._lines = lines
        self._width = len(str(len(lines)))
        self._current = -1
        self._errors = frozenset(line - 1 for line in error_lines)
        self.endResetModel()

    def rowCount(self, parent=QModelIndex()) -> int:  # noqa: B008 (Qt signature)
        return 0 if parent.isValid() else len(self._lines)

    def columnCount(self, parent=QModelIndex()) -> int:  # noqa: B008 (Qt signature)
        return 0 if parent.isValid() else 1

    def data(self, index: QModelIndex, role: int = Qt.ItemDataRole.DisplayRole):
        row = index.row()
        if role == Qt.ItemDataRole.DisplayRole:
            return f"{row + 1:>{self._width}}  {self._lines[row]}"
        if role == Qt.ItemDataRole.BackgroundRole:
            if row == self._current:
                return CURRENT_BRUSH
            if row in self._errors:
                return ERROR_BRUSH
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
