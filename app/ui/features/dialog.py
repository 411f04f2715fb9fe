"""Features > New job: a list of features the operator orders, one form per kind for
the selected one, a live preview of the whole job with its estimated time, and "Open
as program" / "Save as…".

Every edit restarts a short timer; then the job is generated (``app.gcode.features``),
read back by the loader and drawn by the window's preview widget. A bad value's
message appears beside its field; a problem in another feature of the list is named
under the preview. ``preview_updated`` is emitted after each refresh.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QTimer, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QDialog,
    QFileDialog,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QPushButton,
    QScrollArea,
    QSplitter,
    QStackedWidget,
    QVBoxLayout,
    QWidget,
)

from app.gcode import load_text
from app.gcode.features import FeatureError, program_moves, write_plain
from app.gcode.features.fanuc import write_fanuc
from app.i18n import localize
from app.profile import MachineProfile
from app.ui.preview.widget import PreviewWidget

from . import spec
from .forms import ERROR_STYLE, FieldForm

REFRESH_MS = 150
OUTLINE_COLOUR = "#f0f0f0"


def _tr(text: str) -> str:
    return QCoreApplication.translate("FeatureForm", text)


PROGRAM_TITLE = "machining features"  # the program's comment: file content stays ASCII English, as G-code

class FeatureDialog(QDialog):
    """The feature job editor (see the module docstring). ``open_program(path)`` is
    called with the saved program when the operator picks "Open as program"."""

    preview_updated = Signal()

    def __init__(self, profile: MachineProfile, open_program, generated_dir: Path, parent=None) -> None:
        super().__init__(parent)
        self.setWindowTitle(self.tr("Machining features"))
        self.profile, self.open_program, self.generated_dir = profile, open_program, Path(generated_dir)
        self.job: list[dict] = []  # {"kind": str, "values": dict}
        self.text, self.moves = "", []  # the last good program and its moves
        self.program = None
        self._timer = QTimer(self, singleShot=True, interval=REFRESH_MS, timeout=self.refresh)
        splitter = QSplitter()
        splitter.addWidget(self._job_column())
        splitter.addWidget(self._form_column())
        splitter.addWidget(self._preview_column())
        splitter.setSizes([200, 520, 580])
        layout = QVBoxLayout(self)
        layout.addWidget(splitter, 1)
        layout.addLayout(self._buttons())
        self.resize(1300, 760)
        self.add_feature("pocket-rect")

    # -- building ---------------------------------------------------------------------

    def _job_column(self) -> QWidget:
        box = QGroupBox(self.tr("Job (in order)"))
        layout = QVBoxLayout(box)
        self.list = QListWidget()
        self.list.currentRowChanged.connect(self._select)
        layout.addWidget(self.list, 1)
        self.kind = QComboBox()
        for kind, title in spec.KIND_TITLES.items():
            self.kind.addItem(_tr(title), kind)
        layout.addWidget(self.kind)
        row = QHBoxLayout()
        for text, slot in ((self.tr("Add"), lambda: self.add_feature(self.kind.currentData())),
                           (self.tr("Remove"), self.remove_feature),
                           (self.tr("Up"), lambda: self.move_feature(-1)),
                           (self.tr("Down"), lambda: self.move_feature(1))):
            button = QPushButton(text)
            button.clicked.connect(slot)
            row.addWidget(button)
        layout.addLayout(row)
        return box

    def _form_column(self) -> QWidget:
        self.forms: dict[str, FieldForm] = {}
        self.stack = QStackedWidget()
        for kind, fields in spec.KIND_FIELDS.items():
            form = FieldForm(fields)
            if kind == "profile":
                form.add_file("contour", self.tr("Contour file"), self.tr("Open a contour"))
                form.add_choice("side", self.tr("Side"), [("outside", self.tr("outside (island)")),
                                                          ("inside", self.tr("inside (pocket)"))])
            form.changed.connect(self._edited)
            self.forms[kind] = form
            self.stack.addWidget(form)
        self.cutting = FieldForm(spec.cutting_fields(self.profile))
        self.cutting.add_check("climb", self.tr("Climb milling (else conventional)"))
        self.cutting.changed.connect(self._edited)
        self.title = QLabel()
        column = QWidget()
        layout = QVBoxLayout(column)
        layout.addWidget(self.title)
        geometry = QGroupBox(self.tr("Geometry"))
        QVBoxLayout(geometry).addWidget(self.stack)
        cutting = QGroupBox(self.tr("Tool and cutting"))
        QVBoxLayout(cutting).addWidget(self.cutting)
        layout.addWidget(geometry)
        layout.addWidget(cutting)
        layout.addStretch(1)
        scroll = QScrollArea()
        scroll.setWidgetResizable(True)
        scroll.setWidget(column)
        return scroll

    def _preview_column(self) -> QWidget:
        travel = (self.profile.travel.x_max, self.profile.travel.y_max)
        self.preview = PreviewWidget(travel=travel, offset=self.profile.travel.work_offset()[:2])
        self.outline = self.preview.plot.plot(pen=pg.mkPen(OUTLINE_COLOUR, width=2))
        self.outline.setZValue(20)
        self.estimate = QLabel()
        self.problem = QLabel()
        self.problem.setStyleSheet(ERROR_STYLE)
        self.problem.setWordWrap(True)
        column = QWidget()
        layout = QVBoxLayout(column)
        layout.addWidget(self.preview, 1)
        layout.addWidget(self.estimate)
        layout.addWidget(self.problem)
        return column

    def _buttons(self) -> QHBoxLayout:
        row = QHBoxLayout()
        row.addStretch(1)
        self.open_button = QPushButton(self.tr("Open as program"))
        self.open_button.clicked.connect(self.open_as_program)
        self.dialect = QComboBox()
        for key, text in (("plain", self.tr("plain G-code")), ("fanuc21", self.tr("Fanuc 21 macro")),
                          ("fanuc31", self.tr("Fanuc 31 macro"))):
            self.dialect.addItem(text, key)
        self.save_button = QPushButton(self.tr("Save as…"))
        self.save_button.clicked.connect(self.save_as)
        row.addWidget(QLabel(self.tr("Save in")))
        row.addWidget(self.dialect)
        close = QPushButton(self.tr("Close"))
        close.clicked.connect(self.reject)
        for button in (self.open_button, self.save_button, close):
            row.addWidget(button)
        return row

    # -- the job ----------------------------------------------------------------------

    def add_feature(self, kind: str) -> None:
        self.job.append({"kind": kind, "values": spec.defaults(kind, self.profile)})
        self.list.addItem(_tr(spec.KIND_TITLES[kind]))
        self.list.setCurrentRow(len(self.job) - 1)
        self._timer.start()

    def remove_feature(self) -> None:
        row = self.list.currentRow()
        if row < 0 or len(self.job) <= 1:
            return
        del self.job[row]
        self.list.takeItem(row)
        self._timer.start()

    def move_feature(self, step: int) -> None:
        row, target = self.list.currentRow(), self.list.currentRow() + step
        if row < 0 or not 0 <= target < len(self.job):
            return
        self.job[row], self.job[target] = self.job[target], self.job[row]
        item = self.list.takeItem(row)
        self.list.insertItem(target, item)
        self.list.setCurrentRow(target)
        self._timer.start()

    def current_form(self) -> FieldForm:
        return self.forms[self.job[self.list.currentRow()]["kind"]]

    def _select(self, row: int) -> None:
        if row < 0:
            return
        entry = self.job[row]
        self.stack.setCurrentWidget(self.forms[entry["kind"]])
        self.title.setText(f"<b>{row + 1}. {_tr(spec.KIND_TITLES[entry['kind']])}</b>")
        self.forms[entry["kind"]].set_values(entry["values"])
        self.cutting.set_values(entry["values"])
        self._show_errors()

    def _edited(self) -> None:
        row = self.list.currentRow()
        if row >= 0:
            self.job[row]["values"].update(self.current_form().values())
            self.job[row]["values"].update(self.cutting.values())
        self._timer.start()

    # -- preview ----------------------------------------------------------------------

    def _features(self):
        """The job's features, and (row, FeatureError) of the first bad one."""
        features = []
        for row, entry in enumerate(self.job):
            try:
                features.append(spec.build(entry["kind"], entry["values"]))
            except FeatureError as exc:
                return None, (row, exc)
        return features, None

    def refresh(self) -> None:
        """Generate the job, draw it, say its time or what is wrong."""
        self._timer.stop()
        features, bad = self._features()
        if bad is None:
            try:
                moves = program_moves(features, self.profile)
                text = write_plain(moves, PROGRAM_TITLE)
            except FeatureError as exc:  # the travel: which feature cannot be known from the text
                bad = (self.list.currentRow(), exc)
        self._show_errors(bad)
        if bad is None:
            self.text, self.moves = text, moves
            self.program = load_text(text, "features.nc")
            self.preview.show_program(self.program.toolpath, self.profile.motion.arc_tolerance_mm)
            self._draw_outlines(features)
            minutes, seconds = divmod(int(round(self.program.toolpath.estimated_time)), 60)
            self.estimate.setText(self.tr("Estimated time: %1 min %2 s, %n line(s)", "",
                                          len(self.program.source_lines)).replace("%1", str(minutes))
                                  .replace("%2", str(seconds)))
        self.open_button.setEnabled(bad is None)
        self.save_button.setEnabled(bad is None)
        self.preview_updated.emit()

    def _draw_outlines(self, features) -> None:
        """The boundary of every feature's region (pockets, slots, islands) and every hole,
        in white."""
        xs, ys = [], []
        turn = np.linspace(0, 2 * np.pi, 33)
        for feature in features:
            if hasattr(feature, "region"):
                x, y = feature.region().exterior.xy
                xs += [*x, np.nan]
                ys += [*y, np.nan]
            for cx, cy in getattr(feature, "centres", ()):
                xs += [*(cx + feature.cut.radius * np.cos(turn)), np.nan]
                ys += [*(cy + feature.cut.radius * np.sin(turn)), np.nan]
        self.outline.setData(np.array(xs, float), np.array(ys, float), connect="finite")

    def _show_errors(self, bad=None) -> None:
        for form in [*self.forms.values(), self.cutting]:
            form.clear_errors()
        self.problem.clear()
        if bad is None:
            return
        row, exc = bad
        title = _tr(spec.KIND_TITLES[self.job[row]["kind"]])
        if row == self.list.currentRow():
            form = self.current_form()
            rule = localize(exc.rule)
            if form.show_error(exc.field, rule) or self.cutting.show_error(exc.field, rule):
                self.problem.setText(self.tr("Fix the marked field to see the job."))
                return
        self.problem.setText(self.tr("Feature %1 (%2): %3").replace("%1", str(row + 1))
                             .replace("%2", title).replace("%3", exc.localized()))


    # -- output -----------------------------------------------------------------------

    def open_as_program(self) -> None:
        self.refresh()
        if not self.open_button.isEnabled():
            return
        self.generated_dir.mkdir(parents=True, exist_ok=True)
        path = self.generated_dir / "features.nc"
        path.write_text(self.text, encoding="utf-8")
        self.open_program(path)
        self.accept()

    def save_as(self) -> None:
        self.refresh()
        if not self.save_button.isEnabled():
            return
        path, _ = QFileDialog.getSaveFileName(self, self.tr("Save the program"), "features.nc",
                                              self.tr("G-code (*.nc *.ngc *.gcode)"))
        if path:
            self.save_to(Path(path))

    def save_to(self, path: Path) -> None:
        """Write the job to ``path`` in the chosen dialect (plain or a Fanuc macro program)."""
        dialect = self.dialect.currentData()
        title = PROGRAM_TITLE
        text = self.text if dialect == "plain" else write_fanuc(self.moves, dialect, title)
        path.write_text(text, encoding="utf-8")
