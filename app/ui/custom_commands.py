"""Runs and keeps the operator's custom commands (``app/ui/settings/commands.py``): read
from ``commands.json`` when the window opens (a problem is told, the good commands
kept), shown in ``CustomBar``, edited in ``CommandsDialog`` and saved at once.

A command runs as a job of its own, as an MDI line does (``OperatorActions.run_lines``),
once the state table allows ``custom_commands``, after the operator's yes when it asks
first; a file that cannot be read is named with the reason and nothing is sent."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QObject
from PySide6.QtWidgets import QDialog, QMessageBox

from app.gcode.reading import SourceError, read_source
from app.i18n import localize
from app.ui.custom_bar import CustomBar
from app.ui.numbers import fill
from app.ui.settings.commands import FILE_NAME, load_commands, save_commands
from app.ui.settings.commands_dialog import CommandsDialog


def ask_yes(parent, title: str, text: str) -> bool:
    answer = QMessageBox.question(parent, title, text)
    return answer == QMessageBox.StandardButton.Yes


class CustomCommands(QObject):
    def __init__(self, window, bar: CustomBar) -> None:
        super().__init__(window)
        self.w, self.bar = window, bar
        self.path = Path(window.config_dir) / FILE_NAME
        self.ask = ask_yes  # (parent, title, text) -> the operator said yes
        loaded = load_commands(self.path)
        if loaded.problem:
            window.notifier.warning(self.tr("Custom commands"), localize(loaded.problem))
        bar.set_commands(loaded.commands)
        bar.run_requested.connect(self.run)
        bar.edit_requested.connect(self.edit)

    def run(self, command) -> bool:
        """Run ``command`` if the table allows it and the operator agrees; whether it was sent."""
        if not self.w.operator.allowed("custom_commands"):
            return False
        question = fill(self.tr("Run “%1” now?"), command.name)
        if command.confirm and not self.ask(self.w, command.name, question):
            return False
        text = command.gcode
        if command.file:
            try:
                text = read_source(Path(command.file)).decode("utf-8")
            except (SourceError, OSError, UnicodeError) as exc:
                reason = localize(exc.args[0]) if isinstance(exc, SourceError) else str(exc)
                said = fill(self.tr("%1: the file %2 cannot be read (%3)"), command.name, command.file,
                            reason)
                self.w.notifier.error(self.tr("Custom commands"), said)
                return False
        return self.w.operator.run_lines(text, command.name)

    def edit(self) -> CommandsDialog:
        dialog = CommandsDialog(self.bar.commands, self.w)
        dialog.finished.connect(lambda result: self._edited(dialog, result))
        dialog.open()
        return dialog

    def _edited(self, dialog: CommandsDialog, result: int) -> None:
        if result != QDialog.DialogCode.Accepted:
            return
        commands = dialog.result_commands()
        try:
            save_commands(self.path, commands)
        except OSError as exc:
            self.w.notifier.error(self.tr("Custom commands"),
                                  fill(self.tr("%1 cannot be written (%2)"), str(self.path), str(exc)))
        self.bar.set_commands(commands)
        self.w.binder.refresh_enabled()  # the new buttons follow the state table
