"""What the 3-D view follows of the window, by the window's signals.

``WindowFeed(window, view)`` listens to the loader (a program opened, or the same
one refined) and to the machine link's worker (session state, status, progress, the
end of a job), and calls the view: ``show_model``, ``set_tools``, ``begin_job``,
``set_done``, ``set_tool``, ``add_measured``. A program shows with the window's tool
table as it is then (the window applies a new table to the next program opened).

Statuses and progress are only stored when they arrive; the view hears of them at
most once per STATUS_MS (the machine's status period while it moves): at once when
the feed has been quiet that long, else when the period is over, with the newest
values. Progress comes once per executed line from the worker's thread (a direct
connection: the newest line is kept, no call crosses threads per line). The measured
path is the window's position history since the last update, taken only while a
job of the program runs (from its start to its end), each row with the last finished
line its status reported (whether it was taken in a rapid).
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Qt, QTimer, Signal

from app.comm.listener import SessionState
from app.ui.plot.history import COMMANDED, MEASURED

STATUS_MS = 50  # docs/protocol.md: a status at least every 50 ms while moving
STARTED = SessionState.STARTING.value  # a job begins (a resumed one goes on: RESUMING)


class WindowFeed(QObject):
    updated = Signal()  # the view was told of the newest status, progress and positions

    def __init__(self, window, view):
        super().__init__(view)
        self.window, self.view = window, view
        self.program = None  # the Program shown
        self.running = False  # a job of the program runs: its positions are measured
        self.updates = 0  # how often the view was told (rate-limited)
        self._tool = self._tool_shown = None
        self._done = self._done_shown = None
        self._history_version = window.history.version
        self._dirty = False
        self._row_done: list[int] = []  # the last finished line of each status since the last update
        self._limit = QTimer(self, singleShot=True, interval=STATUS_MS, timeout=self._period_over)
        window.loader.loaded.connect(self._loaded)
        window.loader.refined.connect(self._refined)
        worker = window.link.worker
        worker.state_changed.connect(self._state)
        worker.status_changed.connect(self._status)
        worker.progress_changed.connect(self._progress, Qt.ConnectionType.DirectConnection)
        worker.job_finished.connect(self._job_finished)
        view.set_tools(window.tools)
        if window.loaded is not None:
            self._loaded(window.loaded)

    # -- the program ----------------------------------------------------------------------

    def _loaded(self, loaded) -> None:
        self.program = loaded.program
        self.view.set_tools(self.window.tools)
        self.view.show_model(loaded.preview, loaded.program)

    def _refined(self, loaded) -> None:
        if loaded.program is self.program:
            self.view.show_model(loaded.preview, loaded.program, keep_camera=True)

    # -- the job ----------------------------------------------------------------------------

    def _state(self, event) -> None:
        if event.new != STARTED:
            return
        self._flush()  # what came before is not this job's
        binder = self.window.binder
        self.running = binder.job is not None and binder.job.program is self.program
        if self.running:  # (a job of the program, not an MDI line or the outline)
            self.view.begin_job()
            self._history_version = self.window.history.version
            self._done, self._done_shown = binder.job_done, None  # -1, or the line before a start
            self._schedule()  # from a line

    def _progress(self, event) -> None:
        """The worker's thread: keep the newest finished line, nothing more."""
        if event.kind == "job":
            self._done = event.done

    def _status(self, event) -> None:
        self._tool = event.position
        if self.running:  # the move each measured row was taken in: after the status's done
            self._row_done.append(event.done)
        self._schedule()

    def _job_finished(self, event) -> None:
        if event.kind == "upload" or not self.running:
            return
        if event.completed:
            self._done = event.total - 1
        self._flush()  # the job's last rows and lines
        self.running = False

    # -- at most once per STATUS_MS ----------------------------------------------------------

    def _schedule(self) -> None:
        self._dirty = True
        if not self._limit.isActive():
            self._flush()

    def _period_over(self) -> None:
        if self._dirty:
            self._flush()

    def _flush(self) -> None:
        self._dirty = False
        self._limit.start()
        self.updates += 1
        if self._tool is not None and self._tool != self._tool_shown:
            self._tool_shown = self._tool
            self.view.set_tool(*self._tool)
        done = self._done
        if self.running and done is not None and done != self._done_shown:
            self._done_shown = done
            self.view.set_done(done)
        history = self.window.history
        fresh = min(history.version - self._history_version, len(history))
        self._history_version = history.version
        row_done, self._row_done = self._row_done, []
        if self.running and fresh > 0:
            rows = history.rows()[-fresh:]
            known = row_done[-fresh:]  # (a row of no status, a gap of a lost link, takes the first's)
            first = known[0] if known else self._done_shown if self._done_shown is not None else -1
            row_done = [first] * (fresh - len(known)) + known
            self.view.add_measured(rows[:, MEASURED].copy(), rows[:, COMMANDED].copy(), row_done)
        self.updated.emit()
