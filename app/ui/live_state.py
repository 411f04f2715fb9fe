"""Feeds the live modal state panel from each status while a job of an opened program
runs (an MDI line or an SD run has no source here: the panel shows dashes): the
machine's ``done`` seq gives the source line (``binder.source_line``), the subprogram
and pass (``Program.context_at``) and, through ``ModalTracker``, what is in force."""

from __future__ import annotations

from PySide6.QtCore import QObject

from app.ui.live_modal import ModalTracker, actual_feed
from app.ui.live_panel import LivePanel
from app.ui.session_binder import JOB


class LiveState(QObject):
    def __init__(self, window, panel: LivePanel) -> None:
        super().__init__(window)
        self.w, self.panel = window, panel
        self.tracker: ModalTracker | None = None
        self._job = None
        self._previous = None
        window.link.worker.status_changed.connect(self.on_status)

    def on_status(self, event) -> None:
        binder = self.w.binder
        loaded = binder.job
        if loaded is None or binder.state not in JOB or binder.sd_job is not None:
            if self._job is not None:
                self._job, self.tracker, self._previous = None, None, None
                self.panel.clear()
            return
        program = loaded.program
        if loaded is not self._job:
            self._job, self.tracker = loaded, ModalTracker(program.lines)
        line = binder.source_line(event.done + 1)  # the line under way: the one after the last done
        view = self.tracker.advance_to(line)
        feed = actual_feed(self._previous, event)
        self._previous = event
        context = program.context_at(event.done + 1)
        self.panel.show_state(view, feed, event.rpm, line, len(program.lines), context)
