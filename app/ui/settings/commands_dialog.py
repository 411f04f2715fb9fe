"""Edit the custom commands: a list of names on the left, the chosen one's fields on the
right (name, G-code lines or a file, ask first), Add and Remove. OK checks every
command (``CustomCommand.problem``) and stays open, naming the one at fault."""

from __future__ import annotations

from PySide6.QtWidgets import (
    QCheckBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QListWidget,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
)

from app.i18n import localize
from app.ui.numbers import fill
from app.ui.settings.commands import LIMIT, CustomCommand


class CommandsDialog(QDialog):
    def __init__(self, commands, parent=None) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("Custom commands"))
        self.commands = [dict(name=c.name, gcode=c.gcode, file=c.file, confirm=c.confirm) for c in commands]
        self.list = QListWidget()
        self.name, self.gcode, self.file = QLineEdit(), QPlainTextEdit(), QLineEdit()
        self.confirm = QCheckBox(self.tr("Ask before running"))
        self.problem = QLabel()
        form = QFormLayout()
        form.addRow(self.tr("Name"), self.name)
        form.addRow(self.tr("G-code lines"), self.gcode)
        form.addRow(self.tr("or a G-code file"), self.file)
        form.addRow("", self.confirm)
        self.add, self.remove = QPushButton(self.tr("Add")), QPushButton(self.tr("Remove"))
        self.add.clicked.connect(self._add)
        self.remove.clicked.connect(self._remove)
        standard = QDialogButtonBox.StandardButton
        buttons = QDialogButtonBox(standard.Ok | standard.Cancel)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        left = QVBoxLayout()
        left.addWidget(self.list)
        left.addWidget(self.add)
        left.addWidget(self.remove)
        top = QHBoxLayout()
        top.addLayout(left)
        top.addLayout(form)
        layout = QVBoxLayout(self)
        layout.addLayout(top)
        layout.addWidget(self.problem)
        layout.addWidget(buttons)
        self.list.addItems([c["name"] for c in self.commands])
        self.list.currentRowChanged.connect(self._show)
        for field in (self.name, self.file):
            field.textEdited.connect(self._store)
        self.gcode.textChanged.connect(self._store)
        self.confirm.toggled.connect(self._store)
        self._loading = False
        self.list.setCurrentRow(0 if self.commands else -1)
        self._show(self.list.currentRow())

    def _show(self, row: int) -> None:
        self._loading = True
        entry = self.commands[row] if 0 <= row < len(self.commands) else dict(name="", gcode="", file="",
                                                                               confirm=False)
        self.name.setText(entry["name"])
        self.gcode.setPlainText(entry["gcode"])
        self.file.setText(entry["file"])
        self.confirm.setChecked(entry["confirm"])
        for widget in (self.name, self.gcode, self.file, self.confirm, self.remove):
            widget.setEnabled(0 <= row < len(self.commands))
        self._loading = False

    def _store(self, *_args) -> None:
        row = self.list.currentRow()
        if self._loading or not 0 <= row < len(self.commands):
            return
        self.commands[row] = dict(name=self.name.text(), gcode=self.gcode.toPlainText(),
                                  file=self.file.text(), confirm=self.confirm.isChecked())
        self.list.item(row).setText(self.name.text())

    def _add(self) -> None:
        if len(self.commands) >= LIMIT:
            self.problem.setText(fill(self.tr("At most %1 commands"), LIMIT))
            return
        self.commands.append(dict(name=self.tr("New command"), gcode="", file="", confirm=False))
        self.list.addItem(self.commands[-1]["name"])
        self.list.setCurrentRow(len(self.commands) - 1)

    def _remove(self) -> None:
        row = self.list.currentRow()
        if 0 <= row < len(self.commands):
            del self.commands[row]
            self.list.takeItem(row)
            self._show(self.list.currentRow())

    def result_commands(self) -> tuple[CustomCommand, ...]:
        return tuple(CustomCommand(**entry) for entry in self.commands)

    def accept(self) -> None:
        for row, command in enumerate(self.result_commands()):
            problem = command.problem()
            if problem:
                self.list.setCurrentRow(row)
                self.problem.setText(fill(self.tr("Command %1 (%2): %3"), row + 1, command.name,
                                          localize(problem)))
                return
        super().accept()
