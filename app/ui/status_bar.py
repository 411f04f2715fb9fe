"""Status bar: machine position, job progress (bar and text), elapsed and remaining."""

from __future__ import annotations

from PySide6.QtWidgets import QLabel, QProgressBar, QStatusBar

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
        self.progress_text = QLabel("no job")
        self.addPermanentWidget(self.position)
        self.addPermanentWidget(self.progress)
        self.addPermanentWidget(self.progress_text)

    def set_position(self, x: float, y: float, z: float) -> None:
        self.position.setText(f"X {x:8.3f}   Y {y:8.3f}   Z {z:8.3f}")

    def set_progress(self, view: ProgressView, label: str = "") -> None:
        self.progress.setValue(int(round(view.percent * 10)))
        self.progress.setFormat(f"{view.percent:.1f} %")
        remaining = "—" if view.remaining is None else format_duration(view.remaining)
        self.progress_text.setText(
            f"{label}line {view.done:,}/{view.total:,} · elapsed {format_duration(view.elapsed)}"
            f" · remaining {remaining}"
        )
