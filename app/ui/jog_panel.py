"""Jog per axis with a step of 0.1, 1 or 10 mm and a feed; shortcuts are the window's
Machine menu actions (Ctrl+arrows for X/Y, Ctrl+PgUp/PgDn for Z)."""

from __future__ import annotations

from PySide6.QtCore import QEvent, Signal
from PySide6.QtWidgets import (
    QButtonGroup,
    QGridLayout,
    QGroupBox,
    QLabel,
    QPushButton,
    QRadioButton,
    QSpinBox,
)

from app.ui.numbers import general

STEPS = (0.1, 1.0, 10.0)
JOG_KEYS = {("X", -1): "Ctrl+Left", ("X", 1): "Ctrl+Right", ("Y", 1): "Ctrl+Up",
            ("Y", -1): "Ctrl+Down", ("Z", 1): "Ctrl+PgUp", ("Z", -1): "Ctrl+PgDown"}


class JogPanel(QGroupBox):
    jog_requested = Signal(str, float, float)  # axis, distance mm, feed mm/min

    def __init__(self, parent=None):
        super().__init__(parent)
        grid = QGridLayout(self)
        self.step_group = QButtonGroup(self)
        for column in range(len(STEPS)):
            radio = QRadioButton()
            radio.setToolTip(f"Alt+{column + 1}")
            self.step_group.addButton(radio, column)
            grid.addWidget(radio, 0, column)
        self.step_group.button(1).setChecked(True)
        self.feed = QSpinBox()
        self.feed.setRange(10, 2000)
        self.feed.setValue(300)
        grid.addWidget(self.feed, 0, 3)
        places = {("Y", 1): (1, 1), ("X", -1): (2, 0), ("X", 1): (2, 2), ("Y", -1): (3, 1),
                  ("Z", 1): (1, 3), ("Z", -1): (3, 3)}
        self.buttons = {}
        for (axis, sign), (row, column) in places.items():
            button = QPushButton(f"{axis}{'+' if sign > 0 else '−'}")
            button.setToolTip(JOG_KEYS[axis, sign])
            button.clicked.connect(lambda _=False, a=axis, s=sign: self.jog(a, s))
            self.buttons[axis, sign] = button
            grid.addWidget(button, row, column)
        grid.addWidget(QLabel("XY"), 2, 1)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.setTitle(self.tr("Jog"))
        self.setToolTip(self.tr("Jog one axis by the chosen step at the feed beside it"))
        for column, step in enumerate(STEPS):
            self.step_group.button(column).setText(self.tr("%1 mm").replace("%1", general(step)))
        self.feed.setSuffix(self.tr(" mm/min"))

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    @property
    def step(self) -> float:
        return STEPS[max(self.step_group.checkedId(), 0)]

    def set_step_index(self, index: int) -> None:
        self.step_group.button(index).setChecked(True)

    def jog(self, axis: str, sign: int) -> None:
        if self.isEnabled():
            self.jog_requested.emit(axis, sign * self.step, float(self.feed.value()))
