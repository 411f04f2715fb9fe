"""File > Open of a point list (plain ``x y z`` lines or a "Fabrication Task" file,
recognised by content): the options step (fit into the travel, scale, cut Z, feed,
clearance) with a preview and the summary (scale, offset, bounds) before converting.

"Convert and open" writes the G-code beside the other generated programs and opens
it as any program. A malformed file shows its line and what was expected, and
nothing can be converted. Reading, converting and preparing the preview run on a
thread (a million points take seconds); only the newest request is shown, and
``preview_updated`` is emitted when it is.
"""

from __future__ import annotations

import contextlib
import threading
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
from app.gcode.features import FeatureError
from app.gcode.pointlist import ImportOptions, PointListError, read_points, to_gcode
from app.gcode.reading import SourceError, read_source
from app.i18n import localize
from app.profile import MachineProfile
from app.ui.preview.model import PreviewModel, screen_tolerance
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
    _converted = Signal(object)  # (request, text, placement, model, problem)

    def __init__(self, path: Path, profile: MachineProfile, open_program, generated_dir: Path,
                 parent=None) -> None:
        super().__init__(parent)
        self.path, self.profile, self.open_program = Path(path), profile, open_program
        self.generated_dir = Path(generated_dir)
        self.setWindowTitle(self.tr("Import points: %1").replace("%1", self.path.name))
        self.points, self.text, self.problem_text = None, "", ""
        self._request, self._shown = 0, 0
        self._converted.connect(self._show)
        self._timer = QTimer(self, singleShot=True, interval=REFRESH_MS, timeout=self.refresh)
        layout = QHBoxLayout(self)
        layout.addWidget(self._options())
        travel = (profile.travel.x_max, profile.travel.y_max)
        self.preview = PreviewWidget(travel=travel, offset=profile.travel.work_offset()[:2])
        layout.addWidget(self.preview, 1)
        self.resize(1100, 650)
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
        self.feed = _spin(feed, 1, self.profile.motion.max_feed_mm_min, self.tr(" mm/min"), 0)
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

    def _read(self) -> str:
        """Read the file once; the problem, or "" when it reads."""
        if self.points is None and not self.problem_text:
            try:
                self.points = read_points(read_source(self.path), self.path.name)
            except SourceError as exc:  # the loader's file checks: a FIFO, a device, too big
                self.problem_text = localize(exc.args[0])
            except PointListError as exc:
                self.problem_text = exc.localized()
        return self.problem_text

    def options(self) -> ImportOptions:
        cut_z = self.cut_z.value() if self.use_cut_z.isChecked() else None
        return ImportOptions(self.fit.isChecked(), self.scale.value(), cut_z, self.feed.value(),
                             self.clearance.value(), self.profile.max_spindle_rpm())

    def refresh(self) -> None:
        """Convert with the current options on a thread; ``_show`` draws the newest."""
        self._timer.stop()
        self.cut_z.setEnabled(self.use_cut_z.isChecked())
        self._request += 1
        self.convert_button.setEnabled(False)
        self.summary.setText(self.tr("Converting…"))
        size = self.preview.view.size()
        try:
            options = self.options()
        except FeatureError as exc:  # an option out of its range (the spin boxes keep to them)
            self._show((self._request, "", None, None, exc.localized()))
            return
        args = (self._request, options, (max(size.width(), 100), max(size.height(), 100)))
        threading.Thread(target=self._convert, args=args, name="points-convert", daemon=True).start()

    def _convert(self, request: int, options: ImportOptions, view_size) -> None:
        problem = self._read()
        if problem:
            self._emit((request, "", None, None, problem))
            return
        try:
            text, placement = to_gcode(self.points, options, self.profile)
        except (PointListError, FeatureError) as exc:
            self._emit((request, "", None, None, exc.localized()))
            return
        toolpath = load_text(text, self.path.name).toolpath
        tolerance = screen_tolerance(toolpath, view_size, self.profile.motion.arc_tolerance_mm)
        model = PreviewModel(toolpath, tolerance)
        model.warm(view_size)
        self._emit((request, text, placement.describe(self.points, options), model, ""))

    def _emit(self, result) -> None:
        with contextlib.suppress(RuntimeError):  # the dialog was closed (and deleted) meanwhile
            self._converted.emit(result)

    def _show(self, result) -> None:
        request, text, summary, model, problem = result
        if request != self._request:  # an older request: a newer one is on its way
            return
        self.text = text
        self.problem.setText(problem)
        self.summary.setText(summary or "")
        if model is not None:
            self.preview.show_model(model)
        self.convert_button.setEnabled(not problem)
        self.preview_updated.emit()

    def convert(self) -> None:
        """Write and open the newest conversion (nothing while one is on its way)."""
        if not self.convert_button.isEnabled() or not self.text:
            return
        self.generated_dir.mkdir(parents=True, exist_ok=True)
        target = self.generated_dir / f"{self.path.stem}.nc"
        target.write_text(self.text, encoding="utf-8")
        self.open_program(target)
        self.accept()
