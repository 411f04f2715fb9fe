"""The remaining time follows the feed override (issue 21), without Qt."""

from __future__ import annotations

import numpy as np
import pytest

from app.ui.progress import ProgressTracker

SECONDS_PER_LINE = 1.0


def tracker() -> ProgressTracker:
    return ProgressTracker(np.cumsum(np.full(100, SECONDS_PER_LINE)), 100, started=0.0)


def test_a_feed_override_scales_the_remaining_time_at_once():
    t = tracker()
    t.update(50)
    assert t.view(50.0).remaining == pytest.approx(50.0)
    t.set_feed(0.5, 50.0)
    assert t.view(50.0).remaining == pytest.approx(100.0)
    t.set_feed(2.0, 50.0)
    assert t.view(50.0).remaining == pytest.approx(25.0)


def test_time_run_under_an_override_does_not_skew_the_measured_rate():
    t = tracker()
    t.update(50)
    t.set_feed(0.5, 50.0)
    t.update(60)  # ten lines in twenty seconds at half feed: exactly as estimated
    assert t.view(70.0).remaining == pytest.approx(40.0 / 0.5)
    t.set_feed(1.0, 70.0)
    assert t.view(70.0).remaining == pytest.approx(40.0)


def test_a_hold_under_an_override_counts_no_motion():
    t = tracker()
    t.update(50)
    t.set_feed(0.5, 50.0)
    t.hold(50.0)
    t.release(80.0)
    assert t.view(80.0).remaining == pytest.approx(100.0)
    assert t.view(80.0).elapsed == pytest.approx(80.0)
