"""What the 3-D view follows of the window, read at its own refresh (no Qt).

The window already keeps everything the view needs: the open program
(``window.loaded``), the tool table (``window.tools``), the job being run and its progress (``binder.job``,
``binder.job_done``, ``binder.last_job_event`` until it ends), the latest status
(``binder.status``) and the position history the diagnostics plot draws (rows of
measured and commanded positions, ``app.ui.plot.history``). ``WindowFeed.poll()``
reads them and says what changed since the last call; it costs a few comparisons
when nothing did, so the view can poll it at 30 Hz without hooks in the window's
wiring. Rows of the history are taken only while a job of a program runs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from app.ui.plot.history import COMMANDED, MEASURED


@dataclass
class FeedChange:
    loaded: object = None  # a LoadedProgram newly open (or refined), else None
    same_program: bool = False  # ``loaded`` draws the program already shown (finer)
    job_started: bool = False
    done_seq: int | None = None  # the job's last finished device line, when it changed
    tool: tuple[float, float, float] | None = None  # the machine's position, when it changed
    measured: np.ndarray | None = None  # (k, 3) new measured positions of the job
    commanded: np.ndarray | None = None  # (k, 3) the commanded position of each
    tools: dict | None = None  # the tool table, when the window has a new one


class WindowFeed:
    def __init__(self, window):
        self.window = window
        self._loaded = None
        self._job_key = None  # (job, running) last seen
        self._done = None
        self._status = None
        self._history_version = window.history.version
        self._tools = None

    def poll(self) -> FeedChange:
        change = FeedChange()
        self._poll_program(change)
        tools = getattr(self.window, "tools", None)
        if tools is not self._tools:
            self._tools = change.tools = tools if tools is not None else {}
        binder = getattr(self.window, "binder", None)
        if binder is None:
            return change
        running = binder.job is not None and binder.last_job_event is None
        key = (id(binder.job), running)
        if running and key != self._job_key:
            change.job_started = True
        self._job_key = key
        if binder.job is not None and binder.job_done != self._done:
            self._done = change.done_seq = binder.job_done
        status = binder.status
        if status is not None and status is not self._status:
            self._status = status
            change.tool = (status.x, status.y, status.z)
        self._poll_history(change, running)
        return change

    def _poll_program(self, change: FeedChange) -> None:
        loaded = self.window.loaded
        if loaded is self._loaded:
            return
        previous, self._loaded = self._loaded, loaded
        change.loaded = loaded
        change.same_program = None not in (previous, loaded) and previous.program is loaded.program

    def _poll_history(self, change: FeedChange, running: bool) -> None:
        history = self.window.history
        fresh = min(history.version - self._history_version, len(history))
        self._history_version = history.version
        if running and fresh > 0:
            rows = history.rows()[-fresh:]
            change.measured = rows[:, MEASURED].copy()
            change.commanded = rows[:, COMMANDED].copy()
