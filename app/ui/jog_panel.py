"""Jog per axis with a step of 0.1, 1 or 10 mm and a feed; shortcuts are the window's
Machine menu actions (Ctrl+arrows for X/Y, Ctrl+PgUp/PgDn for Z).

A fourth mode, "Hold", jogs while a button is held (``hold_changed`` carries the keys
held now, ``()`` once all are released); the plain arrow and PageUp/PageDown keys do
the same in every mode (``hold_jog_keys.HoldJogKeys`` calls ``set_held``). A button
disabled while held (the state table, the cover) counts as released."""

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
HOLD_MODE = len(STEPS)  # the step group's id of the "Hold" mode
JOG_KEYS = {("X", -1): "Ctrl+Left", ("X", 1): "Ctrl+Right", ("Y", 1): "Ctrl+Up",
            ("Y", -1): "Ctrl+Down", ("Z", 1): "Ctrl+PgUp", ("Z", -1): "Ctrl+PgDown"}


def key_of(axis: str, sign: int) -> str:
    """The hold-to-jog key of a button: ``"X+"``, ``"Y-"``."""
    return f"{axis}{'+' if sign > 0 else '-'}"


class JogPanel(QGroupBox):
    jog_requested = Signal(str, float, float)  # axis, distance mm, feed mm/min
    hold_changed = Signal(object, float)  # the keys held now ("X+", ...), feed mm/min

    def __init__(self, parent=None):
        super().__init__(parent)
        grid = QGridLayout(self)
        self.step_group = QButtonGroup(self)
        for column in range(len(STEPS) + 1):
            radio = QRadioButton()
            radio.setToolTip(f"Alt+{column + 1}")
            self.step_group.addButton(radio, column)
            grid.addWidget(radio, 0, column)
        self.step_group.button(1).setChecked(True)
        self.feed = QSpinBox()
        self.feed.setRange(10, 2000)
        self.feed.setValue(300)
        grid.addWidget(self.feed, 0, 4)
        self.held: set[str] = set()
        self._by_button: set[str] = set()  # the held keys that are buttons held down
        places = {("Y", 1): (1, 1), ("X", -1): (2, 0), ("X", 1): (2, 2), ("Y", -1): (3, 1),
                  ("Z", 1): (1, 3), ("Z", -1): (3, 3)}
        self.buttons = {}
        for (axis, sign), (row, column) in places.items():
            button = QPushButton(f"{axis}{'+' if sign > 0 else '−'}")
            button.setToolTip(JOG_KEYS[axis, sign])
            button.clicked.connect(lambda _=False, a=axis, s=sign: self._clicked(a, s))
            button.pressed.connect(lambda a=axis, s=sign: self._button_held(a, s, True))
            button.released.connect(lambda a=axis, s=sign: self._button_held(a, s, False))
            button.installEventFilter(self)
            self.buttons[axis, sign] = button
            grid.addWidget(button, row, column)
        grid.addWidget(QLabel("XY"), 2, 1)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.setTitle(self.tr("Jog"))
        self.setToolTip(self.tr("Jog one axis by the chosen step at the feed beside it"))
        for column, step in enumerate(STEPS):
            self.step_group.button(column).setText(self.tr("%1 mm").replace("%1", general(step)))
        self.step_group.button(HOLD_MODE).setText(self.tr("Hold"))
        self.step_group.button(HOLD_MODE).setToolTip(
            self.tr("Jog while a button is held (Alt+4); the arrow keys and PageUp/PageDown always do"))
        self.feed.setSuffix(self.tr(" mm/min"))

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.EnabledChange and not watched.isEnabled():
            for (axis, sign), button in self.buttons.items():
                if button is watched and key_of(axis, sign) in self._by_button:
                    self._button_held(axis, sign, False)
        return super().eventFilter(watched, event)

    @property
    def hold_mode(self) -> bool:
        return self.step_group.checkedId() == HOLD_MODE

    @property
    def step(self) -> float:
        return STEPS[self.step_group.checkedId()] if 0 <= self.step_group.checkedId() < len(STEPS) else 1.0

    def set_held(self, key: str, held: bool) -> None:
        """Key ``"X+"``... pressed (``held``) or released: emit the keys held now if that
        changed them."""
        before = set(self.held)
        (self.held.add if held else self.held.discard)(key)
        if self.held != before:
            self.hold_changed.emit(tuple(sorted(self.held)), float(self.feed.value()))

    def release_all(self) -> None:
        for key in list(self.held):
            self.set_held(key, False)

    def _button_held(self, axis: str, sign: int, held: bool) -> None:
        key = key_of(axis, sign)
        if held and self.hold_mode:
            self._by_button.add(key)
        elif not held and key in self._by_button:
            self._by_button.discard(key)
        else:
            return
        self.set_held(key, held)

    def set_step_index(self, index: int) -> None:
        self.step_group.button(index).setChecked(True)

    def _clicked(self, axis: str, sign: int) -> None:
        if not self.hold_mode:  # in the Hold mode, press and release did the work
            self.jog(axis, sign)

    def jog(self, axis: str, sign: int) -> None:
        """One step (the step chosen; 1 mm while the Hold mode is on)."""
        if self.isEnabled():
            self.jog_requested.emit(axis, sign * self.step, float(self.feed.value()))
