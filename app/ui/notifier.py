"""Messages to the operator that never block the event loop.

``Notifier.error/warning/info`` show a non-modal message box (one per title, reused)
and emit ``notified``; tests read ``messages`` or pass ``show_boxes=False``.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Qt, Signal
from PySide6.QtWidgets import QApplication, QMessageBox, QWidget

ICONS = {
    "error": QMessageBox.Icon.Critical,
    "warning": QMessageBox.Icon.Warning,
    "info": QMessageBox.Icon.Information,
}


class Notifier(QObject):
    notified = Signal(str, str, str)  # level, title, text

    def __init__(self, parent: QWidget | None = None, show_boxes: bool = True):
        super().__init__(parent)
        self._parent = parent
        self.show_boxes = show_boxes
        self.messages: list[tuple[str, str, str]] = []
        self.boxes: dict[str, QMessageBox] = {}

    def error(self, title: str, text: str) -> None:
        self.notify("error", title, text)

    def warning(self, title: str, text: str) -> None:
        self.notify("warning", title, text)

    def info(self, title: str, text: str) -> None:
        self.notify("info", title, text)

    def notify(self, level: str, title: str, text: str, beep: bool = False) -> QMessageBox | None:
        self.messages.append((level, title, text))
        self.notified.emit(level, title, text)
        if beep:
            QApplication.beep()
        if not self.show_boxes:
            return None
        box = self.boxes.get(title)
        if box is None:
            box = QMessageBox(ICONS.get(level, QMessageBox.Icon.NoIcon), title, text, parent=self._parent)
            box.setWindowModality(Qt.WindowModality.NonModal)
            box.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
            box.destroyed.connect(lambda *_: self.boxes.pop(title, None))
            self.boxes[title] = box
        box.setText(text)
        box.show()
        box.raise_()
        return box

    def last(self) -> tuple[str, str, str] | None:
        return self.messages[-1] if self.messages else None
