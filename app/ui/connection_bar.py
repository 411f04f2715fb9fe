"""Connection bar: port (simulator first, refreshed when the list opens), baud,
Connect / Disconnect, the link indicator and the machine's state."""

from __future__ import annotations

from PySide6.QtCore import Signal
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
        self.button = QPushButton("Connect")
        self.button.clicked.connect(self._clicked)
        self.link = QLabel()
        self.state = QLabel("—")
        self.state.setMinimumWidth(160)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(4, 0, 4, 0)
        for widget in (QLabel("Port"), self.ports, QLabel("Baud"), self.baud, self.button, self.link):
            layout.addWidget(widget)
        layout.addWidget(QLabel("Machine:"))
        layout.addWidget(self.state)
        self.connected = False
        self.set_link("DISCONNECTED")

    def _clicked(self) -> None:
        if self.connected:
            self.disconnect_requested.emit()
        else:
            self.connect_requested.emit(self.ports.url(), int(self.baud.currentData()))

    def set_connected(self, connected: bool) -> None:
        self.connected = connected
        self.button.setText("Disconnect" if connected else "Connect")
        self.ports.setEnabled(not connected)
        self.baud.setEnabled(not connected)

    def set_link(self, state: str, detail: str = "") -> None:
        colour = LINK_COLOURS.get(state, "#808080")
        text = state.lower() + (f" ({detail})" if detail else "")
        self.link.setText(f"<span style='color:{colour}; font-size:14pt'>●</span> link {text}")
        self.link.setToolTip(detail or state)

    def set_machine_state(self, state: str, flags: str = "") -> None:
        words = {"H": "homed", "C": "cover open", "L": "host lost", "U": "UART lost",
                 "P": "spindle", "S": "SD"}
        extra = [words[f] for f in flags if f in words]
        self.state.setText(state + (f" · {', '.join(extra)}" if extra else ""))
