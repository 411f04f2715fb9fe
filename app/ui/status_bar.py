"""Status bar: machine position, job progress (bar and text), elapsed and remaining, and
the time of day the job should end."""

from __future__ import annotations

import time

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QLabel, QProgressBar, QStatusBar

from app.ui.numbers import decimal, fill, integer
from app.ui.program.summary import format_duration
from app.ui.progress import ProgressView


class JobStatusBar(QStatusBar):
    def __init__(self, parent=None):
        super().__init__(parent)
        self.position = QLabel("X — Y — Z —")
        self.position.setMinimumWidth(260)
        self.progress = QProgressBar()
        self.progress.setMaximumWidth(220)
        self.progress.setRange(0, 1000)
        self.progress.setFormat("%p %")
        self.progress_text = QLabel()
        self.addPermanentWidget(self.position)
        self.addPermanentWidget(self.progress)
        self.addPermanentWidget(self.progress_text)
        self._shown: tuple | None = None  # the last progress (view, label)
        self._position: tuple | None = None
        self.clock = time.time  # seconds since the epoch: the end time of day is now + remaining
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.position.setToolTip(self.tr("machine position in work coordinates (mm)"))
        if self._shown is None:
            self.progress_text.setText(self.tr("no job"))
        else:
            self.set_progress(*self._shown)
        if self._position is not None:
            self.set_position(*self._position)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def set_position(self, x: float, y: float, z: float) -> None:
        self._position = (x, y, z)
        shown = (f"{axis} {decimal(value, 3):>8}" for axis, value in zip("XYZ", (x, y, z), strict=True))
        self.position.setText("   ".join(shown))

    def set_progress(self, view: ProgressView, label: str = "", line: tuple[int, int] | None = None) -> None:
        """``view``'s percent and times; ``line``: (current line, lines) of the file the operator
        opened (source lines; an SD file's own lines), else the view's counts."""
        self._shown = (view, label, line)
        self.progress.setValue(int(round(view.percent * 10)))
        self.progress.setFormat(f"{decimal(view.percent, 1)} %")
        current, lines = line if line is not None else (view.done, view.total)
        figures = [integer(current), integer(lines), format_duration(view.elapsed)]
        if view.remaining is None:
            text = self.tr("line %1/%2 · elapsed %3 · remaining %4")
            figures.append("—")
        else:
            text = self.tr("line %1/%2 · elapsed %3 · remaining %4 · ends at %5")
            ends = time.strftime("%H:%M", time.localtime(self.clock() + view.remaining))
            figures += [format_duration(view.remaining), ends]
        self.progress_text.setText(label + fill(text, *figures))

    def clear_progress(self) -> None:
        """No job: no figures of an earlier one stay."""
        self._shown = None
        self.progress.setValue(0)
        self.progress.setFormat("%p %")
        self.progress_text.setText(self.tr("no job"))
