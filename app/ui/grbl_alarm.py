"""A GRBL machine's alarm lock in the window (issue 23): a banner under the connection bar
while the machine reports ``Alarm``, saying first why it is locked and what unlocking
risks (``codes.unlock_advice``: the ``ALARM:N`` in words, or the lock GRBL starts in
until homed), then offering what gets out of it, as Candle, UGS and gSender do: *Reset*
after a hard or soft limit (GRBL answers nothing else then), *Home* ($H) and *Unlock*
($X). The state table decides whether each may be sent (``home``, ``unlock``, ``stop``).
A machine without homing (``$22=0``, ``homing`` False) gets no *Home*, and advice that
says to check the position and work zero instead.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QLabel, QPushButton, QToolBar

from app.comm.grbl.codes import RESET_FIRST, unlock_advice
from app.i18n import localize


def alarm_number(code: str) -> int | None:
    """``ALARM:9`` -> 9; None for another alarm code."""
    head, _, number = code.partition(":")
    return int(number) if head == "ALARM" and number.isdigit() else None


class GrblAlarmBar(QObject):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.code: int | None = None  # the last ALARM:N since the machine's last reset
        self.reset_sent = False
        self.homing = True  # the machine has a homing cycle ($22; set by GrblWindow)
        self.label = QLabel()
        self.label.setWordWrap(True)
        self.label.installEventFilter(self)  # LanguageChange reaches widgets, not this QObject
        self.label.setStyleSheet("QLabel { background: #8a4b00; color: white; padding: 6px; }")
        self.buttons = {key: QPushButton() for key in ("reset", "home", "unlock")}
        self.buttons["reset"].clicked.connect(self.reset)
        self.buttons["home"].clicked.connect(lambda: window.operator.home("NORMAL"))
        self.buttons["unlock"].clicked.connect(self.unlock)
        self.bar = QToolBar(window)
        self.bar.setObjectName("grbl_alarm_toolbar")
        self.bar.setMovable(False)
        self.bar.addWidget(self.label)
        self.placed = {key: self.bar.addWidget(button) for key, button in self.buttons.items()}
        window.addToolBar(self.bar)
        self.bar.setVisible(False)
        worker = window.link.worker
        worker.alarm_raised.connect(self.on_alarm)
        worker.status_changed.connect(self.on_status)
        worker.machine_info_changed.connect(self.on_machine_started)
        worker.disconnected.connect(lambda _reason: self._hide())
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.buttons["reset"].setText(self.tr("Reset"))
        self.buttons["home"].setText(self.tr("Home ($H)"))
        self.buttons["unlock"].setText(self.tr("Unlock ($X)"))
        self.buttons["unlock"].setToolTip(self.tr("Lets the machine move without homing: "
                                                  "it may not know where it is"))
        self.bar.setWindowTitle(self.tr("Alarm"))
        self._show_text()

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 (Qt override)
        if watched is self.label and event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        return super().eventFilter(watched, event)

    @property
    def shown(self) -> bool:
        return not self.bar.isHidden()

    def advice(self) -> str:
        return localize(unlock_advice(self.code, self.homing))

    def _show_text(self) -> None:
        self.label.setText(self.tr("MACHINE LOCKED (alarm): %1").replace("%1", self.advice()))
        needs_reset = self.code in RESET_FIRST and not self.reset_sent
        for key, action in self.placed.items():  # a toolbar shows its widgets through their actions
            action.setVisible(needs_reset == (key == "reset") and (key != "home" or self.homing))

    def set_homing(self, homing: bool) -> None:
        """Whether the machine has a homing cycle (its ``$22``)."""
        if homing != self.homing:
            self.homing = homing
            self._show_text()

    def on_alarm(self, event) -> None:
        """An ``ALARM:N``: shown at once (after a hard or soft limit GRBL sends no report
        until it is reset)."""
        number = alarm_number(event.code)
        if number is not None:
            self.code, self.reset_sent = number, False
            self._show(True)

    def on_machine_started(self, _info) -> None:
        """A welcome (reset or power-up): the alarm before it has been dealt with."""
        self.code, self.reset_sent = None, False
        self._show_text()

    def on_status(self, event) -> None:
        self._show(event.state == "ALARM" or self.code in RESET_FIRST)

    def _show(self, locked: bool) -> None:
        locked = locked and getattr(self.w.link.capabilities, "unlock", False)
        self._show_text()
        if locked and not self.shown:
            self.bar.setVisible(True)
            self.w.status.showMessage(self.tr("Machine locked: %1").replace("%1", self.advice()))
        elif not locked and self.shown:
            self._hide()

    def _hide(self) -> None:
        self.bar.setVisible(False)
        self.code, self.reset_sent = None, False

    def reset(self) -> None:
        if self.w.operator.allowed("stop"):
            self.reset_sent = True
            self.w.link.call("machine_call", "reset", ())
            self._show_text()

    def unlock(self) -> None:
        if self.w.operator.allowed("unlock"):
            self.w.console.add_log("warning", self.advice())
            self.w.link.call("machine_call", "unlock", ())
