"""The status bar's job figures: the time of day the job should end (issue 21)."""

from __future__ import annotations

import time

from app.ui.progress import ProgressView
from app.ui.status_bar import JobStatusBar


def test_the_end_time_of_day_is_now_plus_the_time_left(qtbot):
    bar = JobStatusBar()
    qtbot.addWidget(bar)
    now = time.mktime((2026, 11, 26, 14, 50, 30, 0, 0, -1))
    bar.clock = lambda: now
    bar.set_progress(ProgressView(4, 10, 63.0, 25 * 60.0), "", (4, 10))
    assert bar.progress_text.text() == "line 4/10 · elapsed 1:03 · remaining 25:00 · ends at 15:15"


def test_no_end_time_without_a_time_left(qtbot):
    bar = JobStatusBar()
    qtbot.addWidget(bar)
    bar.set_progress(ProgressView(10, 10, 63.0, None), "", (10, 10))
    assert bar.progress_text.text().endswith("remaining —")
    assert "ends at" not in bar.progress_text.text()
