"""Console dock: frame traffic (TX/RX) with a filter, pause scrolling and the resend
counters, and an MDI line to send one G-code line or a command.

Frames arrive by the hundred per second; ``add_frame`` only queues them and a 10 Hz
timer appends what passes the filter in one go (the view keeps the last lines only).
"""

from __future__ import annotations

from collections import deque

from PySide6.QtCore import QEvent, QTimer, Signal
from PySide6.QtGui import QFontDatabase
from PySide6.QtWidgets import (
    QCheckBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.comm.grbl.protocol import STREAM_KINDS
from app.i18n import localize
from app.ui.numbers import decimal, fill, integer

MAX_LINES = 4000
NOISY_KINDS = frozenset({*"SAFD", *STREAM_KINDS})  # status and stream frames (the mill's, GRBL's)
HEARTBEAT_VERBS = frozenset({"PING", "STATUS"})  # the heartbeat and its answers: hidden with them


def is_noise(kind: str, text: str) -> bool:
    """A status or stream frame (the mill's S/A/F/D, GRBL's job lines, their ``ok`` and the
    polled reports), or the heartbeat's command (``C <id> PING``) and its answer: what the
    "stream/status frames" box shows, hidden by default. An operator's own ``?`` is
    answered by a GRBL "report", shown."""
    if kind in NOISY_KINDS:
        return True
    words = text.split()
    return kind in ("C", "O") and len(words) >= 3 and words[2] in HEARTBEAT_VERBS


class ConsoleView(QWidget):
    mdi_submitted = Signal(str)

    def __init__(self, parent=None):
        super().__init__(parent)
        self._pending: deque[str] = deque(maxlen=MAX_LINES)
        self.log = QPlainTextEdit(readOnly=True)
        self.log.setMaximumBlockCount(MAX_LINES)
        self.log.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
        self.filter = QLineEdit()
        self.show_tx = QCheckBox("TX", checked=True)
        self.show_rx = QCheckBox("RX", checked=True)
        self.show_stream = QCheckBox(checked=False)
        self.pause = QCheckBox()
        self.counters = QLabel()
        self.mdi = QLineEdit()
        self.mdi.returnPressed.connect(self._submit)
        send = self.send = QPushButton()
        send.clicked.connect(self._submit)
        clear = self.clear = QPushButton()
        clear.clicked.connect(self.log.clear)
        top = QHBoxLayout()
        for widget in (self.filter, self.show_tx, self.show_rx, self.show_stream):
            top.addWidget(widget)
        for widget in (self.pause, self.counters, clear):
            top.addWidget(widget)
        bottom = QHBoxLayout()
        bottom.addWidget(self.mdi, 1)
        bottom.addWidget(send)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addLayout(top)
        layout.addWidget(self.log, 1)
        layout.addLayout(bottom)
        self.mdi_history: list[str] = []
        self.timer = QTimer(self, interval=100, timeout=self.flush)
        self.timer.start()
        self._resends_shown = None
        self._resends = (0, 0.0, False)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.filter.setPlaceholderText(self.tr("filter (text)"))
        self.show_tx.setToolTip(self.tr("frames sent to the machine"))
        self.show_rx.setToolTip(self.tr("frames received from the machine"))
        self.show_stream.setText(self.tr("stream/status frames"))
        self.pause.setText(self.tr("pause scrolling"))
        hint = self.tr("MDI: a G-code line (G0 X10) or a command (HOME, SD LIST, GET KP_X)")
        self.mdi.setPlaceholderText(hint)
        self.send.setText(self.tr("Send"))
        self.clear.setText(self.tr("Clear"))
        self._resends_shown = None
        self.set_resends(*self._resends)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def add_frame(self, direction: str, kind: str, text: str, ok: bool = True) -> None:
        if not self._passes(direction, kind, text):
            return
        mark = "→" if direction == "tx" else "←"
        self._pending.append(f"{mark} {text}" + ("" if ok else "   [dropped]"))

    def add_log(self, level: str, text: str, source: str = "host") -> None:
        needle = self.filter.text().strip().lower()
        if needle and needle not in text.lower() and needle not in localize(text).lower():
            return
        self._pending.append(f"# {source} {level}: {localize(text)}")

    def _passes(self, direction: str, kind: str, text: str) -> bool:
        if (direction == "tx" and not self.show_tx.isChecked()) or (
            direction == "rx" and not self.show_rx.isChecked()
        ):
            return False
        if is_noise(kind, text) and not self.show_stream.isChecked():
            return False
        needle = self.filter.text().strip().lower()
        return not needle or needle in text.lower()

    def flush(self) -> None:
        if not self._pending or self.pause.isChecked():
            return
        text = "\n".join(self._pending)
        self._pending.clear()
        self.log.appendPlainText(text)
        bar = self.log.verticalScrollBar()
        bar.setValue(bar.maximum())

    def set_resends(self, resends: int, rate: float, warning: bool = False) -> None:
        key = (resends, round(rate, 3), warning)
        if key == self._resends_shown:
            return
        self._resends_shown, self._resends = key, (resends, rate, warning)
        colour = "#e05050" if warning else "palette(window-text)"
        text = fill(self.tr("resends %1 (%2 %)"), integer(resends), decimal(rate * 100, 1))
        self.counters.setText(f"<span style='color:{colour}'>{text}</span>")

    def _submit(self) -> None:
        text = self.mdi.text().strip()
        if text:
            self.mdi_history.append(text)
            self.mdi_submitted.emit(text)
            self.mdi.clear()
