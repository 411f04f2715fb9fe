"""The prompt shown while the machine holds at a program stop or a tool change.

Not modal: while the machine holds the operator may touch off in the window (jog,
hold to jog, set a work zero; docs/protocol.md, "Program stops and tool changes"), and
the prompt says so. It names the line (source line and device line) and, for ``M06``,
the tool with its diameter from the tool table when the table knows it. "Continue"
emits ``continue_requested``, "Stop job" ``stop_requested``; ``dismiss()`` closes it
when the job went on or ended by other means (the machine panel's OK or EXIT, the STOP button).
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtWidgets import QMessageBox, QWidget

from app.gcode import tools
from app.ui.numbers import decimal


def tool_diameter(number: int | None, config_dir: Path | None = None) -> float | None:
    """The diameter of tool ``number`` from the tool table (``app.gcode.tools``), if any."""
    if number is None:
        return None
    path = Path(config_dir) / tools.FILE_NAME if config_dir is not None else tools.default_path()
    entry = tools.load_tools(path).tools.get(number)
    return entry.diameter if entry is not None and entry.diameter > 0 else None


class StopPrompt(QMessageBox):
    continue_requested = Signal()
    stop_requested = Signal()

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setIcon(QMessageBox.Icon.Question)
        self.continue_button = self.addButton("", QMessageBox.ButtonRole.AcceptRole)
        self.stop_button = self.addButton("", QMessageBox.ButtonRole.RejectRole)
        self.setDefaultButton(self.continue_button)
        self.setWindowModality(Qt.WindowModality.NonModal)  # the jog and zero stay usable
        self.buttonClicked.connect(self._clicked)
        self.index: int | None = None
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        """The buttons in the current language (the text is set anew at each stop)."""
        self.continue_button.setText(self.tr("Continue"))
        self.stop_button.setText(self.tr("Stop job"))

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def show_stop(self, event, source_line: int, diameter: float | None) -> None:
        """Show the prompt for ``event`` (a ``ProgramStopEvent``) at ``source_line``."""
        self.index = event.index
        self.setWindowTitle(self.tr("Tool change") if event.code == 6 else self.tr("Program stop"))
        self.setText(self._headline(event, source_line))
        self.setInformativeText(self._detail(event, diameter) + " " + self.tr(
            "Before continuing you may jog and set a work zero (touch off); Continue first "
            "brings the tool back above where it stopped."))
        self.show()

    def _headline(self, event, source_line: int) -> str:
        if event.code == 6:
            return self.tr("Tool change at line %1 (%2): the spindle is off and Z is up.").replace(
                "%1", str(source_line)).replace("%2", event.line)
        kind = self.tr("Optional stop") if event.code == 1 else self.tr("Program stop")
        return self.tr("%1 at line %2 (%3): the machine holds.").replace("%1", kind).replace(
            "%2", str(source_line)).replace("%3", event.line)

    def _detail(self, event, diameter: float | None) -> str:
        if event.code != 6:
            return self.tr("Continue goes on with the next line.")
        if event.tool is None:
            tool = self.tr("Fit the next tool (the program names none).")
        elif diameter is None:
            tool = self.tr("Fit tool %1 (diameter unknown: not in the tool table).").replace(
                "%1", str(event.tool))
        else:
            tool = self.tr("Fit tool %1 (diameter %2 mm).").replace("%1", str(event.tool)).replace(
                "%2", decimal(diameter, 3))

        return tool + " " + self.tr("Continue restarts the spindle, lowers Z and goes on.")

    def _clicked(self, button) -> None:
        self.index = None
        if button is self.continue_button:
            self.continue_requested.emit()
        else:
            self.stop_requested.emit()

    def keyPressEvent(self, event) -> None:  # noqa: N802 (Qt override)
        """Escape neither continues nor stops: the operator answers with a button."""
        if event.key() == Qt.Key.Key_Escape:
            event.ignore()
            return
        super().keyPressEvent(event)

    def closeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if self.index is not None:  # closing the window is no answer
            event.ignore()
            return
        super().closeEvent(event)

    def dismiss(self) -> None:
        """Close without a choice (the job went on or ended by other means)."""
        self.index = None
        if self.isVisible():
            self.done(0)
