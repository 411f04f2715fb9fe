"""The problems list as a table model: line, column, kind and message of each error and
warning, made only when its row scrolls into view. A million-line program with thousands
of findings costs nothing when it arrives (a QTreeWidget built an item of five
properties for each, 40-100 ms of the window's first turn for 400 warnings), and every
finding is listed, not only the first few thousand."""

from __future__ import annotations

from PySide6.QtCore import QAbstractTableModel, QModelIndex, Qt
from PySide6.QtGui import QBrush

from app.i18n import localize

LINE, COLUMN, KIND, MESSAGE = range(4)
KIND_COLOURS = {"error": QBrush(Qt.GlobalColor.red), "warning": QBrush(Qt.GlobalColor.darkYellow)}


class ProblemsModel(QAbstractTableModel):
    """Rows of ``(kind, diagnostic)``, kind ``"error"`` or ``"warning"``; the window gives
    the words it shows for the kinds and the column titles (its translations)."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self._rows: list[tuple[str, object]] = []
        self._said: dict[str, str] = {}
        self._headers: list[str] = ["", "", "", ""]

    def set_problems(self, rows: list[tuple[str, object]], said: dict[str, str]) -> None:
        """Show ``rows``; ``said``: the word shown for each kind."""
        self.beginResetModel()
        self._rows, self._said = rows, said
        self.endResetModel()

    def set_headers(self, headers: list[str]) -> None:
        self._headers = list(headers)
        self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0, len(self._headers) - 1)

    def line_of(self, row: int) -> int:
        """The 1-based source line of row ``row`` (0 when it names none)."""
        return _number(self._rows[row][1], "line") if 0 <= row < len(self._rows) else 0

    def widest(self) -> tuple[str, str, str]:
        """The widest text of the line, column and kind columns (the largest number is the
        widest), found without making every row's texts."""
        lines = max((_number(d, "line") for _, d in self._rows), default=0)
        columns = max((_number(d, "column") for _, d in self._rows), default=0)
        return str(lines), str(columns or ""), max(self._said.values(), key=len, default="")

    def rowCount(self, parent=QModelIndex()) -> int:  # noqa: B008, N802 (Qt signature)
        return 0 if parent.isValid() else len(self._rows)

    def columnCount(self, parent=QModelIndex()) -> int:  # noqa: B008, N802 (Qt signature)
        return 0 if parent.isValid() else len(self._headers)

    def data(self, index: QModelIndex, role: int = Qt.ItemDataRole.DisplayRole):
        kind, diagnostic = self._rows[index.row()]
        column = index.column()
        if role == Qt.ItemDataRole.DisplayRole:
            return self._text(kind, diagnostic, column)
        if role == Qt.ItemDataRole.ToolTipRole and column == MESSAGE:
            return localize(diagnostic.message)  # the whole message where the column is too narrow
        if role == Qt.ItemDataRole.ForegroundRole and column == KIND:
            return KIND_COLOURS.get(kind)
        if role == Qt.ItemDataRole.UserRole:
            return self.line_of(index.row())
        return None

    def _text(self, kind: str, diagnostic, column: int) -> str:
        if column == LINE:
            return str(_number(diagnostic, "line"))
        if column == COLUMN:
            return str(_number(diagnostic, "column") or "")
        if column == KIND:
            return self._said.get(kind, kind)
        return localize(diagnostic.message)

    def headerData(self, section: int, orientation, role: int = Qt.ItemDataRole.DisplayRole):  # noqa: N802
        if orientation == Qt.Orientation.Horizontal and role == Qt.ItemDataRole.DisplayRole:
            return self._headers[section] if 0 <= section < len(self._headers) else None
        return None


def _number(diagnostic, name: str) -> int:
    """``diagnostic.line`` or ``.column`` (0 when it has none)."""
    return int(getattr(diagnostic, name, 0) or 0)
