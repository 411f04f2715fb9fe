"""The machine's own panel, mirrored for the simulator: the 128 x 64 OLED scaled up,
the four buttons and the two resets, the LED and buzzer, and the cover switch.

It reads a ``panel`` object (``backend_sim``'s ``sim.panel``: ``oled_framebuffer()``,
``led``, ``buzzer``, ``press(button)``, ``set_cover(open)``) ten times a second; with
no panel (a real board) it says so and disables itself.
"""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QEvent, Qt, QTimer
from PySide6.QtGui import QImage, QPixmap
from PySide6.QtWidgets import QCheckBox, QGridLayout, QHBoxLayout, QLabel, QPushButton, QVBoxLayout, QWidget

SCALE = 3
OLED_ON = (120, 200, 255)
BUTTONS = ("UP", "DOWN", "OK", "EXIT")
RESETS = ("MRESET", "RESET")


def oled_image(frame: np.ndarray) -> QImage:
    """A 1-bit framebuffer (64, 128) as an RGB image, lit pixels in the OLED's blue."""
    rgb = np.zeros(frame.shape + (3,), dtype=np.uint8)
    rgb[frame.astype(bool)] = OLED_ON
    rgb = np.ascontiguousarray(rgb)
    height, width = frame.shape
    return QImage(rgb.data, width, height, 3 * width, QImage.Format.Format_RGB888).copy()


class MachinePanelView(QWidget):
    def __init__(self, parent=None):
        super().__init__(parent)
        self.panel = None
        self._last_frame: bytes | None = None
        self.oled = QLabel()
        self.oled.setAlignment(Qt.AlignmentFlag.AlignCenter)
        self.oled.setMinimumSize(128 * SCALE + 8, 64 * SCALE + 8)
        self.oled.setStyleSheet("background: black; color: #888; border: 2px solid #444;")
        self.led = QLabel()
        self.buzzer = QLabel()
        self.cover = QCheckBox()
        self.cover.toggled.connect(self._cover_toggled)
        self.buttons = {name: self._button(name) for name in BUTTONS + RESETS}
        layout = QVBoxLayout(self)
        layout.addWidget(self.oled)
        layout.addLayout(self._button_grid())
        indicators = QHBoxLayout()
        for widget in (self.led, self.buzzer, self.cover):
            indicators.addWidget(widget)
        layout.addLayout(indicators)
        layout.addStretch(1)
        self.timer = QTimer(self, interval=100, timeout=self.refresh)
        self._indicators = (False, False)
        self.set_panel(None)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.cover.setText(self.tr("Cover open"))
        self.cover.setToolTip(self.tr("the cover switch: while open the machine refuses every motion"))
        self.oled.setToolTip(self.tr("the machine's 128 x 64 OLED (its 5x7 font is ASCII only)"))
        for name in RESETS:
            self.buttons[name].setToolTip(self.tr("MRESET: resets the main board; RESET: the motion board"))
        if self.panel is None:
            self.oled.setText(self.tr("no machine panel (connect to the built-in simulator)"))
        self._set_indicators(*self._indicators)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def _button(self, name: str) -> QPushButton:
        button = QPushButton(name)
        button.clicked.connect(lambda _=False, n=name: self.press(n))
        return button

    def _button_grid(self) -> QGridLayout:
        grid = QGridLayout()
        places = {"UP": (0, 1), "EXIT": (1, 0), "OK": (1, 2), "DOWN": (2, 1),
                  "MRESET": (0, 3), "RESET": (2, 3)}
        for name, (row, column) in places.items():
            grid.addWidget(self.buttons[name], row, column)
        return grid

    def set_panel(self, panel) -> None:
        self.panel = panel
        self._last_frame = None
        for widget in [*self.buttons.values(), self.cover]:
            widget.setEnabled(panel is not None)
        if panel is None:
            self.timer.stop()
            self.oled.setPixmap(QPixmap())
            self.oled.setText(self.tr("no machine panel (connect to the built-in simulator)"))
            self._set_indicators(False, False)
        else:
            self.timer.start()
            self.refresh()

    def press(self, name: str) -> None:
        if self.panel is not None:
            self.panel.press(name)
            self.refresh()

    def _cover_toggled(self, open_: bool) -> None:
        if self.panel is not None:
            self.panel.set_cover(open_)

    def refresh(self) -> None:
        if self.panel is None:
            return
        frame = np.asarray(self.panel.oled_framebuffer())
        raw = frame.tobytes()
        if raw != self._last_frame:
            self._last_frame = raw
            image = oled_image(frame).scaled(frame.shape[1] * SCALE, frame.shape[0] * SCALE)
            pixmap = QPixmap.fromImage(image)
            self.oled.setPixmap(pixmap)
        self._set_indicators(bool(self.panel.led), bool(self.panel.buzzer))

    def _set_indicators(self, led: bool, buzzer: bool) -> None:
        self._indicators = (led, buzzer)
        led_colour = "#ff3030" if led else "#402020"
        self.led.setText(f"<span style='color:{led_colour}; font-size:16pt'>●</span> " + self.tr("LED"))
        colour = "#ffb000" if buzzer else "#404040"
        said = self.tr("buzzer") if buzzer else self.tr("buzzer off")
        self.buzzer.setText(f"<span style='color:{colour}; font-size:16pt'>♪</span> {said}")
