"""The live modal state while a job runs: the active G-codes, the programmed and actual
feed, the commanded and measured spindle speed, the tool, the current source line and
the subprogram and loop pass. ``app/ui/live_state.py`` feeds it; no job: dashes, or
the modal state the machine itself last reported (``show_machine``: GRBL's ``$G``)."""

from __future__ import annotations

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QFormLayout, QLabel, QWidget

from app.ui.live_modal import ModalView
from app.ui.numbers import decimal, fill, integer

NONE = "—"
ROWS = ("codes", "feed", "spindle", "tool", "line", "context", "g92")


class LivePanel(QWidget):
    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.form = QFormLayout(self)
        self.machine_view: ModalView | None = None  # what the machine reported, shown between jobs
        self.values = {key: QLabel(NONE) for key in ROWS}
        self.labels = {key: QLabel() for key in ROWS}
        for key in ROWS:
            self.form.addRow(self.labels[key], self.values[key])
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        names = {
            "codes": self.tr("Active G-codes"),
            "feed": self.tr("Feed (programmed / actual)"),
            "spindle": self.tr("Spindle (commanded / measured)"),
            "tool": self.tr("Tool"),
            "line": self.tr("Source line"),
            "context": self.tr("Subprogram / loop pass"),
            "g92": self.tr("G92 offset"),
        }
        for key, label in self.labels.items():
            label.setText(names[key])

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def clear(self) -> None:
        for value in self.values.values():
            value.setText(NONE)
        if self.machine_view is not None:
            self._show_codes(self.machine_view)

    def show_machine(self, view: ModalView | None) -> None:
        """The modal state the machine reported (None: forget it), shown while no job runs."""
        self.machine_view = view
        self.clear()

    def _show_codes(self, view: ModalView) -> None:
        codes = view.codes
        self.values["codes"].setText(" ".join(codes[g] or NONE for g in (
            "motion", "plane", "units", "distance", "wcs", "compensation")))
        self.values["feed"].setText(f"{NONE if view.feed is None else decimal(view.feed, 1)} / {NONE}")
        speed = NONE if view.speed is None else integer(round(view.speed))
        self.values["spindle"].setText(f"{speed} / {NONE}")
        self.values["tool"].setText(fill(self.tr("T%1"), view.tool) if view.tool else NONE)
        self.values["g92"].setText(view.g92 or self.tr("not in force"))

    def show_state(self, view: ModalView, actual_feed: float | None, measured_rpm: int,
                   line: int, lines: int, context: tuple[str, int]) -> None:
        self._show_codes(view)
        programmed = NONE if view.feed is None else decimal(view.feed, 1)
        actual = NONE if actual_feed is None else decimal(actual_feed, 1)
        self.values["feed"].setText(f"{programmed} / {actual}")
        commanded = NONE if view.speed is None else integer(round(view.speed))
        self.values["spindle"].setText(f"{commanded} / {integer(measured_rpm)}")
        self.values["line"].setText(fill(self.tr("%1 of %2"), integer(line), integer(lines)))
        name, loop_pass = context
        where = name or self.tr("main program")
        self.values["context"].setText(fill(self.tr("%1, pass %2"), where, loop_pass) if loop_pass else where)
