"""The disconnect alert: a non-modal dialog (plus a beep) the moment the link is lost,
saying what was lost and what the machine did, then — once reconnected — the offer to
resume exactly where the job stopped."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QEvent, Qt, QTimer, Signal
from PySide6.QtWidgets import QApplication, QDialog, QHBoxLayout, QLabel, QPushButton, QVBoxLayout

from app.i18n import localize
from app.ui.numbers import integer

LOST_TEXT = {
    "usb": QT_TRANSLATE_NOOP("LinkAlert", "The USB link between this computer and the machine is lost: "
                                          "no valid frame for 3 s."),
    "uart": QT_TRANSLATE_NOOP("LinkAlert", "The machine's internal link (UART between the main board and the "
                                           "motion board) is lost."),
}


def _t(text: str) -> str:
    return QCoreApplication.translate("LinkAlert", text)


def machine_action(job_running: bool, from_sd: bool) -> str:
    if from_sd:
        return QCoreApplication.translate("LinkAlert",
                                          "The machine carries on with the job from its SD card.")
    if job_running:
        return QCoreApplication.translate("LinkAlert", "The machine holds the job on the path (feed hold), "
                                                       "spindle as it was: it has not lost its place.")
    return QCoreApplication.translate("LinkAlert", "No job was running; the machine stays where it is.")


class LinkAlert(QDialog):
    reconnect_requested = Signal()
    resume_requested = Signal()
    restart_requested = Signal()
    abandon_requested = Signal()

    def __init__(self, parent=None, beep_every_ms: int = 2000):
        super().__init__(parent)
        self.setWindowModality(Qt.WindowModality.NonModal)
        self.setMinimumWidth(460)
        self.headline = QLabel()
        self.headline.setStyleSheet("font-size: 14pt; font-weight: bold; color: #e03030;")
        self.body = QLabel()
        self.body.setWordWrap(True)
        self.reconnect, self.resume, self.restart = QPushButton(), QPushButton(), QPushButton()
        self.abandon, self.close_button = QPushButton(), QPushButton()
        self.reconnect.clicked.connect(self.reconnect_requested.emit)
        self.resume.clicked.connect(self.resume_requested.emit)
        self.restart.clicked.connect(self.restart_requested.emit)
        self.abandon.clicked.connect(self.abandon_requested.emit)
        self.close_button.clicked.connect(self.hide)
        row = QHBoxLayout()
        for button in (self.reconnect, self.resume, self.restart, self.abandon, self.close_button):
            row.addWidget(button)
        layout = QVBoxLayout(self)
        layout.addWidget(self.headline)
        layout.addWidget(self.body)
        layout.addLayout(row)
        self.beeper = QTimer(self, interval=beep_every_ms, timeout=QApplication.beep)
        self.shown_at: float | None = None
        self._shown = None  # (method, args) of the last message, to re-say it in another language
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.setWindowTitle(self.tr("Link lost"))
        self.reconnect.setText(self.tr("Reconnect"))
        self.resume.setText(self.tr("Resume job"))
        self.restart.setText(self.tr("Home and restart"))
        self.abandon.setText(self.tr("Abandon job"))
        self.close_button.setText(self.tr("Close"))
        if self._shown is not None:
            method, args = self._shown
            method(*args, again=True)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def _buttons(self, *visible: QPushButton) -> None:
        for button in (self.reconnect, self.resume, self.restart, self.abandon):
            button.setVisible(button in visible)

    def show_lost(self, what: str, job_running: bool, from_sd: bool = False, detail: str = "",
                  again: bool = False) -> None:
        """At once: what was lost (``"usb"`` or ``"uart"``) and what the machine did.
        ``detail`` may be a core message (``app.i18n``): it is shown in the window's language."""
        self._shown = (self.show_lost, (what, job_running, from_sd, detail))
        self.headline.setText(self.tr("⚠ Link to the machine lost"))
        text = [_t(LOST_TEXT[what]) if what in LOST_TEXT else what, machine_action(job_running, from_sd)]
        if detail:
            text.append(localize(detail))
        text.append(self.tr("Check the cable and the machine's power, then reconnect."))
        self.body.setText("\n\n".join(text))
        if again:
            return
        self._buttons(self.reconnect)
        QApplication.beep()
        if job_running and not self.beeper.isActive():
            self.beeper.start()
        self.show()
        self.raise_()

    def show_offer(self, same_boot: bool, from_line: int, total: int, again: bool = False) -> None:
        """After reconnecting: resume where it stopped, or (machine reset) home and restart."""
        self._shown = (self.show_offer, (same_boot, from_line, total))
        self.headline.setText(self.tr("✓ Link restored"))
        line, lines = integer(from_line + 1), integer(total)
        if same_boot:
            text = self.tr("The machine kept its position. Resume the job at line %1 of %2: "
                           "no line runs twice, none is skipped.")
        else:
            text = self.tr("The machine was reset and no longer knows its position. Home it, check the "
                           "stock, then restart at line %1 of %2 with the feed and spindle restored.")
        self.body.setText(text.replace("%1", line).replace("%2", lines))
        if again:
            return
        self.beeper.stop()
        self._buttons(self.resume, self.abandon) if same_boot else self._buttons(self.restart, self.abandon)
        self.show()
        self.raise_()

    def show_restored(self, again: bool = False) -> None:
        self._shown = (self.show_restored, ())
        self.beeper.stop()
        self.headline.setText(self.tr("✓ Link restored"))
        self.body.setText(self.tr("The machine answers again."))
        if not again:
            self._buttons()

    def say(self, text: str) -> None:
        """A one-off line in the body (already in the operator's language)."""
        self._shown = None
        self.body.setText(text)

    def hideEvent(self, event) -> None:  # noqa: N802 (Qt override)
        self.beeper.stop()
        super().hideEvent(event)
