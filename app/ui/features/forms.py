"""A form of labelled fields, each with its unit and range and, beside it, the message
of what is wrong with it (``show_error(name, text)``). ``changed`` is emitted on
every edit; ``values()`` / ``set_values()`` read and fill it by field name."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDoubleSpinBox,
    QFileDialog,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QWidget,
)

from .spec import Field

ERROR_STYLE = "color: #d03030;"


UNITS = (QT_TRANSLATE_NOOP("FeatureForm", "mm/min"), QT_TRANSLATE_NOOP("FeatureForm", "rpm"))  # others: as is


def _tr(text: str) -> str:
    return QCoreApplication.translate("FeatureForm", text)



class FieldForm(QWidget):
    """Rows of label, editor and error message (see the module docstring)."""

    changed = Signal()

    def __init__(self, fields: list[Field], parent=None) -> None:
        super().__init__(parent)
        self.grid = QGridLayout(self)
        self.grid.setColumnStretch(2, 1)
        self.editors: dict[str, tuple[QWidget, Callable, Callable]] = {}
        self.errors: dict[str, QLabel] = {}
        for field in fields:
            self.add_spin(field)

    def _row(self, name: str, label: str, editor: QWidget, getter, setter) -> None:
        row = self.grid.rowCount()
        self.grid.addWidget(QLabel(label), row, 0)
        self.grid.addWidget(editor, row, 1)
        error = QLabel()
        error.setStyleSheet(ERROR_STYLE)
        error.setWordWrap(True)
        error.setObjectName(f"error_{name}")
        self.grid.addWidget(error, row, 2)
        self.editors[name] = (editor, getter, setter)
        self.errors[name] = error

    def add_spin(self, field: Field) -> QDoubleSpinBox:
        spin = QDoubleSpinBox()
        spin.setObjectName(field.name)
        spin.setDecimals(field.decimals)
        spin.setRange(field.low, field.high)
        spin.setValue(field.default)
        if field.unit:
            spin.setSuffix(f" {_tr(field.unit)}")
        spin.setKeyboardTracking(False)
        spin.valueChanged.connect(self.changed)
        self._row(field.name, _tr(field.label), spin, spin.value, spin.setValue)
        return spin

    def add_check(self, name: str, label: str) -> QCheckBox:
        box = QCheckBox(label)
        box.setObjectName(name)
        box.toggled.connect(self.changed)
        self._row(name, "", box, box.isChecked, box.setChecked)
        return box

    def add_choice(self, name: str, label: str, items: list[tuple[str, str]]) -> QComboBox:
        combo = QComboBox()
        combo.setObjectName(name)
        for key, text in items:
            combo.addItem(text, key)
        combo.currentIndexChanged.connect(self.changed)
        self._row(name, label, combo, combo.currentData,
                  lambda key: combo.setCurrentIndex(max(0, combo.findData(key))))
        return combo

    def add_file(self, name: str, label: str, caption: str) -> QLineEdit:
        edit = QLineEdit()
        edit.setObjectName(name)
        edit.editingFinished.connect(self.changed)
        browse = QPushButton(QCoreApplication.translate("FeatureForm", "Browse…"))
        holder = QWidget()
        layout = QHBoxLayout(holder)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(edit, 1)
        layout.addWidget(browse)

        def pick() -> None:
            path, _ = QFileDialog.getOpenFileName(self, caption, edit.text())
            if path:
                edit.setText(path)
                self.changed.emit()

        browse.clicked.connect(pick)
        self._row(name, label, holder, edit.text, edit.setText)
        return edit

    def values(self) -> dict:
        return {name: getter() for name, (_, getter, _) in self.editors.items()}

    def set_values(self, values: dict) -> None:
        """Fill the fields this form has from ``values`` without emitting ``changed``."""
        self.blockSignals(True)
        for name, (editor, _, setter) in self.editors.items():
            if name in values:
                editor.blockSignals(True)
                setter(values[name])
                editor.blockSignals(False)
        self.blockSignals(False)

    def show_error(self, name: str, text: str) -> bool:
        """Show ``text`` beside field ``name``; False when the form has no such field."""
        if name not in self.errors:
            return False
        self.errors[name].setText(text)
        return True

    def clear_errors(self) -> None:
        for label in self.errors.values():
            label.clear()
