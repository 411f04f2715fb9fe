"""Worker events -> widgets. Handlers only store what arrived; a ~30 Hz timer moves
the latest status and progress to the labels, the preview's tool marker and finished
part, and the source listing, so a flood of frames never floods the GUI."""

from __future__ import annotations

import threading
import time
from collections import deque

from PySide6.QtCore import QObject, Qt, QTimer

from app.comm.listener import BUSY_STATES, JOB_STATES, RECOVERY_STATES, SessionState
from app.i18n import localize
from app.ui.codes import alarm_text, refusal_text
from app.ui.commanded import commanded_position
from app.ui.numbers import decimal, fill, integer
from app.ui.program.summary import device_count
from app.ui.progress import ProgressTracker, line_times

UI_TICK_MS = 33
SLOW_EVERY = 6  # the finished part, current line and progress text: every 6th tick (~5 Hz)
BUSY = frozenset(s.value for s in BUSY_STATES)
JOB = frozenset(s.value for s in JOB_STATES)
RECOVERY = frozenset(s.value for s in RECOVERY_STATES)


class SessionBinder(QObject):
    def __init__(self, window):
        super().__init__(window)
        self.w = window
        self.status = None  # latest StatusEvent
        self.state = SessionState.DISCONNECTED.value
        self.link_state = "DISCONNECTED"
        self.connected = False
        self.job = None  # LoadedProgram being run
        self.tracker: ProgressTracker | None = None
        self.job_done = -1  # last finished device line of the job
        self.last_job_event = None  # JobEvent of the last job (not upload)
        self.last_upload_event = None
        self.alert_clock: float | None = None  # link clock when the alert last appeared
        self._dirty = False  # a status arrived since the last refresh
        self._progress_dirty = False  # progress arrived since the last slow refresh
        self._ticks = 0
        self._gui_thread = threading.get_ident()
        self._progress_in: deque = deque()  # progress events from the worker, drained by tick()
        self._connect(window.link.worker)
        window.loader.loaded.connect(window.operator.program_loaded)
        window.loader.refined.connect(window.operator.program_refined)
        window.loader.failed.connect(self.on_load_failed)
        self.timer = QTimer(self, interval=UI_TICK_MS, timeout=self.tick)
        self.timer.start()

    def _connect(self, worker) -> None:
        worker.connected.connect(self.on_connected)
        worker.connect_failed.connect(self.on_connect_failed)
        worker.disconnected.connect(self.on_disconnected)
        worker.state_changed.connect(self.on_state)
        worker.status_changed.connect(self.on_status)
        # One progress event per executed line (hundreds a second): queued one by one, each
        # would be a call into Python on the GUI thread waiting for the worker's GIL, in
        # bursts. The worker only appends to a deque here; tick() applies the latest.
        worker.progress_changed.connect(self._progress_arrived, Qt.ConnectionType.DirectConnection)
        worker.link_changed.connect(self.on_link)
        worker.alarm_raised.connect(self.on_alarm)
        worker.log_added.connect(self.on_log)
        worker.frame_logged.connect(self.on_frame)
        worker.command_finished.connect(self.on_command)
        worker.job_finished.connect(self.on_job_finished)
        worker.error_occurred.connect(self.on_error)
        worker.resume_offered.connect(self.on_resume_offer)
        worker.hold_reported.connect(self.on_hold)

    # Cross-thread signals must reach bound methods of this QObject (queued into the GUI
    # thread); a lambda would run in the emitting thread.

    def on_load_failed(self, path: str, text: str) -> None:
        self.w.status.showMessage(self.tr("Open failed"), 5000)
        self.w.notifier.error(self.tr("Cannot open file"), localize(text))

    def on_log(self, event) -> None:
        self.w.console.add_log(event.level, event.text, event.source)

    def on_frame(self, event) -> None:
        self.w.console.add_frame(event.direction, event.kind, event.text, event.ok)

    def on_error(self, event) -> None:
        if event.code == "LINK_LOST":
            self.w.console.add_log("error", localize(event.text))
            return
        self.w.notifier.error(self.tr("Link error"), f"{event.code}: {localize(event.text)}")

    # -- connection -----------------------------------------------------------------

    def on_connected(self, url: str) -> None:
        self.connected = True
        self.w.connection.set_connected(True)
        sim = self.w.link.sim
        self.w.machine_panel.set_panel(sim.panel if sim is not None and url.startswith("sim") else None)
        self.w.link.call("list_sd")
        self.refresh_enabled()

    def on_connect_failed(self, text: str) -> None:
        self.w.connection.set_connected(False)
        self.w.connection.set_link("DISCONNECTED")
        self.w.notifier.error(self.tr("Cannot connect"),
                              self.tr("The port could not be opened: %1").replace("%1", localize(text)))

    def on_disconnected(self, reason: str) -> None:
        self.connected = False
        self.w.connection.set_connected(False)
        if "operator" in reason or "shut down" in reason:
            self.w.connection.set_link("DISCONNECTED")
        else:  # the port's own words (pyserial, the OS) go to the console, not to the operator
            self.w.console.add_log("error", reason)
            self.w.connection.set_link("LOST", self.tr("the port failed; details in the console"))
            self._alert("usb", self.tr("The serial port reported an error; the details are in the console."))
        self.refresh_enabled()

    def on_link(self, event) -> None:
        self.link_state = event.state
        percent = decimal(event.resend_rate * 100, 1)
        detail = self.tr("%1 % resends").replace("%1", percent) if event.quality_warning else ""
        self.w.connection.set_link(event.state, detail)
        health = fill(self.tr("resends in the last minute: %1 % of %2 frames"), percent,
                      integer(event.sent_last_min))
        self.w.connection.link.setToolTip(health)
        self.w.status.setToolTip(health)
        self.w.console.set_resends(event.resent_last_min, event.resend_rate, event.quality_warning)
        if event.state == "LOST":
            self._alert("usb", event.reason)

    def on_hold(self, event) -> None:
        """Why the machine holds or stopped, in words with its source (status bar), until
        it runs again; the cover and program stops have their own banner and prompt."""
        if not event.why:
            self.w.status.clearMessage()
            return
        if event.why in ("COVER", "PROG"):
            return
        sources = {"host": self.tr("this computer"), "panel": self.tr("the machine's panel"),
                   "cover": self.tr("the cover"), "link": self.tr("the link"),
                   "program": self.tr("the program"), "machine": self.tr("the machine")}
        held = event.state == "HOLD"
        template = self.tr("Machine holds (%1): %2") if held else self.tr("Machine stopped (%1): %2")
        source = sources.get(event.source, event.source)
        self.w.status.showMessage(fill(template, source, localize(event.text)))

    def on_alarm(self, event) -> None:
        self.w.console.add_log("warning", f"alarm {event.code}: {event.text}", "machine")
        if event.code == "UART_LOST":
            self._alert("uart", event.text)
        elif event.code not in ("HOST_LOST", "BOOT"):
            self.w.notifier.warning(self.tr("Machine alarm"), alarm_text(event.code, event.text))

    def _alert(self, what: str, detail: str) -> None:
        if not self.w.alert.isVisible():
            self.alert_clock = self.w.link.clock()
        from_sd = self.status is not None and "S" in self.status.flags
        self.w.alert.show_lost(what, self.state in JOB or self.state in RECOVERY, from_sd, detail)

    def on_resume_offer(self, offer) -> None:
        self.w.alert.show_offer(offer.same_boot, offer.from_seq, offer.total)

    # -- state, status, progress ----------------------------------------------------

    def on_state(self, event) -> None:
        self.state = event.new
        self.w.connection.set_machine_state(self._machine_state(), self.status.flags if self.status else "")
        if event.new in JOB:
            self.w.keep_awake.start()
        elif event.new not in RECOVERY:
            self.w.keep_awake.stop()
        if event.new == "READY" and self.w.alert.isVisible() and self.link_state == "CONNECTED":
            self.w.alert.show_restored()
        self.refresh_enabled()

    def _machine_state(self) -> str:
        return self.status.state if self.status else "—"

    def on_status(self, event) -> None:
        self.status = event
        measured = event.position
        commanded = measured
        if self.job is not None and self.state in JOB:
            commanded = commanded_position(self.job.preview, event.done + 1, measured)
        self.history.append(event.time or time.monotonic(), measured, commanded)
        self._dirty = True

    @property
    def history(self):
        return self.w.history

    def _progress_arrived(self, event) -> None:
        """Runs in the emitting thread (DirectConnection): store only, no widgets."""
        if threading.get_ident() == self._gui_thread:
            self.on_progress(event)
        else:
            self._progress_in.append(event)

    def _drain_progress(self) -> None:
        """Apply the progress that arrived since the last tick: the newest event per kind
        (progress only grows, so the ones in between change nothing that is shown)."""
        latest = {}
        while self._progress_in:
            event = self._progress_in.popleft()
            latest.pop(event.kind, None)
            latest[event.kind] = event
        for event in latest.values():
            self.on_progress(event)

    def on_progress(self, event) -> None:
        if event.kind == "upload":
            self.w.sd_panel.set_progress(event.done + 1, event.total)
        elif self.tracker is not None:
            self.job_done = event.done
            self.tracker.update(event.done + 1)
            self._progress_dirty = True

    def begin_job(self, loaded, first: int = 0) -> None:
        """Called when the operator starts ``loaded``: fresh progress (None: an MDI line);
        ``first``: the device line a start-from-line run begins at."""
        self._drain_progress()
        self.job = loaded
        self.job_done = first - 1
        self.last_job_event = None
        if loaded is None:
            self.tracker = None
            return
        program = loaded.program
        count = device_count(program)
        self.tracker = ProgressTracker(line_times(program.toolpath, count), count, time.monotonic(), first)
        self.w.preview.set_done(first - 1)
        self._progress_dirty = True

    def on_job_finished(self, event) -> None:
        self._drain_progress()  # the last lines' progress before the end
        if event.kind == "upload":
            self.last_upload_event = event
            if event.completed:
                text = self.tr("saved as %1: %n line(s), verified by the card's CRC32", "", event.total)
            else:
                text = self.tr("not saved: %1").replace("%1", localize(event.reason))
            text = text.replace("%1", event.name)
            self.w.sd_panel.upload_finished(event.completed, text)
            self.w.link.call("list_sd")
            return
        self.last_job_event = event
        if self.tracker is not None and event.completed:
            self.tracker.update(event.total)
            self.job_done = event.total - 1
        self._progress_dirty = True
        self.tick()
        if event.completed:
            self.w.status.showMessage(self.tr("Job finished"), 15000)
        else:
            self.w.notifier.warning(self.tr("Job ended"), self.tr("The job did not complete: %1")
                                    .replace("%1", localize(event.reason)) + self._where_it_stopped(event))

    def _where_it_stopped(self, event) -> str:
        """Which source line the job stopped at (the refused line, else the one after the
        last finished) and how much ran (the log keeps the rest)."""
        line_map = getattr(getattr(self.job, "program", None), "line_map", None)
        nxt = event.refused if event.refused >= 0 else event.done + 1
        if line_map is None or not 0 <= nxt < len(line_map):
            return ""
        return self.tr(" (at source line %1; %2 device lines ran, see the console)").replace(
            "%1", str(int(line_map[nxt]))).replace("%2", str(event.done + 1))

    def on_command(self, result) -> None:
        if result.verb == "SD" and result.args[:1] == ("LIST",) and result.ok:
            self.w.sd_panel.set_files(result.rows)
        elif result.verb == "SD" and result.args[:1] == ("DEL",) and result.ok:
            self.w.link.call("list_sd")
        if not result.ok and result.code not in ("SUPERSEDED",) and result.verb != "PING":
            text = f"{result.verb} {' '.join(result.args)}: {result.code} {result.info}".strip()
            self.w.console.add_log("error", text, "machine")
            shown = f"{result.verb} {' '.join(result.args)}: {refusal_text(result.code, result.info)}"
            self.w.status.showMessage(shown, 10000)
            if result.verb in ("HOME", "JOG", "SD", "ZERO", "SPINDLE", "SET"):
                self.w.notifier.warning(self.tr("Machine refused"), shown)

    # -- the ~30 Hz refresh -----------------------------------------------------------

    def tick(self) -> None:
        self._ticks += 1
        self._drain_progress()
        if self._dirty and self.status is not None:
            self._dirty = False
            s = self.status
            self.w.status.set_position(s.x, s.y, s.z)
            self.w.preview.set_tool(s.x, s.y)
            self.w.connection.set_machine_state(s.state, s.flags)
            self.w.controls.set_rpm(s.rpm)
        slow_turn = self._ticks % SLOW_EVERY == 0 or self.last_job_event is not None
        if self._progress_dirty and self.tracker is not None and slow_turn:
            self._progress_dirty = False
            self.w.status.set_progress(self.tracker.view(time.monotonic()))
            self.w.preview.set_done(self.job_done)
            self._show_current_line()

    def _show_current_line(self) -> None:
        line_map = getattr(self.job.program, "line_map", None)
        seq = min(self.job_done + 1, device_count(self.job.program) - 1)
        if line_map is not None and 0 <= seq < len(line_map):
            self.w.program_panel.show_device_line(self.job.program, seq)

    def refresh_enabled(self) -> None:
        busy = self.state in BUSY
        paused = self.state == "PAUSED" or (self.status is not None and self.status.state == "HOLD")
        has_program = self.w.loaded is not None
        preflight = getattr(self.w, "preflight", None)
        startable = has_program and not (preflight is not None and preflight.blocks_start())
        self.w.controls.set_state(self.connected, busy, paused, startable)
        self.w.sd_panel.set_enabled(self.connected, has_program, busy)
