"""The disconnect alert: a non-modal dialog (plus a beep) the moment the link is lost,
saying what was lost and what the machine did, then — once reconnected — the offer to
resume exactly where the job stopped."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QEvent, Qt, QTimer, Signal
from PySide6.QtWidgets import QApplication, QDialog, QHBoxLayout, QLabel, QPushButton, QVBoxLayout

from app.i18n import localize
from app.ui.numbers import integer

# What was lost, by its cause: the port failed (unplugged, the machine's process ended),
# the machine went silent, the machine's own internal link.
LOST_TEXT = {
    "port": QT_TRANSLATE_NOOP("LinkAlert", "The serial port to the machine failed (cable unplugged, or the "
                                           "machine switched off); the details are in the console."),
    "silence": QT_TRANSLATE_NOOP("LinkAlert", "The machine has not answered for 3 s: no valid frame came "
                                              "over the link."),
    "uart": QT_TRANSLATE_NOOP("LinkAlert", "The machine's internal link (UART between the main board and the "
                                           "motion board) is lost."),
    "report_silence": QT_TRANSLATE_NOOP("LinkAlert", "The machine has sent no status report for 3 s (a "
                                                     "GRBL machine has no heartbeat: its reports are the "
                                                     "sign of life)."),
}
HEADLINE_LOST = "font-size: 14pt; font-weight: bold; color: #e03030;"
HEADLINE_OK = "font-size: 14pt; font-weight: bold; color: #39a353;"


def _t(text: str) -> str:
    return QCoreApplication.translate("LinkAlert", text)


def machine_action(job_running: bool, from_sd: bool, what: str = "silence", last_state: str = "",
                   host_watch: bool = True) -> str:
    """What the machine does now, as far as this computer can know: the machine's rule
    (docs/protocol.md: a streamed job holds once the host is missed for 3 s, an SD job
    carries on; ``host_watch`` False: a machine that does not watch for its host, as GRBL,
    runs what its buffer holds) and the last state it reported; only the machine's own
    report of a lost internal link says what it did."""
    said = QCoreApplication.translate("LinkAlert", "Last state seen: %1.").replace("%1", last_state or "—")
    translate = QCoreApplication.translate
    if from_sd:
        rule = translate("LinkAlert", "A job from the SD card carries on without this computer.")
    elif job_running and what == "uart":
        rule = translate("LinkAlert", "The main board holds the job: the motion board did not answer it.")
    elif job_running and not host_watch:
        rule = translate("LinkAlert", "A GRBL machine does not notice that this computer is gone: it runs "
                                      "the lines already in its buffer, then waits.")
    elif job_running:
        rule = translate("LinkAlert", "If the machine is still powered, it holds the job on the path once "
                                      "it has missed this computer for 3 s; it keeps its place unless it "
                                      "was reset.")
    else:
        rule = translate("LinkAlert", "No job was running.")
    return f"{rule} {said}"


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
        self.headline.setStyleSheet(HEADLINE_LOST)
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
                  last_state: str = "", host_watch: bool = True, again: bool = False) -> None:
        """At once: what was lost (a key of ``LOST_TEXT``), what the machine does by its
        rules (``host_watch``: see ``machine_action``) and the state it last reported.
        ``detail`` may be a core message (``app.i18n``): it is shown in the window's language."""
        self._shown = (self.show_lost, (what, job_running, from_sd, detail, last_state, host_watch))
        self.headline.setText(self.tr("⚠ Link to the machine lost"))
        self.headline.setStyleSheet(HEADLINE_LOST)
        text = [_t(LOST_TEXT[what]) if what in LOST_TEXT else what,
                machine_action(job_running, from_sd, what, last_state, host_watch)]
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
        """After reconnecting: resume where it stopped, or (machine reset) home and restart;
        ``from_line`` and ``total`` are source lines of the file the operator opened."""
        self._shown = (self.show_offer, (same_boot, from_line, total))
        self.headline.setText(self.tr("✓ Link restored"))
        self.headline.setStyleSheet(HEADLINE_OK)
        line, lines = integer(from_line), integer(total)
        if same_boot:
            text = self.tr("The machine kept its position. Resume the job at line %1 of %2: "
                           "no line runs twice, none is skipped.")
        else:
            text = self.tr("The machine was reset and no longer knows its position. Home it, check the "
                           "stock, then restart at line %1 of %2 with the feed and spindle restored.")
        self.body.setText(text.replace("%1", line).replace("%2", lines))
        self.restart.setText(self.tr("Home and restart"))
        if again:
            return
        self.beeper.stop()
        self._buttons(self.resume, self.abandon) if same_boot else self._buttons(self.restart, self.abandon)
        self.show()
        self.raise_()

    def show_restart_offer(self, from_line: int, total: int, needs_home: bool, again: bool = False) -> None:
        """After reconnecting to a machine that cannot resume exactly (GRBL): Start here at
        ``from_line`` of ``total`` (source lines), the line after the last one known
        finished, with the modal state restored; ``needs_home``: it was reset."""
        self._shown = (self.show_restart_offer, (from_line, total, needs_home))
        self.headline.setText(self.tr("✓ Link restored"))
        self.headline.setStyleSheet(HEADLINE_OK)
        line, lines = integer(from_line), integer(total)
        text = self.tr("GRBL cannot resume a job exactly. Start again at line %1 of %2, the line after "
                       "the last one known finished (its “ok” came back and its motion was done), with the "
                       "units, work system, coolant, spindle and feed restored; lines after it may already "
                       "have run.")
        parts = [text.replace("%1", line).replace("%2", lines)]
        if needs_home:
            parts.append(self.tr("The machine was reset and no longer knows its position: it is homed "
                                 "first."))
        self.body.setText("\n\n".join(parts))
        self.restart.setText(self.tr("Home and restart") if needs_home
                             else self.tr("Start here at line %1").replace("%1", line))
        if again:
            return
        self.beeper.stop()
        self._buttons(self.restart, self.abandon)
        self.show()
        self.raise_()

    def show_restored(self, again: bool = False) -> None:
        self._shown = (self.show_restored, ())
        self.beeper.stop()
        self.headline.setText(self.tr("✓ Link restored"))
        self.headline.setStyleSheet(HEADLINE_OK)
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
