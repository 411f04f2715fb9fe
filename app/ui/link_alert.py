"""The disconnect alert: a non-modal dialog (plus a beep) the moment the link is lost,
saying what was lost and what the machine did, then — once reconnected — the offer to
resume exactly where the job stopped."""

from __future__ import annotations

from PySide6.QtCore import Qt, QTimer, Signal
from PySide6.QtWidgets import QApplication, QDialog, QHBoxLayout, QLabel, QPushButton, QVBoxLayout

LOST_TEXT = {
    "usb": "The USB link between this computer and the machine is lost: no valid frame for 3 s.",
    "uart": "The machine's internal link (UART between the main board and the motion board) is lost.",
}


def machine_action(job_running: bool, from_sd: bool) -> str:
    if from_sd:
        return "The machine carries on with the job from its SD card."
    if job_running:
        return ("The machine holds the job on the path (feed hold), spindle as it was: "
                "it has not lost its place.")
    return "No job was running; the machine stays where it is."


class LinkAlert(QDialog):
    reconnect_requested = Signal()
    resume_requested = Signal()
    restart_requested = Signal()
    abandon_requested = Signal()

    def __init__(self, parent=None, beep_every_ms: int = 2000):
        super().__init__(parent)
        self.setWindowTitle("Link lost")
        self.setWindowModality(Qt.WindowModality.NonModal)
        self.setMinimumWidth(460)
        self.headline = QLabel()
        self.headline.setStyleSheet("font-size: 14pt; font-weight: bold; color: #e03030;")
        self.body = QLabel()
        self.body.setWordWrap(True)
        self.reconnect = QPushButton("Reconnect")
        self.resume = QPushButton("Resume job")
        self.restart = QPushButton("Home and restart")
        self.abandon = QPushButton("Abandon job")
        self.close_button = QPushButton("Close")
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

    def _buttons(self, *visible: QPushButton) -> None:
        for button in (self.reconnect, self.resume, self.restart, self.abandon):
            button.setVisible(button in visible)

    def show_lost(self, what: str, job_running: bool, from_sd: bool = False, detail: str = "") -> None:
        """At once: what was lost (``"usb"`` or ``"uart"``) and what the machine did."""
        self.headline.setText("⚠ Link to the machine lost")
        text = [LOST_TEXT.get(what, what), machine_action(job_running, from_sd)]
        if detail:
            text.append(detail)
        text.append("Check the cable and the machine's power, then reconnect.")
        self.body.setText("\n\n".join(text))
        self._buttons(self.reconnect)
        QApplication.beep()
        if job_running and not self.beeper.isActive():
            self.beeper.start()
        self.show()
        self.raise_()

    def show_offer(self, same_boot: bool, from_line: int, total: int) -> None:
        """After reconnecting: resume where it stopped, or (machine reset) home and restart."""
        self.beeper.stop()
        self.headline.setText("✓ Link restored")
        if same_boot:
            self.body.setText(
                f"The machine kept its position. Resume the job at line {from_line + 1} of {total}: "
                "no line runs twice, none is skipped."
            )
            self._buttons(self.resume, self.abandon)
        else:
            self.body.setText(
                "The machine was reset and no longer knows its position. Home it, check the stock, "
                f"then restart at line {from_line + 1} of {total} with the feed and spindle restored."
            )
            self._buttons(self.restart, self.abandon)
        self.show()
        self.raise_()

    def show_restored(self) -> None:
        self.beeper.stop()
        self.headline.setText("✓ Link restored")
        self.body.setText("The machine answers again.")
        self._buttons()

    def hideEvent(self, event) -> None:  # noqa: N802 (Qt override)
        self.beeper.stop()
        super().hideEvent(event)
