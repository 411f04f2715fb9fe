"""GRBL's ``$$`` settings in a dialog (issue 23): each setting's number, value, unit, name
and meaning (``app/comm/grbl/codes.py``, in the operator's language), edited in place,
backed up to a file and restored from one.

Nothing is written as it is typed: edits and a restored file become *changes*, listed as
``$n (name): old -> new`` (the diff) before anything is sent. *Send changes* writes them one
at a time: each ``$n=value`` goes alone (GRBL stops reading while it writes its EEPROM) and
the next only after its ``ok``; an ``error:N`` stops there, says the refusal in words and
keeps that change and the ones after it listed (nothing is lost). Then ``$$`` is read again,
so the table shows what the machine stored. A backup file is GRBL's own ``$$`` print-out
(``settings.read_backup``: a bad line is refused naming file and line, and nothing is sent).
The state table's ``machine_settings`` control decides when a write may go.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QEvent, Qt
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFileDialog,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
)

from app.atomic import write_atomic
from app.comm.grbl.settings import SettingChange, format_value, read_backup, same_value, table, write_backup
from app.gcode.reading import read_config
from app.i18n import localize
from app.ui.dro_panel import typed_number
from app.ui.numbers import fill

COLUMNS = 5  # setting, value, unit, name, meaning
VALUE = 1


class GrblSettingsDialog(QDialog):
    def __init__(self, window, grbl) -> None:
        super().__init__(window)
        self.w, self.grbl = window, grbl
        self.pending: dict[int, str] = {}  # setting -> the value to write (as GRBL takes it)
        self.sending: list[int] = []  # the settings still to write, in order
        self.in_flight: str | None = None  # the "$n=value" line awaiting its answer
        self._filling = False
        self.table = QTableWidget(0, COLUMNS)
        self.table.itemChanged.connect(self._edited)
        self.changes = QListWidget()
        self.note = QLabel()
        self.note.setWordWrap(True)
        self.buttons = {key: QPushButton() for key in ("read", "backup", "restore", "send", "discard")}
        self.buttons["read"].clicked.connect(self.read)
        self.buttons["backup"].clicked.connect(lambda: self.back_up())
        self.buttons["restore"].clicked.connect(lambda: self.restore())
        self.buttons["send"].clicked.connect(self.send_changes)
        self.buttons["discard"].clicked.connect(self.discard)
        self.changes_label = QLabel()
        row = QHBoxLayout()
        for key in ("read", "backup", "restore"):
            row.addWidget(self.buttons[key])
        row.addStretch(1)
        sending = QHBoxLayout()
        sending.addWidget(self.buttons["send"])
        sending.addWidget(self.buttons["discard"])
        sending.addStretch(1)
        close = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        close.rejected.connect(self.close)
        layout = QVBoxLayout(self)
        for part in (row, self.table, self.changes_label, self.changes, sending, self.note, close):
            (layout.addLayout if isinstance(part, QHBoxLayout) else layout.addWidget)(part)
        self.resize(900, 640)
        window.link.worker.command_finished.connect(self.on_command)
        grbl.settings_changed.connect(self.show_settings)
        self.retranslate_ui()
        self.show_settings()

    def retranslate_ui(self) -> None:
        self.setWindowTitle(self.tr("Machine settings ($$)"))
        self.table.setHorizontalHeaderLabels([self.tr("Setting"), self.tr("Value"), self.tr("Unit"),
                                              self.tr("Name"), self.tr("Meaning")])
        texts = {"read": self.tr("Read again"), "backup": self.tr("Back up to a file…"),
                 "restore": self.tr("Restore from a file…"), "send": self.tr("Send changes"),
                 "discard": self.tr("Discard changes")}
        for key, text in texts.items():
            self.buttons[key].setText(text)
        self.changes_label.setText(self.tr("Changes to send (one at a time, each waited for):"))
        self._show_changes()

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
            self.show_settings()
        super().changeEvent(event)

    # -- showing ---------------------------------------------------------------------

    @property
    def current(self) -> dict[int, str]:
        return self.grbl.settings

    def show_settings(self) -> None:
        """The table as the machine last printed it, with the values about to be sent."""
        self._filling = True
        rows = table(self.current)
        self.table.setRowCount(len(rows))
        for r, row in enumerate(rows):
            value = self.pending.get(row.number, row.value)
            cells = (f"${row.number}", value, localize(row.unit), localize(row.name), localize(row.meaning))
            for c, text in enumerate(cells):
                item = QTableWidgetItem(text)
                item.setData(Qt.ItemDataRole.UserRole, row.number)
                flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
                item.setFlags(flags | Qt.ItemFlag.ItemIsEditable if c == VALUE else flags)
                self.table.setItem(r, c, item)
        self.table.resizeColumnsToContents()
        self._filling = False
        self._show_changes()

    def diff(self) -> list[SettingChange]:
        return [SettingChange(n, self.current.get(n), v) for n, v in sorted(self.pending.items())]

    def _show_changes(self) -> None:
        self.changes.clear()
        for change in self.diff():
            self.changes.addItem(localize(change.describe()))
        idle = self.in_flight is None
        self.buttons["send"].setEnabled(bool(self.pending) and idle)
        self.buttons["discard"].setEnabled(bool(self.pending) and idle)
        self.buttons["restore"].setEnabled(idle)

    def say(self, text: str) -> None:
        self.note.setText(text)
        self.w.console.add_log("info", text)

    # -- editing ---------------------------------------------------------------------

    def _edited(self, item: QTableWidgetItem) -> None:
        if self._filling or item.column() != VALUE:
            return
        number = item.data(Qt.ItemDataRole.UserRole)
        value = typed_number(item.text())
        if value is None:
            self.say(fill(self.tr("$%1: “%2” is not a number; nothing changed"), number, item.text()))
            self.show_settings()
            return
        self.want({number: format_value(value)})

    def want(self, values: dict[int, str]) -> None:
        """Add ``values`` to the changes (a value equal to the machine's is no change)."""
        for number, value in values.items():
            if number in self.current and same_value(self.current[number], value):
                self.pending.pop(number, None)
            else:
                self.pending[number] = format_value(value)
        self.show_settings()

    def discard(self) -> None:
        self.pending.clear()
        self.show_settings()

    # -- files -----------------------------------------------------------------------

    def back_up(self, path: str | None = None) -> bool:
        """Write the machine's settings as GRBL prints them (``$n=value`` lines)."""
        if not self.current:
            self.say(self.tr("The machine has not sent its settings yet: nothing to back up."))
            return False
        if path is None:
            title, name = self.tr("Back up the machine's settings"), "grbl-settings.txt"
            kinds = self.tr("Settings (*.txt);;All files (*)")
            path, _ = QFileDialog.getSaveFileName(self, title, name, kinds)
            if not path:
                return False
        try:
            write_atomic(path, write_backup(self.current))
        except OSError as exc:
            self.say(fill(self.tr("Cannot write %1: %2"), path, exc.strerror or str(exc)))
            return False
        self.say(fill(self.tr("%n setting(s) backed up to %1", "", len(self.current)), path))
        return True

    def restore(self, path: str | None = None) -> bool:
        """Read a backup and list what differs as changes (sent only with Send changes);
        a bad file is refused naming file and line, and changes nothing."""
        if path is None:
            path, _ = QFileDialog.getOpenFileName(self, self.tr("Restore the machine's settings"), "",
                                                  self.tr("Settings (*.txt);;All files (*)"))
            if not path:
                return False
        try:
            wanted = read_backup(read_config(path), Path(path).name)
        except OSError as exc:
            why = self.tr("no such file") if isinstance(exc, FileNotFoundError) else exc.strerror or str(exc)
            self.say(fill(self.tr("Backup not read, nothing changed: %1"), f"{path}: {why}"))
            return False
        except ValueError as exc:  # the reader's message names the file and the line
            self.say(fill(self.tr("Backup not read, nothing changed: %1"), localize(exc.args[0])))
            return False
        unknown = sorted(n for n in wanted if n not in self.current)
        self.want({n: v for n, v in wanted.items() if n in self.current})
        said = fill(self.tr("%1: %n setting(s) differ from the machine's; check them, then Send changes.",
                            "", len(self.pending)), Path(path).name)
        if unknown:
            said += " " + fill(self.tr("Left out (this machine has no such setting): %1"),
                               " ".join(f"${n}" for n in unknown))
        self.say(said)
        return True

    # -- the machine -----------------------------------------------------------------

    def read(self) -> None:
        self.w.link.call("send_command", "$$")

    def send_changes(self) -> None:
        """Write the changes one by one, each after the answer to the one before."""
        if not self.pending or self.in_flight is not None or not self.w.operator.allowed("machine_settings"):
            return
        self.sending = sorted(self.pending)
        self._next()

    def _next(self) -> None:
        if not self.sending:
            self.in_flight = None
            self.say(self.tr("Every change was written; the settings are read again."))
            self.read()
            self._show_changes()
            return
        number = self.sending[0]
        value = self.pending[number]
        self.in_flight = f"${number}={value}"
        self.note.setText(fill(self.tr("Writing $%1=%2 (%3 left)…"), number, value, len(self.sending)))
        self.w.link.call("machine_call", "write_setting", (number, value))
        self._show_changes()

    def on_command(self, result) -> None:
        if self.in_flight is None or result.verb != self.in_flight:
            return
        number = self.sending.pop(0)
        if result.ok:
            self.grbl.settings[number] = self.pending.pop(number)
            self._next()
            self.show_settings()
            return
        self.in_flight, self.sending = None, []
        why = f"{result.code}: {localize(result.info)}".strip(": ")
        self.say(fill(self.tr("$%1 was refused (%2); it and the changes after it were not written."),
                      number, why))
        self.show_settings()
