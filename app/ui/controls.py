"""Machine controls: homing, job start / pause / resume / stop, spindle, work zero and
check mode. Emits requests; ``set_state`` enables what makes sense now."""

from __future__ import annotations

from PySide6.QtCore import Signal
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
        self.set_state(connected=False, busy=False, paused=False, has_program=False)

    def _button(self, key: str, text: str, slot, tip: str = "") -> QPushButton:
        button = QPushButton(text)
        button.setToolTip(tip)
        button.clicked.connect(slot)
        self.buttons[key] = button
        return button

    def _job_box(self) -> QGroupBox:
        box = QGroupBox("Job")
        grid = QGridLayout(box)
        grid.addWidget(self._button("home", "Home", lambda: self.home_requested.emit("NORMAL")), 0, 0)
        recover = self._button(
            "home_recover", "Home (recover)", lambda: self.home_requested.emit("RECOVER"),
            "after a fault: first move away from the switches, then home",
        )
        grid.addWidget(recover, 0, 1)
        grid.addWidget(self._button("start", "Start", self.start_requested.emit), 1, 0)
        pause = self._button("pause", "Pause", self.pause_requested.emit, "feed hold, at once")
        grid.addWidget(pause, 1, 1)
        grid.addWidget(self._button("resume", "Resume", self.resume_requested.emit), 2, 0)
        stop = self._button("stop", "STOP", self.stop_requested.emit, "stop and flush, at once")
        stop.setStyleSheet("QPushButton { font-weight: bold; color: #e03030; }"
                           " QPushButton:disabled { color: #808080; }")
        grid.addWidget(stop, 2, 1)
        self.check_mode = QCheckBox("Check mode (dry run, no motion)")
        self.check_mode.toggled.connect(self.check_mode_toggled.emit)
        grid.addWidget(self.check_mode, 3, 0, 1, 2)
        self.optional_stop = QCheckBox(self.tr("Optional stop (M01 holds the job)"))
        self.optional_stop.setChecked(True)
        grid.addWidget(self.optional_stop, 4, 0, 1, 2)
        self.override_travel = QCheckBox(self.tr("Override travel check (check mode only)"))
        self.override_travel.setToolTip(self.tr("run a program that leaves the travel as a dry run"))
        grid.addWidget(self.override_travel, 5, 0, 1, 2)
        return box

    def _spindle_box(self) -> QGroupBox:
        box = QGroupBox("Spindle")
        row = QHBoxLayout(box)
        self.rpm = QSpinBox()
        self.rpm.setRange(0, 30000)
        self.rpm.setSingleStep(100)
        self.rpm.setValue(3000)
        self.rpm.setSuffix(" rpm")
        self.rpm_label = QLabel("measured —")
        row.addWidget(self.rpm)
        row.addWidget(self._button("spindle_on", "On", lambda: self.spindle_requested.emit(self.rpm.value())))
        row.addWidget(self._button("spindle_off", "Off", lambda: self.spindle_requested.emit(0)))
        row.addWidget(self.rpm_label)
        return box

    def _zero_box(self) -> QGroupBox:
        box = QGroupBox("Work zero (here)")
        row = QHBoxLayout(box)
        for axes in ("X", "Y", "Z", "XY", "XYZ"):
            row.addWidget(self._button(f"zero_{axes}", axes, lambda _=False, a=axes: self._zero(a)))
        return box

    def _zero(self, axes: str) -> None:
        self.zero_requested.emit(axes)

    def set_state(self, connected: bool, busy: bool, paused: bool, has_program: bool) -> None:
        """Enable the buttons that make sense: ``busy`` = a job or upload is running."""
        idle = connected and not busy
        enable = {
            "home": idle, "home_recover": idle, "start": idle and has_program,
            "pause": connected and busy and not paused, "resume": connected and paused,
            "stop": connected, "spindle_on": idle, "spindle_off": connected,
        }
        for key, button in self.buttons.items():
            button.setEnabled(enable.get(key, idle))
        self.jog.setEnabled(idle)
        self.check_mode.setEnabled(idle)
        self.override_travel.setEnabled(idle and self.check_mode.isChecked())

    def set_rpm(self, rpm: int) -> None:
        self.rpm_label.setText(f"measured {rpm} rpm")
