"""Program stops in the window: the prompt, the optional-stop switch, the job settings.

``ProgramStops`` shows ``StopPrompt`` when the worker reports a stop of a streamed job,
or the machine's ``L STOP`` notice of an SD run (Continue -> ``RESUME``, Stop job ->
``STOP``), and closes it once the job goes on or ends by other means (the status no
longer shows ``W``). The "Optional stop" checkbox and the profile's ``job`` section
(optional stop, spindle at stops, after the job) are pushed to the machine with ``SET``
on connect and on change; the checkbox is saved with the settings.
"""

from __future__ import annotations

import time
from dataclasses import replace

from PySide6.QtCore import QObject

from app.comm.stops import stop_event
from app.ui.settings.store import FILE_NAME, save_settings
from app.ui.stop_prompt import StopPrompt, tool_diameter


class ProgramStops(QObject):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.prompt = StopPrompt(window)
        self.events: list = []  # every stop reported, in order
        worker = window.link.worker
        worker.program_stopped.connect(self.on_stop)
        worker.log_added.connect(self.on_machine_log)
        worker.status_changed.connect(self.on_status)
        worker.state_changed.connect(self.on_state)
        worker.connected.connect(self.on_connected)
        self.prompt.continue_requested.connect(window.operator.resume)
        self.prompt.stop_requested.connect(window.operator.stop)
        box = window.controls.optional_stop
        box.setChecked(bool(window.profile.job.optional_stop))
        box.toggled.connect(self.set_optional_stop)

    def on_stop(self, event, sd_run: bool = False) -> None:
        self.events.append(event)
        diameter = tool_diameter(event.tool, self.w.config_dir)
        line = event.index + 1 if sd_run else self._source_line(event.index)
        self.prompt.show_stop(event, line, diameter)
        self.w.status.showMessage(self.tr("Program stop at %1: waiting for the operator").replace(
            "%1", event.line))

    def on_machine_log(self, event) -> None:
        """An SD run's stop (``L STOP <seq> <line>``; a streamed job's comes as ``on_stop``):
        the same prompt, naming the line of the SD file."""
        words = event.text.split(" ", 2)
        status = self.w.binder.status
        if event.source != "machine" or words[0] != "STOP" or len(words) < 3 or not words[1].isdigit():
            return
        if status is not None and "S" in status.flags:
            self.on_stop(stop_event(int(words[1]), words[2]), sd_run=True)

    def _source_line(self, index: int) -> int:
        loaded = self.w.binder.job or self.w.loaded
        line_map = getattr(getattr(loaded, "program", None), "line_map", None)
        if line_map is None or not 0 <= index < len(line_map):
            return index + 1
        return int(line_map[index])

    def on_state(self, event) -> None:
        """Close the prompt once the job goes on or ends; held time is not motion."""
        tracker = self.w.binder.tracker
        if event.new == "PAUSED":
            if tracker is not None:
                tracker.hold(time.monotonic())
            return
        self.prompt.dismiss()
        if tracker is not None:
            tracker.release(time.monotonic())

    def on_status(self, event) -> None:
        if "W" not in event.flags and self.prompt.isVisible():
            self.prompt.dismiss()

    def on_connected(self, url: str) -> None:
        job = self.w.profile.job
        for name, value in (("OPTSTOP", job.optional_stop), ("STOPSPINDLE", job.stop_spindle),
                            ("AFTERJOB", job.after_job)):
            self.w.link.call("send_command", f"SET {name} {value}")

    def set_optional_stop(self, on: bool) -> None:
        self.w.profile = replace(self.w.profile, job=replace(self.w.profile.job, optional_stop=int(on)))
        if self.w.binder.connected:
            self.w.link.call("send_command", f"SET OPTSTOP {int(on)}")
        try:
            save_settings(self.w.config_dir / FILE_NAME, self.w.profile)
        except OSError as exc:
            self.w.notifier.error(self.tr("Settings not saved"), str(exc))
