"""The cover interlock in the window: a red banner under the connection bar while the
machine reports its cover open (flag ``C``), and the same words in the status bar."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtWidgets import QLabel, QToolBar

COVER_FLAG = "C"


class CoverBanner(QObject):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.label = QLabel()
        self.label.installEventFilter(self)  # LanguageChange reaches widgets, not this QObject
        self.label.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.label.setStyleSheet("QLabel { background: #b00020; color: white; font-weight: bold;"
                                 " padding: 6px; }")
        window.addToolBarBreak()
        self.bar = QToolBar(window)
        self.bar.setObjectName("cover_toolbar")
        self.bar.setMovable(False)
        self.bar.addWidget(self.label)
        window.addToolBar(self.bar)
        self.bar.setVisible(False)
        self.open = False
        self.retranslate_ui()
        window.link.worker.status_changed.connect(self.on_status)

    def retranslate_ui(self) -> None:
        self.label.setText(self.tr("COVER OPEN - close to continue: no motion, spindle stopped. "
                                   "Resume restarts the spindle, then the job."))
        self.bar.setWindowTitle(self.tr("Cover"))

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 (Qt override)
        if watched is self.label and event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        return super().eventFilter(watched, event)

    def on_status(self, event) -> None:
        is_open = COVER_FLAG in event.flags
        if is_open == self.open:
            return
        self.open = is_open
        self.bar.setVisible(is_open)
        if is_open:
            self.w.status.showMessage(self.tr("COVER OPEN - close to continue"))
        elif event.state == "HOLD":  # a job held by the cover: Resume brings it back
            self.w.status.showMessage(self.tr("Cover closed: press Resume to go on"), 10000)
        else:
            self.w.status.showMessage(self.tr("Cover closed"), 10000)
