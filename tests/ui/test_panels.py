"""Each panel opens on its own, with no window around it."""

import numpy as np
import pytest

from app.profile import MachineProfile
from app.ui.connection_bar import ConnectionBar
from app.ui.console import ConsoleView
from app.ui.controls import MachineControls
from app.ui.link_alert import LinkAlert
from app.ui.machine_panel import MachinePanelView
from app.ui.plot.diagnostics import DiagnosticsView
from app.ui.plot.history import PositionHistory
from app.ui.plot.position_plot import PositionPlot
from app.ui.preview.widget import PreviewWidget
from app.ui.program.program_panel import ProgramPanel
from app.ui.sd_panel import SdPanel
from app.ui.settings.dialog import SettingsDialog

PANELS = {
    "preview": PreviewWidget,
    "position_plot": lambda: PositionPlot(PositionHistory(100)),
    "diagnostics": lambda: DiagnosticsView(PositionHistory(100)),
    "program": ProgramPanel,
    "console": ConsoleView,
    "connection": lambda: ConnectionBar(lister=lambda: [("sim://", "sim")]),
    "controls": MachineControls,
    "sd": SdPanel,
    "machine_panel": MachinePanelView,
    "settings": lambda: SettingsDialog(MachineProfile()),
    "link_alert": LinkAlert,
}


@pytest.mark.parametrize("name", sorted(PANELS))
def test_panel_opens_on_its_own(qtbot, name):
    widget = PANELS[name]()
    qtbot.addWidget(widget)
    widget.show()
    qtbot.waitExposed(widget)
    assert not widget.grab().isNull()


class FakePanel:
    def __init__(self):
        self.pressed = []
        self.cover = None
        self.led = True
        self.buzzer = False

    def oled_framebuffer(self):
        frame = np.zeros((64, 128), dtype=bool)
        frame[10:20, 10:50] = True
        return frame

    def press(self, name):
        self.pressed.append(name)

    def set_cover(self, is_open):
        self.cover = is_open


def test_machine_panel_mirrors_oled_and_forwards_buttons(qtbot):
    view = MachinePanelView()
    qtbot.addWidget(view)
    panel = FakePanel()
    view.set_panel(panel)
    image = view.oled.pixmap().toImage()
    assert (image.width(), image.height()) == (128 * 3, 64 * 3)
    assert image.pixelColor(15 * 3, 12 * 3).blue() > 200  # lit pixel
    assert image.pixelColor(100 * 3, 50 * 3).blue() == 0  # dark pixel
    for name in ("UP", "DOWN", "OK", "EXIT", "MRESET", "RESET"):
        view.buttons[name].click()
    assert panel.pressed == ["UP", "DOWN", "OK", "EXIT", "MRESET", "RESET"]
    view.cover.setChecked(True)
    assert panel.cover is True
    assert "LED" in view.led.text()
    view.set_panel(None)
    assert not view.buttons["OK"].isEnabled()


def test_console_filters_pauses_and_sends_mdi(qtbot):
    console = ConsoleView()
    qtbot.addWidget(console)
    console.add_frame("tx", "C", "C 5 HOME NORMAL")
    console.add_frame("rx", "S", "S CAFE IDLE 0 0 0")  # status frames hidden by default
    console.flush()
    text = console.log.toPlainText()
    assert "HOME NORMAL" in text and "IDLE" not in text
    console.pause.setChecked(True)
    console.add_frame("rx", "O", "O 5 HOME")
    console.flush()
    assert "O 5 HOME" not in console.log.toPlainText()
    console.pause.setChecked(False)
    console.flush()
    assert "O 5 HOME" in console.log.toPlainText()
    console.filter.setText("spindle")
    console.add_frame("tx", "C", "C 6 JOG X 1 300")
    console.flush()
    assert "JOG" not in console.log.toPlainText()
    with qtbot.waitSignal(console.mdi_submitted) as blocker:
        console.mdi.setText("G0 X10")
        console.mdi.returnPressed.emit()
    assert blocker.args == ["G0 X10"]


def test_controls_start_disabled_and_emit_when_enabled(qtbot):
    """Alone, every control is off until the window's state table enables it."""
    controls = MachineControls()
    qtbot.addWidget(controls)
    assert not any(b.isEnabled() for b in controls.buttons.values())
    controls.buttons["stop"].setEnabled(True)
    with qtbot.waitSignal(controls.stop_requested):
        controls.buttons["stop"].click()


def test_jog_emits_step_and_feed(qtbot):
    controls = MachineControls()
    qtbot.addWidget(controls)
    controls.jog.buttons["Z", -1].setEnabled(True)
    controls.jog.set_step_index(2)
    with qtbot.waitSignal(controls.jog.jog_requested) as blocker:
        controls.jog.buttons["Z", -1].click()
    assert blocker.args == ["Z", -10.0, 300.0]
