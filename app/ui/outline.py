""""Trace outline" (issue 21): the machine traces the open job's bounding rectangle (or,
with "Convex hull", its convex hull), spindle off, at the job's top Z, so the operator
sees on the stock where it will cut.

``OutlineBox`` is the button and the option; ``trace()`` asks the state table
(``outline``), builds the short program (``app.gcode.outline``), checks it against the
travel with the machine's work offset first (the preflight's check) and runs it as a
job through the normal path, where Pause holds it and Stop ends it.
"""

from __future__ import annotations

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QCheckBox, QGroupBox, QHBoxLayout, QPushButton

from app.gcode import load_text
from app.gcode.checks import preflight
from app.gcode.outline import outline_lines
from app.i18n import localize


class OutlineBox(QGroupBox):
    """The "Trace outline" button and its "Convex hull" option (see the module docstring)."""

    def __init__(self, window) -> None:
        super().__init__()
        self.w = window
        row = QHBoxLayout(self)
        self.button = QPushButton()
        self.button.clicked.connect(self.trace)
        self.button.setEnabled(False)  # until the window's state table says otherwise
        self.hull = QCheckBox()
        row.addWidget(self.button)
        row.addWidget(self.hull)
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.setTitle(self.tr("Outline"))
        self.button.setText(self.tr("Trace outline"))
        self.button.setToolTip(self.tr("spindle off, at the job's top Z: trace where the job will cut "
                                       "(Pause holds it, Stop ends it)"))
        self.hull.setText(self.tr("Convex hull"))
        self.hull.setToolTip(self.tr("trace the convex hull of the job instead of its bounding rectangle"))

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def program_lines(self) -> list[str] | None:
        """The outline's device lines, checked against the travel; None (the operator told
        why) when there is no program, it moves nowhere, or the outline leaves the travel."""
        loaded, notifier = self.w.loaded, self.w.notifier
        if loaded is None or loaded.program.errors:
            notifier.warning(self.tr("No outline"), self.tr("Open a program without errors first."))
            return None
        try:
            lines = outline_lines(loaded.program.toolpath, float(self.w.controls.jog.feed.value()),
                                  self.hull.isChecked())
        except ValueError as exc:
            notifier.warning(self.tr("No outline"), localize(exc.args[0]))
            return None
        program = load_text("\n".join(lines), name="outline", profile=self.w.profile)
        offset = self.w.preflight.current_offset()
        errors = preflight(program.ops, self.w.profile, program.lines, offset)
        if program.errors or errors:
            first = (list(program.errors) + errors)[0]
            notifier.error(self.tr("Outline leaves the travel"), localize(first.message))
            return None
        return list(program.device_lines)

    def trace(self) -> None:
        if not self.w.operator.allowed("outline"):
            return
        lines = self.program_lines()
        if lines is None:
            return
        self.w.binder.begin_job(None)
        self.w.link.call("start_job", lines)
