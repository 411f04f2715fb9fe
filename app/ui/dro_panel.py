"""The full DRO: work and machine coordinates side by side, the active coordinate system,
the six systems' offsets (read from the machine, typed into), "zero here" per axis and
"go to" work zero or a typed position.

The panel only shows and asks: ``show`` takes the host's ``WorkSystems`` and the last
work position; the operator's requests leave as signals (``app/ui/dro.py`` sends them).
"""

from __future__ import annotations

import math

from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from app.ui.numbers import decimal, fill, parse_number
from app.ui.work_offsets import AXES, SYSTEMS, WorkSystems

UNKNOWN = "—"


def _mm(value: float | None) -> str:
    return UNKNOWN if value is None else decimal(value, 3)


def typed_number(text: str) -> float | None:
    """A finite number typed with a point or a comma, else ``None``."""
    try:
        value = float(parse_number(text))
    except ValueError:
        return None
    return value if math.isfinite(value) else None


class DroPanel(QWidget):
    select_requested = Signal(int)  # 54..59
    row_edited = Signal(int, str, float)  # system, axis, machine mm
    zero_requested = Signal(str)  # one axis
    move_requested = Signal(dict)  # axis -> work mm (axes left out stay)
    refused = Signal(str)  # what the operator typed that cannot be sent, and why

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._showing = False
        layout = QVBoxLayout(self)
        layout.addWidget(self._coordinates())
        layout.addWidget(self._table_box())
        layout.addWidget(self._move_box())
        self.retranslate_ui()

    # -- building ----------------------------------------------------------------------

    def _coordinates(self) -> QGroupBox:
        box = self.coordinates_box = QGroupBox()
        grid = QGridLayout(box)
        self.wcs = QComboBox()
        self.wcs.addItems([f"G{n}" for n in SYSTEMS])
        self.wcs.activated.connect(lambda index: self.select_requested.emit(SYSTEMS[index]))
        self.wcs_label, self.work_head, self.machine_head = QLabel(), QLabel(), QLabel()
        self.g92 = QLabel()
        grid.addWidget(self.wcs_label, 0, 0)
        grid.addWidget(self.wcs, 0, 1)
        grid.addWidget(self.g92, 0, 2, 1, 2)
        grid.addWidget(self.work_head, 1, 1)
        grid.addWidget(self.machine_head, 1, 2)
        self.work, self.machine, self.zero = {}, {}, {}
        for row, axis in enumerate(AXES, start=2):
            grid.addWidget(QLabel(axis), row, 0)
            for column, labels in ((1, self.work), (2, self.machine)):
                labels[axis] = QLabel(UNKNOWN)
                labels[axis].setAlignment(Qt.AlignmentFlag.AlignRight)
                grid.addWidget(labels[axis], row, column)
            button = self.zero[axis] = QPushButton()
            button.clicked.connect(lambda _=False, a=axis: self.zero_requested.emit(a))
            grid.addWidget(button, row, 3)
        return box

    def _table_box(self) -> QGroupBox:
        box = self.table_box = QGroupBox()
        self.table = QTableWidget(len(SYSTEMS), len(AXES))
        self.table.setVerticalHeaderLabels([f"G{n}" for n in SYSTEMS])
        self.table.setHorizontalHeaderLabels(list(AXES))
        self.table.itemChanged.connect(self._edited)
        QVBoxLayout(box).addWidget(self.table)
        return box

    def _move_box(self) -> QGroupBox:
        box = self.move_box = QGroupBox()
        row = QHBoxLayout(box)
        self.target = {axis: QLineEdit() for axis in AXES}
        for axis, field in self.target.items():
            row.addWidget(QLabel(axis))
            row.addWidget(field)
        self.go_to = QPushButton()
        self.go_to.clicked.connect(self._go_to_typed)
        self.go_zero = QPushButton()
        self.go_zero.clicked.connect(lambda: self.move_requested.emit({a: 0.0 for a in AXES}))
        row.addWidget(self.go_to)
        row.addWidget(self.go_zero)
        return box

    def retranslate_ui(self) -> None:
        self.coordinates_box.setTitle(self.tr("Position"))
        self.wcs_label.setText(self.tr("Coordinate system"))
        self.work_head.setText(self.tr("Work"))
        self.machine_head.setText(self.tr("Machine"))
        for axis, button in self.zero.items():
            button.setText(fill(self.tr("Zero %1"), axis))
            tip = self.tr("Make the current position the work zero of %1 in the active system")
            button.setToolTip(fill(tip, axis))
        self.table_box.setTitle(self.tr("Work offsets (machine position of each work zero, mm)"))
        self.move_box.setTitle(self.tr("Go to (work mm; an empty axis stays)"))
        self.go_to.setText(self.tr("Go"))
        self.go_zero.setText(self.tr("Go to work zero"))
        tip = self.tr("Rapid to the top of Z first, then across, then down")
        self.go_to.setToolTip(tip)
        self.go_zero.setToolTip(tip)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    # -- showing -----------------------------------------------------------------------

    def show_state(self, systems: WorkSystems, work: tuple[float, float, float] | None,
                   g92: str = "") -> None:
        """What the machine has answered, and the last work position (``None``: none yet)."""
        self._showing = True
        if systems.active in SYSTEMS:
            self.wcs.setCurrentIndex(SYSTEMS.index(systems.active))
        self.wcs.setVisible(systems.supported is not False)
        machine = systems.machine(work) if work is not None else [None] * 3
        for k, axis in enumerate(AXES):
            self.work[axis].setText(_mm(None if work is None else work[k]))
            self.machine[axis].setText(_mm(machine[k]))
        for r, system in enumerate(SYSTEMS):
            for c in range(len(AXES)):
                self._cell(r, c, systems.rows[system][c], editable=systems.supported is not False)
            self.table.setRowHidden(r, systems.supported is False and system != 54)
        self.g92.setText(fill(self.tr("G92 in force: %1"), g92) if g92 else "")
        self._showing = False

    def _cell(self, row: int, column: int, value: float | None, editable: bool) -> None:
        item = self.table.item(row, column)
        if item is None:
            item = QTableWidgetItem()
            item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            self.table.setItem(row, column, item)
        editing = (self.table.state() == QAbstractItemView.State.EditingState
                   and self.table.currentItem() is item)
        if item.text() != _mm(value) and not editing:  # a cell being typed into is left alone
            item.setText(_mm(value))
        flags = Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsSelectable
        flags = flags | Qt.ItemFlag.ItemIsEditable if editable else flags
        if item.flags() != flags:
            item.setFlags(flags)

    # -- asking ------------------------------------------------------------------------

    def _edited(self, item: QTableWidgetItem) -> None:
        if self._showing:
            return
        value = typed_number(item.text())
        if value is None:
            self.refused.emit(fill(self.tr("Work offset %1 %2: “%3” is not a number"),
                                   f"G{SYSTEMS[item.row()]}", AXES[item.column()], item.text()))
            return
        self.row_edited.emit(SYSTEMS[item.row()], AXES[item.column()], value)

    def _go_to_typed(self) -> None:
        target = {}
        for axis, field in self.target.items():
            if not field.text().strip():
                continue
            value = typed_number(field.text())
            if value is None:
                self.refused.emit(fill(self.tr("Go to %1: “%2” is not a number"), axis, field.text()))
                field.setFocus()
                field.selectAll()
                return
            target[axis] = value
        if target:
            self.move_requested.emit(target)
