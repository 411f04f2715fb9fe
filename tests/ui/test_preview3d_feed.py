"""The 3-D view follows the window by its signals (loader, worker), rate-limited to the
status period; without a GPU (the view draws nothing, its state is what is checked)."""

from __future__ import annotations

import threading
from types import SimpleNamespace

import numpy as np
import pytest
from PySide6.QtCore import QObject, Signal

from app.comm.events import JobEvent, ProgressEvent, StateEvent, StatusEvent
from app.gcode import load_text
from app.ui.plot.history import PositionHistory
from app.ui.preview.model import PreviewModel
from app.ui.preview3d.view import Preview3D
from tests.ui.test_preview3d_model import star_program
from tests.ui.test_preview3d_view import _seq_before


class FakeLoader(QObject):
    loaded = Signal(object)
    refined = Signal(object)


class FakeWorker(QObject):
    state_changed = Signal(object)
    status_changed = Signal(object)
    progress_changed = Signal(object)
    job_finished = Signal(object)


def _loaded(program):
    return SimpleNamespace(program=program, preview=PreviewModel(program.toolpath, threads=1))


@pytest.fixture
def followed(qtbot):
    tool = SimpleNamespace(diameter=6.0)
    window = SimpleNamespace(loader=FakeLoader(), link=SimpleNamespace(worker=FakeWorker()), loaded=None,
                             binder=SimpleNamespace(job=None, job_done=-1), history=PositionHistory(),
                             tools={1: tool})
    view = Preview3D(probe=lambda: "none here")
    qtbot.addWidget(view)
    view.follow(window)
    return window, view


def _status(window, measured, commanded=None, done: int = 0) -> None:
    """What the window's binder does first with a status (the history), then the signal."""
    window.history.append(0.0, measured, commanded)
    window.link.worker.status_changed.emit(StatusEvent("b", "RUN", *measured, done, done, 0, 0, "H"))


def test_a_program_shows_when_loaded_and_finer_when_refined(qtbot, followed):
    window, view = followed
    assert view.tools == window.tools and view.model is None
    program = load_text(star_program())
    first = _loaded(program)
    window.loader.loaded.emit(first)
    assert view.model is first.preview
    window.loader.refined.emit(_loaded(load_text(star_program(passes=2))))  # another program: not shown
    assert view.model is first.preview
    finer = _loaded(program)
    window.loader.refined.emit(finer)
    assert view.model is finer.preview and not view._fit_next  # the camera stays


def test_a_job_is_followed_at_the_status_rate_and_measured_only_while_it_runs(qtbot, followed):
    window, view = followed
    feed, worker = view.feed, window.link.worker
    loaded = _loaded(load_text(star_program()))
    window.loader.loaded.emit(loaded)
    view.measured.append((1, 1, 1), (1, 1, 1))  # from before: a job starts afresh
    window.binder.job = loaded  # started from a line whose next move is a cut
    window.binder.job_done = _seq_before(loaded.program, loaded.preview, rapid=False)
    worker.state_changed.emit(StateEvent("READY", "STARTING"))
    assert feed.running and len(view.measured) == 0
    told = feed.updates
    cut = window.binder.job_done
    rapid = _seq_before(loaded.program, loaded.preview, rapid=True)
    for k in range(30):  # a burst of statuses: the view hears of them once a period
        done = rapid if k == 0 else cut  # the first during a rapid (the machine said so then)
        _status(window, (60.0, 70.0 + k * 0.1, -1.0), (60.0, 70.0 + k * 0.1, -1.02), done)
    assert feed.updates == told
    with qtbot.waitSignal(feed.updated, timeout=2000):
        pass
    assert feed.updates == told + 1 and len(view.measured) == 30
    assert view.tool_at == pytest.approx((60.0, 72.9, -1.0))
    deviation = view.measured.rows()[:, 3]
    assert deviation[0] < 0  # a rapid's: none
    np.testing.assert_allclose(deviation[1:], 0.02, atol=1e-5)
    seq = len(loaded.program.device_lines) // 2
    lines = [ProgressEvent("job", 99, s, s, s) for s in range(seq + 1)]
    worker_thread = threading.Thread(  # progress comes from the worker's thread, one per line
        target=lambda: [worker.progress_changed.emit(event) for event in lines])
    worker_thread.start()
    worker_thread.join()
    _status(window, (61.0, 70.0, -1.0))
    qtbot.waitUntil(lambda: view._done_seq == seq, timeout=2000)
    total = len(loaded.program.device_lines)
    worker.job_finished.emit(JobEvent("job", True, "", total - 1, total))
    assert view._done_seq == total - 1 and not feed.running
    rows = len(view.measured)
    with qtbot.waitSignal(feed.updated, timeout=2000):
        _status(window, (0.0, 0.0, 10.0))  # after the job: the tool moves, nothing is measured
    assert view.tool_at == (0.0, 0.0, 10.0) and len(view.measured) == rows
    window.binder.job = None  # an MDI line or the outline: not the program's job
    worker.state_changed.emit(StateEvent("READY", "STARTING"))
    assert not feed.running and len(view.measured) == rows
    window.binder.job, window.binder.job_done = loaded, 4  # again, from a line
    worker.state_changed.emit(StateEvent("READY", "STARTING"))
    assert feed.running and len(view.measured) == 0
    qtbot.waitUntil(lambda: view._done_seq == 4, timeout=2000)


def test_following_a_window_with_a_program_open_shows_it(qtbot):
    program = load_text(star_program())
    window = SimpleNamespace(loader=FakeLoader(), link=SimpleNamespace(worker=FakeWorker()),
                             loaded=_loaded(program), binder=SimpleNamespace(job=None, job_done=-1),
                             history=PositionHistory(), tools={})
    view = Preview3D(probe=lambda: "none here")
    qtbot.addWidget(view)
    view.follow(window)
    assert view.model is window.loaded.preview
