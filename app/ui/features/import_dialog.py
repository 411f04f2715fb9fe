"""File > Open of a point list (plain ``x y z`` lines or a "Fabrication Task" file,
recognised by content): the options step (fit into the travel, scale, cut Z, feed,
clearance) with a preview and the summary (scale, offset, bounds) before converting.

"Convert and open" writes the G-code beside the other generated programs and opens
it as any program. A malformed file shows its line and what was expected, and
nothing can be converted.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QTimer, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QDialog,
    QDoubleSpinBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.gcode import load_text
from app.gcode.pointlist import ImportOptions, PointListError, read_points, to_gcode
from app.profile import MachineProfile
from app.ui.preview.widget import PreviewWidget

from .forms import ERROR_STYLE

REFRESH_MS = 150


def _spin(value: float, low: float, high: float, suffix: str, decimals: int = 3) -> QDoubleSpinBox:
    spin = QDoubleSpinBox()
    spin.setRange(low, high)
    spin.setDecimals(decimals)
    spin.setValue(value)
    spin.setSuffix(suffix)
    spin.setKeyboardTracking(False)
    return spin


class PointImportDialog(QDialog):
    """The options step of a point-list import (see the module docstring)."""

    preview_updated = Signal()

    def __init__(self, path: Path, profile: MachineProfile, open_program, generated_dir: Path,
                 parent=None) -> None:
        super().__init__(parent)
        self.path, self.profile, self.open_program = Path(path), profile, open_program
        self.generated_dir = Path(generated_dir)
        self.setWindowTitle(self.tr("Import points: %1").replace("%1", self.path.name))
        self.points, self.text = None, ""
        self._timer = QTimer(self, singleShot=True, interval=REFRESH_MS, timeout=self.refresh)
        layout = QHBoxLayout(self)
        layout.addWidget(self._options())
        travel = (profile.travel.x_max, profile.travel.y_max)
        self.preview = PreviewWidget(travel=travel, offset=profile.travel.work_offset()[:2])
        layout.addWidget(self.preview, 1)
        self.resize(1100, 650)
        self._read()
        self.refresh()

    def _options(self) -> QWidget:
        column = QWidget()
        form = QFormLayout()
        self.fit = QCheckBox(self.tr("Fit X and Y into the travel (keeps the aspect)"))
        self.fit.setChecked(True)
        self.scale = _spin(1.0, 0.0001, 10000, "", 4)
        self.use_cut_z = QCheckBox(self.tr("Cut every point at one Z"))
        self.use_cut_z.setChecked(True)
        self.cut_z = _spin(-0.2, -100, 100, " mm")
        feed = min(300.0, self.profile.motion.max_feed_mm_min)
        self.feed = _spin(feed, 1, self.profile.motion.max_feed_mm_min, " mm/min", 0)
        self.clearance = _spin(5.0, 0.1, 100, " mm")
        form.addRow(self.fit)
        form.addRow(self.tr("Scale (after fitting)"), self.scale)
        form.addRow(self.use_cut_z)
        form.addRow(self.tr("Cut Z"), self.cut_z)
        form.addRow(self.tr("Feed"), self.feed)
        form.addRow(self.tr("Clearance height"), self.clearance)
        for widget in (self.fit, self.use_cut_z):
            widget.toggled.connect(self._timer.start)
        for spin in (self.scale, self.cut_z, self.feed, self.clearance):
            spin.valueChanged.connect(self._timer.start)
        self.summary = QLabel()
        self.summary.setWordWrap(True)
        self.problem = QLabel()
        self.problem.setStyleSheet(ERROR_STYLE)
        self.problem.setWordWrap(True)
        self.convert_button = QPushButton(self.tr("Convert and open"))
        self.convert_button.clicked.connect(self.convert)
        cancel = QPushButton(self.tr("Cancel"))
        cancel.clicked.connect(self.reject)
        buttons = QHBoxLayout()
        buttons.addWidget(self.convert_button)
        buttons.addWidget(cancel)
        layout = QVBoxLayout(column)
        layout.addLayout(form)
        layout.addWidget(self.summary)
        layout.addWidget(self.problem)
        layout.addStretch(1)
        layout.addLayout(buttons)
        column.setMaximumWidth(420)
        return column

    def _read(self) -> None:
        try:
            self.points = read_points(self.path.read_bytes(), self.path.name)
        except OSError as exc:
            self.problem.setText(self.tr("%1 cannot be read: %2").replace("%1", self.path.name)
                                 .replace("%2", exc.strerror or str(exc)))
        except PointListError as exc:
            self.problem.setText(str(exc))

    def options(self) -> ImportOptions:
        cut_z = self.cut_z.value() if self.use_cut_z.isChecked() else None
        return ImportOptions(self.fit.isChecked(), self.scale.value(), cut_z, self.feed.value(),
                             self.clearance.value(), self.profile.spindle.no_load_rpm)

    def refresh(self) -> None:
        """Convert with the current options; preview and summary, or the problem."""
        self._timer.stop()
        self.cut_z.setEnabled(self.use_cut_z.isChecked())
        ok = False
        if self.points is not None:
            try:
                self.text, placement = to_gcode(self.points, self.options(), self.profile)
            except PointListError as exc:
                self.problem.setText(str(exc))
            else:
                self.problem.clear()
                program = load_text(self.text, self.path.name)
                self.preview.show_program(program.toolpath, self.profile.motion.arc_tolerance_mm)
                self.summary.setText(placement.describe(self.points, self.options()))
                ok = True
        self.convert_button.setEnabled(ok)
        self.preview_updated.emit()

    def convert(self) -> None:
        self.refresh()
        if not self.convert_button.isEnabled():
            return
        self.generated_dir.mkdir(parents=True, exist_ok=True)
        target = self.generated_dir / f"{self.path.stem}.nc"
        target.write_text(self.text, encoding="utf-8")
        self.open_program(target)
        self.accept()
