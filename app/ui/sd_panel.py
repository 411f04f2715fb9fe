"""SD card panel: save the open program to the card (name suggested from the file,
progress, verified by the machine's CRC check), list, delete and run files."""

from __future__ import annotations

import re
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QEvent, Qt, Signal
from PySide6.QtWidgets import (
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QProgressBar,
    QPushButton,
    QTreeWidget,
    QTreeWidgetItem,
    QVBoxLayout,
    QWidget,
)

NAME_RE = re.compile(r"^[A-Za-z0-9_.-]{1,32}$")


def suggest_name(path: str | Path) -> str:
    """A card name from a file name: allowed characters only, at most 32, ending .nc."""
    stem = re.sub(r"[^A-Za-z0-9_-]+", "_", Path(path).stem).strip("_") or "program"
    return stem[:29] + ".nc"


def name_problem(name: str) -> str:
    """Why ``name`` cannot be used on the card ("" when it can)."""
    if NAME_RE.match(name) and name not in (".", ".."):
        return ""
    return QCoreApplication.translate("SdPanel", "a card name has 1 to 32 letters, digits, '_', '-' or '.'")


class SdPanel(QWidget):
    upload_requested = Signal(str)
    list_requested = Signal()
    delete_requested = Signal(str)
    run_requested = Signal(str)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.name = QLineEdit()
        self.save = QPushButton()
        self.save.clicked.connect(self._save)
        self.progress = QProgressBar()
        self.progress.setFormat("%p %")
        self.result = QLabel("")
        self.files = QTreeWidget()
        self.files.setRootIsDecorated(False)
        self.refresh = QPushButton()
        self.refresh.clicked.connect(self.list_requested.emit)
        self.delete = QPushButton()
        self.delete.clicked.connect(lambda: self._with_selected(self.delete_requested))
        self.run = QPushButton()
        self.run.clicked.connect(lambda: self._with_selected(self.run_requested))
        save_row = QHBoxLayout()
        save_row.addWidget(self.name, 1)
        save_row.addWidget(self.save)
        file_row = QHBoxLayout()
        for button in (self.refresh, self.delete, self.run):
            file_row.addWidget(button)
        layout = QVBoxLayout(self)
        layout.addLayout(save_row)
        layout.addWidget(self.progress)
        layout.addWidget(self.result)
        layout.addWidget(self.files, 1)
        layout.addLayout(file_row)
        for button in (self.save, self.refresh, self.delete, self.run):
            button.setEnabled(False)  # until the window's state table says otherwise
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.name.setPlaceholderText(self.tr("name on the card"))
        self.save.setText(self.tr("Save program to SD"))
        self.save.setToolTip(self.tr("send the open program to the card; the machine checks every line"))
        self.files.setHeaderLabels([self.tr("Name"), self.tr("Bytes"), self.tr("Lines")])
        self.refresh.setText(self.tr("Refresh"))
        self.delete.setText(self.tr("Delete"))
        self.run.setText(self.tr("Run from SD"))
        self.run.setToolTip(self.tr("the machine runs the file on its own, even without this computer"))

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def suggest_for(self, path: str | Path) -> None:
        self.name.setText(suggest_name(path))

    def _save(self) -> None:
        name = self.name.text().strip()
        problem = name_problem(name)
        if problem:
            self.result.setText(f"<span style='color:#e05050'>{problem}</span>")
            return
        self.result.setText(self.tr("uploading…"))
        self.progress.setValue(0)
        self.upload_requested.emit(name)

    def _with_selected(self, signal) -> None:
        item = self.files.currentItem()
        if item is not None:
            signal.emit(item.text(0))

    def lines_of(self, name: str) -> int:
        """The line count the card listed for ``name`` (0 if not listed)."""
        for index in range(self.files.topLevelItemCount()):
            item = self.files.topLevelItem(index)
            if item.text(0) == name and item.text(2).isdigit():
                return int(item.text(2))
        return 0

    def set_progress(self, done: int, total: int) -> None:
        self.progress.setMaximum(max(total, 1))
        self.progress.setValue(done)

    def upload_finished(self, completed: bool, text: str) -> None:
        colour = "#39a353" if completed else "#e05050"
        self.result.setText(f"<span style='color:{colour}'>{text}</span>")
        if completed:
            self.progress.setValue(self.progress.maximum())

    def set_files(self, rows) -> None:
        """``rows``: ``"<name> <bytes> <lines>"`` strings as the machine lists them."""
        self.files.clear()
        for row in rows:
            parts = str(row).split()
            item = QTreeWidgetItem((parts + ["", "", ""])[:3])
            for column in (1, 2):
                item.setTextAlignment(column, Qt.AlignmentFlag.AlignRight)
            self.files.addTopLevelItem(item)
        self.files.resizeColumnToContents(0)
