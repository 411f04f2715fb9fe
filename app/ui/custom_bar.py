"""The row of the operator's custom commands: one button per command, and "Commands…"
to edit them. The bar only asks (``run_requested``, ``edit_requested``);
``app/ui/custom_commands.py`` runs and keeps them."""

from __future__ import annotations

from PySide6.QtCore import QEvent, Signal
from PySide6.QtWidgets import QHBoxLayout, QPushButton, QWidget

from app.ui.numbers import fill


class CustomBar(QWidget):
    run_requested = Signal(object)  # a CustomCommand
    edit_requested = Signal()

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.row = QHBoxLayout(self)
        self.row.setContentsMargins(0, 0, 0, 0)
        self.buttons: list[QPushButton] = []
        self.commands: tuple = ()
        self.edit = QPushButton()
        self.edit.clicked.connect(self.edit_requested.emit)
        self.row.addWidget(self.edit)
        self.retranslate_ui()

    def set_commands(self, commands) -> None:
        for button in self.buttons:
            self.row.removeWidget(button)
            button.deleteLater()
        self.commands = tuple(commands)
        self.buttons = []
        for index, command in enumerate(self.commands):
            button = QPushButton(command.name)
            button.clicked.connect(lambda _=False, c=command: self.run_requested.emit(c))
            self.row.insertWidget(index, button)
            self.buttons.append(button)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.edit.setText(self.tr("Commands…"))
        self.edit.setToolTip(self.tr("Add, change or remove your own command buttons"))
        for button, command in zip(self.buttons, self.commands, strict=True):
            what = command.gcode if command.gcode else fill(self.tr("file %1"), command.file)
            tip = fill(self.tr("Runs: %1"), what)
            button.setToolTip(tip + ("\n" + self.tr("Asks first") if command.confirm else ""))

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)
