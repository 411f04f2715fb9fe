"""Feed, spindle and rapid overrides while a job runs (docs/protocol.md, "Overrides").

``OverridesPanel`` has a slider and step buttons for the feed (steps of 1 and 10, reset
to 100) and the spindle (steps of 10, reset), and three buttons for the rapid rate (25 /
50 / 100 %). The ranges are the connected driver's (``set_ranges(capabilities)``,
``driver.Capabilities.override_range``): the mill's feed 10-200 % and spindle 50-150 %,
GRBL's 10-200 % both; a rapid rate the driver lacks is hidden. Each change emits
``override_requested(verb, percent)`` with the absolute value (``FEED``, ``SPINDLE``,
``RAPID``); the window sends it only if the state table allows.
``show_machine(overrides)`` shows what the machine reports in its status and moves the
controls to it (the OLED menu can set them too), except for a value just asked for that
the machine has not reported yet.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtWidgets import QButtonGroup, QGridLayout, QGroupBox, QLabel, QPushButton, QSlider

from app.comm.driver import FRAME_CAPABILITIES
from app.comm.frame import NO_OVERRIDES, OVERRIDE_RANGES

VERBS = ("FEED", "SPINDLE", "RAPID")
SLIDERS = ("FEED", "SPINDLE")
STEPS = {"FEED": (-10, -1, 1, 10), "SPINDLE": (-10, 10)}
RAPIDS = tuple(OVERRIDE_RANGES["RAPID"])  # the rapid buttons; a driver offers some of them
STALE_AFTER = 20  # statuses (about a second) after which an unreported request is forgotten


class OverridesPanel(QGroupBox):
    override_requested = Signal(str, int)  # verb, absolute percent

    def __init__(self, parent=None):
        super().__init__(parent)
        grid = QGridLayout(self)
        self.sliders: dict[str, QSlider] = {}
        self.values: dict[str, QLabel] = {}
        self.buttons: dict[str, list[QPushButton]] = {verb: [] for verb in VERBS}
        self.names: dict[str, QLabel] = {}
        self._asked: dict[str, tuple[int, int]] = {}  # verb -> (percent, statuses since)
        for row, verb in enumerate(SLIDERS):
            self._slider_row(grid, row, verb)
        self._rapid_row(grid, len(SLIDERS))
        self.machine = QLabel()
        grid.addWidget(self.machine, len(SLIDERS) + 1, 0, 1, 8)
        self._reported: tuple[int, int, int] | None = None
        self.ranges: dict[str, tuple[int, ...]] = {}
        self.set_ranges(FRAME_CAPABILITIES)
        self.retranslate_ui()

    def set_ranges(self, capabilities) -> None:
        """The connected driver's override ranges (``capabilities.override_range(verb)``)
        on the sliders and rapid buttons; a rapid rate with no button is refused."""
        ranges = {verb: tuple(capabilities.override_range(verb)) for verb in VERBS}
        unknown = set(ranges["RAPID"]) - set(RAPIDS)
        if unknown or not all(ranges.values()):
            raise ValueError(f"override ranges the panel cannot show: {ranges}")
        self.ranges = ranges
        for verb in SLIDERS:  # a value the new range clamps is shown, not sent
            slider = self.sliders[verb]
            slider.setProperty("syncing", True)
            slider.setRange(ranges[verb][0], ranges[verb][-1])
            slider.setProperty("syncing", False)
        for button in self.rapid_group.buttons():
            button.setVisible(self.rapid_group.id(button) in ranges["RAPID"])

    def clamp(self, verb: str, percent: int) -> int:
        """``percent`` brought into the range of ``verb``'s override."""
        allowed = self.ranges[verb]
        return min(max(percent, allowed[0]), allowed[-1])

    # -- building ------------------------------------------------------------------
    def _slider_row(self, grid: QGridLayout, row: int, verb: str) -> None:
        self.names[verb] = QLabel()
        grid.addWidget(self.names[verb], row, 0)
        slider = self.sliders[verb] = QSlider(Qt.Orientation.Horizontal)
        slider.setRange(min(OVERRIDE_RANGES[verb]), max(OVERRIDE_RANGES[verb]))
        slider.setValue(100)
        slider.setPageStep(10)
        slider.sliderReleased.connect(lambda v=verb: self.request(v, self.sliders[v].value()))
        slider.valueChanged.connect(lambda value, v=verb: self._slid(v, value))
        grid.addWidget(slider, row, 1)
        self.values[verb] = QLabel("100 %")
        grid.addWidget(self.values[verb], row, 2)
        for col, delta in enumerate(STEPS[verb]):
            button = self._button(verb, f"{delta:+d}", lambda _=False, v=verb, d=delta: self.step(v, d))
            grid.addWidget(button, row, 3 + col)
        grid.addWidget(self._button(verb, "100 %", lambda _=False, v=verb: self.request(v, 100)), row, 7)

    def _rapid_row(self, grid: QGridLayout, row: int) -> None:
        self.names["RAPID"] = QLabel()
        grid.addWidget(self.names["RAPID"], row, 0)
        self.rapid_group = QButtonGroup(self)
        for col, percent in enumerate(RAPIDS):
            send = lambda _=False, p=percent: self.request("RAPID", p)  # noqa: E731
            button = self._button("RAPID", f"{percent} %", send)
            button.setCheckable(True)
            button.setChecked(percent == 100)
            self.rapid_group.addButton(button, percent)
            grid.addWidget(button, row, 3 + col)
        self.values["RAPID"] = QLabel("100 %")
        grid.addWidget(self.values["RAPID"], row, 2)

    def _button(self, verb: str, text: str, slot) -> QPushButton:
        button = QPushButton(text)
        button.clicked.connect(slot)
        self.buttons[verb].append(button)
        return button

    def controls(self, verb: str) -> list:
        """The widgets of ``verb``'s override (for the state table)."""
        return [*(s for v, s in self.sliders.items() if v == verb), *self.buttons[verb]]

    def retranslate_ui(self) -> None:
        self.setTitle(self.tr("Overrides"))
        self.names["FEED"].setText(self.tr("Feed"))
        self.names["SPINDLE"].setText(self.tr("Spindle"))
        self.names["RAPID"].setText(self.tr("Rapid"))
        for verb in SLIDERS:
            self.sliders[verb].setToolTip(self.tr("drag, then release to send"))
        self._show_reported()

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    # -- operator --------------------------------------------------------------------
    def value(self, verb: str) -> int:
        """The value the controls show (what was last asked for or reported)."""
        if verb == "RAPID":
            return max(self.rapid_group.checkedId(), RAPIDS[0])
        return self.sliders[verb].value()

    def step(self, verb: str, delta: int) -> None:
        """One step from the value shown (``+10``, ``-1``...), kept within the range."""
        self.request(verb, self.clamp(verb, self.value(verb) + delta))

    def request(self, verb: str, percent: int) -> None:
        """Show ``percent`` and ask the window to send it."""
        self._set_control(verb, percent)
        self._asked[verb] = (percent, 0)
        self.override_requested.emit(verb, percent)

    def _slid(self, verb: str, value: int) -> None:
        self.values[verb].setText(f"{value} %")
        slider = self.sliders[verb]
        by_hand = not slider.isSliderDown() and slider.property("syncing") is not True
        if by_hand and self._asked.get(verb, (None,))[0] != value:  # keyboard or wheel on the slider
            self.request(verb, value)

    def _set_control(self, verb: str, percent: int) -> None:
        if verb == "RAPID":
            button = self.rapid_group.button(percent)
            if button is not None:
                button.setChecked(True)
        else:
            slider = self.sliders[verb]
            slider.setProperty("syncing", True)
            slider.setValue(percent)
            slider.setProperty("syncing", False)
        self.values[verb].setText(f"{percent} %")

    # -- machine ---------------------------------------------------------------------
    def show_machine(self, overrides: tuple[int, int, int] | None) -> None:
        """The overrides of a status (None: a machine that does not report them)."""
        self._reported = overrides
        self._show_reported()
        if overrides is None:
            return
        for verb, percent in zip(VERBS, overrides, strict=True):
            asked = self._asked.get(verb)
            if asked is not None and asked[0] != percent and asked[1] < STALE_AFTER:
                self._asked[verb] = (asked[0], asked[1] + 1)  # not reported yet: keep the request
                continue
            self._asked.pop(verb, None)
            if not (verb in self.sliders and self.sliders[verb].isSliderDown()):
                self._set_control(verb, percent)

    def _show_reported(self) -> None:
        if self._reported is None:
            self.machine.setText(self.tr("Machine: overrides not reported"))
            return
        feed, spindle, rapid = self._reported
        text = self.tr("Machine: feed %1 %, spindle %2 %, rapid %3 %")
        for marker, value in (("%1", feed), ("%2", spindle), ("%3", rapid)):
            text = text.replace(marker, str(value))
        self.machine.setText(text)
        self.machine.setProperty("default", self._reported == NO_OVERRIDES)
