"""Machine controls: homing, job start / pause / resume / stop, spindle, work zero and
check mode. Emits requests; the window's state table (``app/ui/enabler.py``) enables them."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QEvent, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from app.ui.jog_panel import JogPanel
from app.ui.numbers import integer

# key: (label, tooltip), translated in the "MachineControls" context.
BUTTON_TEXTS = {
    "home": (QT_TRANSLATE_NOOP("MachineControls", "Home"), ""),
    "home_recover": (
        QT_TRANSLATE_NOOP("MachineControls", "Home (recover)"),
        QT_TRANSLATE_NOOP("MachineControls", "after a fault: first move away from the switches, then home"),
    ),
    "start": (QT_TRANSLATE_NOOP("MachineControls", "Start"), ""),
    "pause": (QT_TRANSLATE_NOOP("MachineControls", "Pause"),
              QT_TRANSLATE_NOOP("MachineControls", "feed hold, at once")),
    "resume": (QT_TRANSLATE_NOOP("MachineControls", "Resume"), ""),
    "stop": (QT_TRANSLATE_NOOP("MachineControls", "STOP"),
             QT_TRANSLATE_NOOP("MachineControls", "stop and flush, at once")),
    "spindle_on": (QT_TRANSLATE_NOOP("MachineControls", "On"), ""),
    "spindle_off": (QT_TRANSLATE_NOOP("MachineControls", "Off"), ""),
}


class MachineControls(QWidget):
    home_requested = Signal(str)  # "NORMAL" or "RECOVER"
    start_requested = Signal()
    pause_requested = Signal()
    resume_requested = Signal()
    stop_requested = Signal()
    spindle_requested = Signal(int)  # rpm, 0 = off
    zero_requested = Signal(str)  # axes, e.g. "XY" or "XYZ"
    check_mode_toggled = Signal(bool)

    def __init__(self, parent=None):
        super().__init__(parent)
        self.buttons: dict[str, QPushButton] = {}
        layout = QVBoxLayout(self)
        layout.addWidget(self._job_box())
        self.jog = JogPanel()
        layout.addWidget(self.jog)
        layout.addWidget(self._spindle_box())
        layout.addWidget(self._zero_box())
        layout.addStretch(1)
        self._rpm_measured: int | None = None
        self._rpm_commanded: float | None = None
        widgets = [*self.buttons.values(), *self.jog.buttons.values(), self.check_mode, self.override_travel]
        for widget in widgets:
            widget.setEnabled(False)  # until the window's state table says otherwise
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        for key, (text, tip) in BUTTON_TEXTS.items():
            self.buttons[key].setText(QCoreApplication.translate("MachineControls", text))
            self.buttons[key].setToolTip(QCoreApplication.translate("MachineControls", tip) if tip else "")
        self.job_box.setTitle(self.tr("Job"))
        self.check_mode.setText(self.tr("Check mode (dry run, no motion)"))
        self.optional_stop.setText(self.tr("Optional stop (M01 holds the job)"))
        self.override_travel.setText(self.tr("Override travel check (check mode only)"))
        self.override_travel.setToolTip(self.tr("run a program that leaves the travel as a dry run"))

        self.spindle_box.setTitle(self.tr("Spindle"))
        self.rpm.setSuffix(self.tr(" rpm"))
        self.zero_box.setTitle(self.tr("Work zero (here)"))
        self.rpm_label.clear()
        self.set_rpm(self._rpm_measured, self._rpm_commanded)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def _button(self, key: str, text: str, slot, tip: str = "") -> QPushButton:
        """A button; its label and tip come from BUTTON_TEXTS when ``key`` is there, else
        pass them already translated (``self.tr``)."""
        button = QPushButton(text)
        button.setToolTip(tip)
        button.clicked.connect(slot)
        self.buttons[key] = button
        return button

    def _job_box(self) -> QGroupBox:
        box = self.job_box = QGroupBox()
        grid = QGridLayout(box)
        grid.addWidget(self._button("home", "", lambda: self.home_requested.emit("NORMAL")), 0, 0)
        recover = self._button("home_recover", "", lambda: self.home_requested.emit("RECOVER"))
        grid.addWidget(recover, 0, 1)
        grid.addWidget(self._button("start", "", self.start_requested.emit), 1, 0)
        pause = self._button("pause", "", self.pause_requested.emit)
        grid.addWidget(pause, 1, 1)
        grid.addWidget(self._button("resume", "", self.resume_requested.emit), 2, 0)
        stop = self._button("stop", "", self.stop_requested.emit)
        stop.setStyleSheet("QPushButton { font-weight: bold; color: #e03030; }"
                           " QPushButton:disabled { color: #808080; }")
        grid.addWidget(stop, 2, 1)
        self.check_mode = QCheckBox()
        self.check_mode.toggled.connect(self.check_mode_toggled.emit)
        grid.addWidget(self.check_mode, 3, 0, 1, 2)
        self.optional_stop = QCheckBox()
        self.optional_stop.setChecked(True)
        grid.addWidget(self.optional_stop, 4, 0, 1, 2)
        self.override_travel = QCheckBox()
        grid.addWidget(self.override_travel, 5, 0, 1, 2)
        return box

    def _spindle_box(self) -> QGroupBox:
        box = self.spindle_box = QGroupBox()
        row = QHBoxLayout(box)
        self.rpm = QSpinBox()
        self.rpm.setRange(0, 30000)
        self.rpm.setSingleStep(100)
        self.rpm.setValue(3000)
        self.rpm_label = QLabel()
        row.addWidget(self.rpm)
        row.addWidget(self._button("spindle_on", "", lambda: self.spindle_requested.emit(self.rpm.value())))
        row.addWidget(self._button("spindle_off", "", lambda: self.spindle_requested.emit(0)))
        row.addWidget(self.rpm_label)
        return box

    def _zero_box(self) -> QGroupBox:
        box = self.zero_box = QGroupBox()
        row = QHBoxLayout(box)
        for axes in ("X", "Y", "Z", "XY", "XYZ"):
            row.addWidget(self._button(f"zero_{axes}", axes, lambda _=False, a=axes: self._zero(a)))
        return box

    def _zero(self, axes: str) -> None:
        self.zero_requested.emit(axes)

    def set_rpm(self, rpm: int | None, commanded: float | None = None) -> None:
        """The measured speed beside the commanded one (None: not known)."""
        if (rpm, commanded) == (self._rpm_measured, self._rpm_commanded) and self.rpm_label.text():
            return
        self._rpm_measured, self._rpm_commanded = rpm, commanded
        asked = "—" if commanded is None else integer(round(commanded))
        got = "—" if rpm is None else integer(rpm)
        text = self.tr("commanded %1 · measured %2 rpm")
        self.rpm_label.setText(text.replace("%1", asked).replace("%2", got))
