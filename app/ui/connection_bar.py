"""Connection bar: port (simulators first, refreshed when the list opens), baud, the
protocol (auto, this mill's frames, GRBL), Connect / Disconnect, the link indicator, what
the machine says it is (a GRBL's welcome and ``$I``) and the machine's state."""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QEvent, Signal
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QPushButton, QWidget

from app.ui.ports import available_ports

BAUDS = (9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)
LINK_COLOURS = {
    "CONNECTED": "#2ecc40",
    "DEGRADED": "#ffb000",
    "LOST": "#ff3030",
    "DISCONNECTED": "#808080",
    "CONNECTING": "#5fa8d3",
}

# Words shown for codes of the protocol (translated where shown).
LINK_STATES = {
    "CONNECTED": QT_TRANSLATE_NOOP("LinkState", "connected"),
    "DEGRADED": QT_TRANSLATE_NOOP("LinkState", "degraded"),
    "LOST": QT_TRANSLATE_NOOP("LinkState", "lost"),
    "DISCONNECTED": QT_TRANSLATE_NOOP("LinkState", "disconnected"),
    "CONNECTING": QT_TRANSLATE_NOOP("LinkState", "connecting"),
}
MACHINE_STATES = {
    "IDLE": QT_TRANSLATE_NOOP("MachineState", "IDLE"),
    "HOMING": QT_TRANSLATE_NOOP("MachineState", "HOMING"),
    "RUN": QT_TRANSLATE_NOOP("MachineState", "RUN"),
    "HOLD": QT_TRANSLATE_NOOP("MachineState", "HOLD"),
    "JOG": QT_TRANSLATE_NOOP("MachineState", "JOG"),
    "ALARM": QT_TRANSLATE_NOOP("MachineState", "ALARM"),
}
DRIVERS = (  # the connection bar's protocol choice: (driver for the worker, shown name)
    ("auto", QT_TRANSLATE_NOOP("Drivers", "Auto")),
    ("frame", QT_TRANSLATE_NOOP("Drivers", "This mill")),
    ("grbl", QT_TRANSLATE_NOOP("Drivers", "GRBL")),
)
FLAG_WORDS = {
    "H": QT_TRANSLATE_NOOP("MachineFlags", "homed"),
    "C": QT_TRANSLATE_NOOP("MachineFlags", "cover open"),
    "L": QT_TRANSLATE_NOOP("MachineFlags", "host lost"),
    "U": QT_TRANSLATE_NOOP("MachineFlags", "UART lost"),
    "P": QT_TRANSLATE_NOOP("MachineFlags", "spindle"),
    "S": QT_TRANSLATE_NOOP("MachineFlags", "SD"),
}


class PortCombo(QComboBox):
    """An editable port list that refreshes itself every time it is opened."""

    def __init__(self, parent=None, lister=available_ports):
        super().__init__(parent)
        self.setEditable(True)
        self.setMinimumContentsLength(22)
        self._lister = lister
        self.refresh()

    def refresh(self) -> None:
        current = self.currentText()
        self.clear()
        for url, description in self._lister():
            self.addItem(description, url)
        at = self.findData(current)
        if at >= 0:
            self.setCurrentIndex(at)
        elif current:
            self.setEditText(current)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.refresh()
        super().changeEvent(event)

    def showPopup(self) -> None:  # noqa: N802 (Qt override)
        self.refresh()
        super().showPopup()

    def url(self) -> str:
        at = self.findText(self.currentText())
        data = self.itemData(at) if at >= 0 else None
        return str(data or self.currentText()).strip()


class ConnectionBar(QWidget):
    connect_requested = Signal(str, int)
    disconnect_requested = Signal()

    def __init__(self, parent=None, lister=available_ports):
        super().__init__(parent)
        self.ports = PortCombo(lister=lister)
        self.baud = QComboBox()
        for rate in BAUDS:
            self.baud.addItem(str(rate), rate)
        self.baud.setCurrentText("115200")
        self.driver = QComboBox()
        for _ in DRIVERS:
            self.driver.addItem("")
        self.button = QPushButton()
        self.button.clicked.connect(self._clicked)
        self.link = QLabel()
        self.state = QLabel("—")
        self.state.setMinimumWidth(160)
        self.port_label, self.baud_label, self.machine_label = QLabel(), QLabel(), QLabel()
        self.driver_label, self.info = QLabel(), QLabel()
        layout = QHBoxLayout(self)
        layout.setContentsMargins(4, 0, 4, 0)
        for widget in (self.port_label, self.ports, self.baud_label, self.baud, self.driver_label,
                       self.driver, self.button, self.link):
            layout.addWidget(widget)
        layout.addWidget(self.info)
        layout.addWidget(self.machine_label)
        layout.addWidget(self.state)
        self.connected = False
        self._link_shown = ("DISCONNECTED", "")
        self._state_shown = ("—", "")
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.port_label.setText(self.tr("Port"))
        self.baud_label.setText(self.tr("Baud"))
        self.machine_label.setText(self.tr("Machine:"))
        self.driver_label.setText(self.tr("Protocol"))
        for at, (_key, name) in enumerate(DRIVERS):
            self.driver.setItemText(at, QCoreApplication.translate("Drivers", name))
        self.set_connected(self.connected)
        self.set_link(*self._link_shown)
        state, flags = self._state_shown
        self._state_shown = None
        self.set_machine_state(state, flags)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def _clicked(self) -> None:
        if self.connected:
            self.disconnect_requested.emit()
        else:
            self.connect_requested.emit(self.ports.url(), int(self.baud.currentData()))

    def set_connected(self, connected: bool) -> None:
        self.connected = connected
        self.button.setText(self.tr("Disconnect") if connected else self.tr("Connect"))
        self.ports.setEnabled(not connected)
        self.baud.setEnabled(not connected)
        self.driver.setEnabled(not connected)
        if not connected:
            self.info.clear()

    def driver_choice(self) -> str:
        """"auto", "frame" or "grbl" (``app.comm.driver``)."""
        return DRIVERS[max(self.driver.currentIndex(), 0)][0]

    def set_machine_info(self, text: str) -> None:
        """What the machine says it is (e.g. ``Grbl 1.1h · 1.1h.20190830``), shown as it is."""
        self.info.setText(text)
        self.info.setToolTip(text)

    def set_link(self, state: str, detail: str = "") -> None:
        """``detail`` is shown as it is: the caller translates it."""
        self._link_shown = (state, detail)
        colour = LINK_COLOURS.get(state, "#808080")
        name = QCoreApplication.translate("LinkState", LINK_STATES.get(state, state))
        text = self.tr("link %1").replace("%1", name) + (f" ({detail})" if detail else "")
        self.link.setText(f"<span style='color:{colour}; font-size:14pt'>●</span> {text}")
        self.link.setToolTip(detail or name)

    def set_machine_state(self, state: str, flags: str = "") -> None:
        if (state, flags) == self._state_shown and self.state.text():
            return
        self._state_shown = (state, flags)
        extra = [QCoreApplication.translate("MachineFlags", FLAG_WORDS[f]) for f in flags if f in FLAG_WORDS]
        shown = QCoreApplication.translate("MachineState", MACHINE_STATES.get(state, state))
        self.state.setText(shown + (f" · {', '.join(extra)}" if extra else ""))
