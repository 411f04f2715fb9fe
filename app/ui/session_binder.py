"""Worker events -> widgets. Handlers only store what arrived; a ~30 Hz timer moves
the latest status and progress to the labels, the preview's tool marker and finished
part, and the source listing, so a flood of frames never floods the GUI. Progress, the
log and the console's traffic (a line each way per GRBL line when the console shows the
stream) are taken where the worker emits them and applied by that timer in batches: no
call per line is queued into the GUI thread."""

from __future__ import annotations

import threading
import time
from collections import deque

import numpy as np
from PySide6.QtCore import QObject, Qt, QTimer

from app.comm.listener import BUSY_STATES, JOB_STATES, RECOVERY_STATES, SessionState
from app.i18n import localize
from app.ui.codes import alarm_text, refusal_text
from app.ui.commanded import SpindleTrack, commanded_position
from app.ui.numbers import decimal, fill, integer
from app.ui.program.summary import device_count
from app.ui.progress import ProgressTracker, line_times
from app.ui.state_table import Inputs, link_of, machine_of

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
        self.offer_answered = False  # the operator answered the alert's offer (until a new cut-off)
        self._dirty = False  # a status arrived since the last refresh
        self._progress_dirty = False  # progress arrived since the last slow refresh
        self._ticks = 0
        self._status_key = None  # (state, flags) of the last status
        self._gui_thread = threading.get_ident()
        self._progress_in: deque = deque()  # progress events from the worker, drained by tick()
        self._console_in: deque = deque()  # ("log" | "frame", event) in arrival order, drained by tick()
        self.sd_job: str | None = None  # the card file the machine runs (its progress comes in S)
        self.sd_name = ""  # the card file of the last SD run (its figures stay labelled after it)
        self._sd_seen = False  # a status of the SD run has arrived
        self._second = -1  # the whole second of the clock last shown (the timer ticks each second)
        self.pending_motion: str | None = None  # HOME, JOG or SPINDLE sent, its answer not yet in
        self.spindle_asked: float | None = None  # the speed of the last spindle command (0: off)
        self.spindle_track: SpindleTrack | None = None  # the running job's commanded speeds
        self.applied: Inputs | None = None  # the state table's inputs last applied
        self._connect(window.link.worker)
        window.loader.loaded.connect(window.operator.program_loaded)
        window.loader.refined.connect(window.operator.program_refined)
        window.loader.checked.connect(window.operator.program_updated)
        window.loader.prepared.connect(window.operator.program_updated)
        window.loader.failed.connect(self.on_load_failed)
        self.timer = QTimer(self, interval=UI_TICK_MS, timeout=self.tick)
        self.timer.start()

    def _connect(self, worker) -> None:
        worker.connected.connect(self.on_connected)
        worker.machine_info_changed.connect(self.on_machine_info)
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
        worker.log_added.connect(self._log_arrived, Qt.ConnectionType.DirectConnection)
        worker.frame_logged.connect(self._frame_arrived, Qt.ConnectionType.DirectConnection)
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

    def _log_arrived(self, event) -> None:
        """Runs in the emitting thread (DirectConnection): store only, no widgets."""
        self._console_in.append((self.on_log, event))

    def _frame_arrived(self, event) -> None:
        self._console_in.append((self.on_frame, event))

    def _drain_console(self) -> None:
        """The log lines and traffic that arrived since the last tick, in their order."""
        for _ in range(len(self._console_in)):
            show, event = self._console_in.popleft()
            show(event)

    def on_error(self, event) -> None:
        if event.code == "LINK_LOST":
            self.w.console.add_log("error", localize(event.text))
            return
        if event.code == "MACHINE_RESET" and (self.w.alert.isVisible() or self.state in RECOVERY):
            self.w.console.add_log("error", localize(event.text))  # the alert's offer says it: no second box
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

    def on_machine_info(self, info) -> None:
        """A GRBL machine's welcome and ``$I`` (the machine's own text, shown as it is)."""
        name = "grblHAL" if info.flavour == "grblhal" else "Grbl"
        build = info.build.split(":")[0] if info.build else ""
        self.w.connection.set_machine_info(f"{name} {info.version}" + (f" · {build}" if build else ""))

    def on_connect_failed(self, text: str) -> None:
        self.w.connection.set_connected(False)
        self.w.connection.set_link("DISCONNECTED")
        self.w.notifier.error(self.tr("Cannot connect"),
                              self.tr("The port could not be opened: %1").replace("%1", localize(text)))

    def on_disconnected(self, reason: str) -> None:
        self.connected = False
        self.history.break_line()
        self.pending_motion = None
        self.w.connection.set_connected(False)
        if "operator" in reason or "shut down" in reason:
            self.w.connection.set_link("DISCONNECTED")
        else:  # the port's own words (pyserial, the OS) go to the console, not to the operator
            self.w.console.add_log("error", reason)
            self.w.connection.set_link("LOST", self.tr("the port failed; details in the console"))
            self._alert("port", "")
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
            self.history.break_line()
            self._alert("silence", event.reason)
        self.refresh_enabled(force=False)

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
        elif event.code not in ("HOST_LOST", "BOOT") and not event.code.startswith("ALARM:"):  # GRBL: banner
            self.w.notifier.warning(self.tr("Machine alarm"), alarm_text(event.code, event.text))

    def _alert(self, what: str, detail: str) -> None:
        self.offer_answered = False
        if not self.w.alert.isVisible():
            self.alert_clock = self.w.link.clock()
        from_sd = self.status is not None and "S" in self.status.flags
        last = self.w.connection.state.text() if self.status is not None else ""
        grbl = getattr(self.w.link.capabilities, "driver", "frame") == "grbl"  # no heartbeat, no host watch
        what = "report_silence" if grbl and what == "silence" else what
        self.w.alert.show_lost(what, self.state in JOB or self.state in RECOVERY, from_sd, detail, last,
                               host_watch=not grbl)
        self.refresh_enabled(force=False)

    def on_resume_offer(self, offer) -> None:
        if self.offer_answered:  # an offer already on its way when the operator answered
            return
        line, lines = self.source_line(offer.from_seq), self.source_total()
        if not self.w.link.capabilities.exact_resume:  # GRBL: Start here, whatever happened
            self.w.alert.show_restart_offer(line, lines, offer.needs_home)
        else:  # the same boot resumes exactly; after a reset: home, restart at the line
            self.w.alert.show_offer(offer.same_boot, line, lines)
        self.refresh_enabled(force=False)

    def source_line(self, seq: int) -> int:
        """The 1-based source line of the job's device line ``seq`` (the last for one past the end)."""
        line_map = getattr(getattr(self.job, "program", None), "line_map", None)
        if line_map is None or not len(line_map):
            return seq + 1
        return int(line_map[min(max(seq, 0), len(line_map) - 1)])

    def source_total(self) -> int:
        program = getattr(self.job, "program", None)
        return len(program.lines) if program is not None else 0

    # -- state, status, progress ----------------------------------------------------

    def on_state(self, event) -> None:
        if event.new in RECOVERY and self.state not in RECOVERY:
            self.offer_answered = False  # a new cut-off: its offers are shown
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
        if self.tracker is not None and event.overrides is not None:
            self.tracker.set_feed(event.overrides[0] / 100.0, time.monotonic())
        measured = event.position
        commanded = measured
        if self.job is not None and self.state in JOB:
            commanded = commanded_position(self.job.preview, event.done + 1, measured)
        self.history.append(event.time or time.monotonic(), measured, commanded)
        self._dirty = True
        if self.sd_job is not None:
            self._sd_status(event)
        elif "S" in event.flags and self.state == "READY" and not self._sd_seen:
            self._sd_seen = True  # a card run started on the machine's own panel: no stale figures
            self.job, self.tracker, self.sd_name = None, None, ""
            self.w.status.clear_progress()
        elif "S" not in event.flags:
            self._sd_seen = self.sd_job is not None and self._sd_seen
        if self.applied is not None and (event.state, event.flags) != self._status_key:
            self.refresh_enabled(force=False)
        self._status_key = (event.state, event.flags)

    def _sd_status(self, event) -> None:
        """An SD run's progress is the status's ``done``; it ends when the flag S goes."""
        if "S" in event.flags:
            self._sd_seen = True
            if self.tracker is not None:
                self.tracker.update(event.done + 1)
            self._progress_dirty = True
        elif self._sd_seen and event.state == "IDLE":
            if self.tracker is not None:
                self.tracker.finish(time.monotonic(), self.tracker.done >= self.tracker.total)
            self.sd_job, self._sd_seen = None, False
            self._progress_dirty = True

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

    def begin_sd_job(self, name: str, lines: int) -> None:
        """The machine runs ``name`` (``lines`` lines, as the card lists it) from its card:
        its own progress, by lines of that file (no estimate of its time is known here)."""
        self._drain_progress()
        self.job, self.sd_job, self.sd_name, self._sd_seen = None, name, name, False
        self.job_done, self.last_job_event = -1, None
        per_line = np.arange(1.0, lines + 1.0)  # no estimate of the file's time: lines count alike
        self.tracker = ProgressTracker(per_line, lines, time.monotonic()) if lines else None
        self.w.status.clear_progress()
        self._progress_dirty = True

    def begin_job(self, loaded, first: int = 0) -> None:
        """Called when the operator starts ``loaded``: fresh progress (None: an MDI line);
        ``first``: the device line a start-from-line run begins at."""
        self._drain_progress()
        self.job, self.sd_job, self.sd_name = loaded, None, ""
        self.job_done = first - 1
        self.last_job_event = None
        if loaded is None:
            self.tracker = None
            self.w.status.clear_progress()
            return
        program = loaded.program
        count = device_count(program)
        self.spindle_track = SpindleTrack(lambda: program.device_lines)
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
        if self.tracker is not None:
            self.tracker.finish(time.monotonic(), event.completed)
        self._progress_dirty = True
        self.tick()
        if event.completed:
            self.w.status.showMessage(self.tr("Job finished"), 15000)
        else:
            why = self._refused_line(event)
            where = "" if why else self._where_it_stopped(event)
            self.w.notifier.warning(self.tr("Job ended"), self.tr("The job did not complete: %1")
                                    .replace("%1", why or localize(event.reason)) + where)

    def _refused_line(self, event) -> str:
        """A refused line named by its source line with the refusal in words ("" when the
        job ended otherwise): the session's reason names the machine's line, kept for the
        console."""
        args = getattr(event.reason, "args", None)
        if event.refused < 0 or not isinstance(args, dict) or "code" not in args:
            return ""
        text = str(args.get("text", ""))
        first, _, rest = text.partition(" ")
        said = refusal_text(args["code"], rest if first.isdigit() else text)
        line = self.source_line(event.refused)
        return self.tr("line %1 was refused: %2").replace("%1", str(line)).replace("%2", said)

    def _where_it_stopped(self, event) -> str:
        """Which source line the job stopped at (the refused line, else the one after the
        last finished) and how much ran (the log keeps the rest)."""
        line_map = getattr(getattr(self.job, "program", None), "line_map", None)
        nxt = event.refused if event.refused >= 0 else event.done + 1
        if line_map is None or not 0 <= nxt < len(line_map):
            return ""
        return self.tr(" (at line %1; the console has the details)").replace("%1", str(int(line_map[nxt])))

    def on_command(self, result) -> None:
        if result.verb == self.pending_motion:
            self.pending_motion = None
            self.refresh_enabled()
        if result.verb == "SD" and result.args[:1] == ("LIST",) and result.ok:
            self.w.sd_panel.set_files(result.rows)
        elif result.verb == "SD" and result.args[:1] == ("DEL",) and result.ok:
            self.w.link.call("list_sd")
        if not result.ok and result.code not in ("SUPERSEDED",) and result.verb != "PING":
            command = " ".join((result.verb, *result.args))
            text = f"{command}: {result.code} {result.info}".strip()
            self.w.console.add_log("error", text, "machine")
            shown = f"{command}: {refusal_text(result.code, result.info)}"
            self.w.status.showMessage(shown, 10000)
            lacks = result.code == "UNSUPPORTED"  # what a GRBL machine has not: logged, no box
            if result.verb in ("HOME", "JOG", "SD", "ZERO", "SPINDLE", "SET") and not lacks:
                self.w.notifier.warning(self.tr("Machine refused"), shown)

    # -- the ~30 Hz refresh -----------------------------------------------------------

    def tick(self) -> None:
        self._ticks += 1
        self._drain_console()
        self._drain_progress()
        if self._dirty and self.status is not None:
            self._dirty = False
            s = self.status
            self.w.status.set_position(s.x, s.y, s.z)
            self.w.preview.set_tool(s.x, s.y)
            self.w.connection.set_machine_state(s.state, s.flags)
            self.w.controls.set_rpm(s.rpm, self.commanded_rpm())
            self.w.controls.overrides.show_machine(s.overrides)
        now = time.monotonic()
        if self.tracker is not None and self.tracker.ended is None and int(now) != self._second:
            self._second = int(now)  # the elapsed and remaining time tick every second
            self._progress_dirty = True
        slow_turn = self._ticks % SLOW_EVERY == 0 or self.last_job_event is not None
        if self._progress_dirty and self.tracker is not None and slow_turn:
            self._progress_dirty = False
            self._show_progress(now)
        if slow_turn:
            self.refresh_enabled(force=False)  # dialogs that opened or closed

    def _show_progress(self, now: float) -> None:
        view = self.tracker.view(now)
        if self.sd_name or self.job is None:
            label = self.tr("SD %1 · ").replace("%1", self.sd_name) if self.sd_name else ""
            self.w.status.set_progress(view, label)
            return
        current = self.source_line(min(self.job_done + 1, view.total - 1))
        self.w.status.set_progress(view, "", (current, self.source_total()))
        self.w.preview.set_done(self.job_done)
        self._show_current_line()

    def commanded_rpm(self) -> float | None:
        """The speed commanded now: the job's spindle line in force, else the last
        spindle command sent (None until one was)."""
        if self.spindle_track is not None and self.state in JOB:
            return self.spindle_track.at(self.job_done + 1)
        return self.spindle_asked

    def _show_current_line(self) -> None:
        line_map = getattr(self.job.program, "line_map", None)
        seq = min(self.job_done + 1, device_count(self.job.program) - 1)
        if line_map is not None and 0 <= seq < len(line_map):
            self.w.program_panel.show_device_line(self.job.program, seq)

    def inputs(self) -> Inputs:
        """The state table's inputs now (``app/ui/state_table.py``)."""
        s, w = self.status, self.w
        status_state = s.state if s is not None else None
        check = w.controls.check_mode.isChecked()
        start_here = getattr(w, "start_here", None)
        dialog = w.alert.isVisible() or (start_here is not None and start_here.pending is not None)
        preflight = getattr(w, "preflight", None)
        runnable = (w.loaded is not None and not list(w.loaded.program.errors)
                    and not (preflight is not None and preflight.blocks_start()))
        return Inputs(link_of(self.connected, self.state, self.link_state, s is not None),
                      machine_of(self.state, status_state, s.flags if s is not None else "", check,
                                 self.pending_motion),
                      s is not None and s.homed, dialog, runnable, w.link.capabilities,
                      w.machine_panel.panel is not None)

    def refresh_enabled(self, force: bool = True) -> None:
        """Apply the state table (``force``: even if its inputs did not change)."""
        if not hasattr(self.w, "actions_by_name"):
            return  # the window is still being built
        inputs = self.inputs()
        if force or inputs != self.applied:
            from app.ui.enabler import apply

            self.applied = inputs
            apply(self.w, inputs)
