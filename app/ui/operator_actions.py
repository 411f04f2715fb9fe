"""What the operator asks for, turned into worker calls (every call returns at once).

Every request first asks the window's state table (``allowed``): one the table forbids
now (a stale click, a shortcut, an MDI line) is refused with the reason in the status
bar and the console, never sent or queued. Checks that need no machine are made here
too so the message is immediate and clear: no program open, a program with errors, a
bad SD name, not homed.
"""

from __future__ import annotations

import gc

from PySide6.QtCore import QCoreApplication, QObject

from app.gcode.checks import preflight
from app.i18n import localize
from app.ui.enabler import reason_text
from app.ui.machine_start import MachineStart
from app.ui.mdi import classify
from app.ui.missing_tool import MissingTool
from app.ui.numbers import decimal, fill, integer
from app.ui.program.summary import device_count
from app.ui.recent import add_recent
from app.ui.settings.dialog import SettingsDialog
from app.ui.settings.store import FILE_NAME, machine_settings, save_settings
from app.ui.state_table import LABELS, OVERRIDE_CONTROLS, decide


class OperatorActions(QObject):
    def __init__(self, window):
        super().__init__(window)
        self.w = window
        self.link = window.link
        self.refused: list[tuple[str, str]] = []  # (control, reason) of every refusal, for tests
        self.machine_start = MachineStart(window)  # jobs read from where the machine stands
        self.missing_tool = MissingTool(window)  # the tool table offered from "tool not found"
        self._connect_widgets()

    def _connect_widgets(self) -> None:
        w, c = self.w, self.w.controls
        w.connection.connect_requested.connect(self.connect_to)
        w.connection.disconnect_requested.connect(self.disconnect)
        c.home_requested.connect(self.home)
        c.start_requested.connect(self.start)
        c.pause_requested.connect(self.pause)
        c.resume_requested.connect(self.resume)
        c.stop_requested.connect(self.stop)
        c.spindle_requested.connect(self.spindle)
        c.overrides.override_requested.connect(self.override)
        c.zero_requested.connect(self.zero)
        c.check_mode_toggled.connect(self.set_check_mode)
        c.jog.jog_requested.connect(self.jog)
        c.jog.hold_changed.connect(self.jog_hold)
        c.jog.step_group.idToggled.connect(lambda *_: self.w.binder.refresh_enabled())
        w.sd_panel.upload_requested.connect(self.upload)
        w.sd_panel.list_requested.connect(lambda: self._send("sd_list", "list_sd"))
        w.sd_panel.delete_requested.connect(lambda name: self._send("sd_delete", "delete_sd", name))
        w.sd_panel.run_requested.connect(self.run_from_sd)
        w.console.mdi_submitted.connect(self.mdi)
        w.console.show_stream.toggled.connect(lambda on: self.link.call("set_verbose_frames", on))
        w.alert.reconnect_requested.connect(self.reconnect)
        w.alert.resume_requested.connect(self.resume_after_reconnect)
        w.alert.restart_requested.connect(self.restart_after_reset)
        w.alert.abandon_requested.connect(self.abandon)
        w.program_panel.line_activated.connect(self.show_source_line)

    def allowed(self, control: str) -> bool:
        """Whether the state table allows ``control`` now; if not, the operator is told why."""
        verdict = decide(control, self.w.binder.inputs())
        if not verdict.allowed:
            label = QCoreApplication.translate("StateTable", LABELS[control])
            text = self.tr("%1 refused: %2").replace("%1", label).replace("%2", reason_text(verdict))
            self.w.status.showMessage(text, 10000)
            self.w.console.add_log("warning", text)
            self.refused.append((control, verdict.reason))
        return verdict.allowed

    def _send(self, control: str, verb: str, *args) -> bool:
        """Call the worker's ``verb`` if the table allows ``control`` now."""
        if not self.allowed(control):
            return False
        self.link.call(verb, *args)
        return True

    # -- connection -----------------------------------------------------------------

    def connect_to(self, url: str, baud: int = 115200) -> None:
        self.w.connection.set_link("CONNECTING")
        self.link.connect_to(url, self.w.connection.driver_choice())

    def disconnect(self) -> None:
        self.link.call("disconnect_from")

    def reconnect(self) -> None:
        self.w.alert.say(self.tr("Reconnecting…"))
        self.link.connect_to(self.link.url)

    # -- job ------------------------------------------------------------------------

    def home(self, mode: str = "NORMAL") -> None:
        if self._send("home_recover" if mode == "RECOVER" else "home", "home", mode):
            self._motion_sent("HOME")

    def _motion_sent(self, verb: str) -> None:
        """Until its answer, a HOME, JOG or SPINDLE counts as running (nothing is queued behind it)."""
        self.w.binder.pending_motion = verb
        self.w.binder.refresh_enabled()

    def start(self) -> None:
        if self.allowed("start") and self.can_start():
            self.machine_start.request(self.w.loaded.program, self._start_job)

    def _start_job(self, job) -> None:
        """Start ``job`` (the open program as read from the machine's position)."""
        if self.allowed("start") and not self.job_refused(job):
            self.w.binder.begin_job(self.w.loaded)
            self.link.call("start_job", job)

    def job_refused(self, job) -> bool:
        """Whether ``job``, read again from where the machine stands (a relative start),
        has errors or leaves the travel from there; if so the operator is told."""
        problems = job.errors or (job is not self.w.loaded.program and preflight(
            job.ops, self.w.profile, job.lines, self.w.preflight.current_offset()))
        if problems:
            title = self.tr("Program has errors") if job.errors else self.tr("Program leaves the travel")
            self.w.notifier.error(title, problems[0].localized())
        return bool(problems)

    def from_machine(self, program):
        """``program`` as a job from the position the machine reports (``Program.from_start``),
        read here: for the small programs of MDI and custom commands (a file's job goes
        through ``machine_start``, off the GUI thread)."""
        position = self.machine_start.position()
        return program if position is None else program.from_start(position)

    def can_start(self) -> bool:
        """Whether the open program may start now; if not, the operator is told why."""
        loaded = self.w.loaded
        if loaded is None:
            self.w.notifier.warning(self.tr("No program"),
                                    self.tr("Open a G-code file first (File ▸ Open…)."))
            return False
        errors = list(loaded.program.errors)
        if errors:
            first = errors[0]
            text = self.tr("%1 has %n error(s) (first: line %2: %3). Fix them before running.", "",
                           len(errors))
            text = fill(text, loaded.path.name, integer(first.line), localize(first.message))
            self.w.notifier.error(self.tr("Program has errors"), text)
            return False
        if self.w.preflight.blocks_start():
            self.w.notifier.error(self.w.preflight.title(), self.w.preflight.message())
            return False
        status = self.w.binder.status
        if status is not None and not status.homed and not self.w.controls.check_mode.isChecked():
            self.w.notifier.warning(self.tr("Not homed"),
                                    self.tr("Home the machine before starting a job (Machine ▸ Home)."))
            return False
        return True

    def pause(self) -> None:
        self._send("pause", "pause")

    def resume(self) -> None:
        self._send("resume", "resume")

    def stop(self) -> None:
        self._send("stop", "stop")

    def jog(self, axis: str, distance: float, feed: float) -> None:
        if self._send("jog", "jog", axis, float(distance), float(feed)):
            self._motion_sent("JOG")

    def jog_hold(self, keys: tuple, feed: float) -> None:
        """Hold-to-jog: the keys held now; a release always goes out, a press only when the
        table allows it (the panel forgets keys it refused)."""
        if keys and not self.allowed("jog_hold"):
            self.w.controls.jog.held.clear()
            return
        self.link.call("jog_hold", tuple(keys), float(feed))

    def spindle(self, rpm: int) -> None:
        control = "spindle_on" if rpm > 0 else "spindle_off"
        if self._send(control, "send_command", f"SPINDLE {rpm}" if rpm > 0 else "SPINDLE OFF"):
            self.w.binder.spindle_asked = float(max(rpm, 0))
            self._motion_sent("SPINDLE")

    def override(self, verb: str, percent: int) -> None:
        """An override (``FEED``, ``SPINDLE``, ``RAPID``) to ``percent``, if the table allows."""
        self._send(OVERRIDE_CONTROLS[verb], "machine_call", f"set_{verb.lower()}_override", (int(percent),))

    def zero(self, axes: str) -> None:
        self._send("zero", "send_command", f"ZERO {axes}")

    def set_check_mode(self, on: bool) -> None:
        if not self._send("check_mode", "send_command", f"SET CHECK {1 if on else 0}"):
            box = self.w.controls.check_mode
            box.blockSignals(True)
            box.setChecked(not on)  # the switch shows what the machine has
            box.blockSignals(False)

    def resume_after_reconnect(self) -> None:
        self.w.binder.offer_answered = True
        self.w.alert.hide()
        self.link.call("resume_after_reconnect")

    def restart_after_reset(self) -> None:
        status = self.w.binder.status
        if status is None or not status.homed:
            self.w.alert.say(self.tr("Homing first; press “Home and restart” again once homed."))
            self.home("NORMAL")
            return
        self.w.binder.offer_answered = True
        self.w.alert.hide()
        self.link.call("confirm_restart")

    def abandon(self) -> None:
        self.w.binder.offer_answered = True
        self.w.alert.hide()
        self.link.call("stop")

    # -- SD card --------------------------------------------------------------------

    def upload(self, name: str) -> None:
        if not self.allowed("sd_save"):
            return
        if self.w.loaded is None:
            self.w.notifier.warning(self.tr("No program"),
                                    self.tr("Open a G-code file to save it to the card."))
            return
        self.machine_start.request(self.w.loaded.program, lambda job: self._upload_job(name, job))

    def _upload_job(self, name: str, job) -> None:
        """Save ``job`` (the open program as read from the machine's position) as ``name``."""
        if not self.allowed("sd_save") or self.job_refused(job):
            self.w.sd_panel.upload_finished(False, self.tr("not saved"))
            return
        self.w.sd_panel.set_progress(0, device_count(job))
        self.link.call("upload_to_sd", name, job)  # the worker thread renders the lines

    def run_from_sd(self, name: str) -> None:
        if self._send("sd_run", "run_from_sd", name):
            self.w.binder.begin_sd_job(name, self.w.sd_panel.lines_of(name))

    # -- MDI ------------------------------------------------------------------------

    def mdi(self, text: str) -> None:
        """One MDI line: a command or a spindle switch is sent as the command its control
        sends (the same rule as that control), any other G-code line as a one-line job."""
        line = classify(text)
        if not self.allowed(line.control):
            return
        if line.command is not None:
            self.link.call("send_command", line.command)
            words = line.command.upper().split()
            verb = words[0]
            if verb == "SPINDLE" and len(words) > 1:
                self.w.binder.spindle_asked = 0.0 if words[1] == "OFF" else float(words[1])
            if verb in ("HOME", "JOG", "SPINDLE"):
                self._motion_sent(verb)
            return
        self.run_lines(text, "MDI")

    def run_lines(self, text: str, name: str) -> bool:
        """G-code ``text`` run as a job of its own (the caller has asked the table) that
        ends where its last line ends (``mdi``: no after-job lift); a line the loader
        refuses is logged and nothing is sent."""
        from app.gcode import load_text

        program = self.from_machine(load_text(text, name=name))
        errors = list(program.errors)
        if errors:
            self.w.console.add_log("error", f"{name}: {localize(errors[0].message)}")
            return False
        self.w.binder.begin_job(None)
        self.link.call("start_job", list(program.device_lines), 0, True)
        return True

    # -- files and settings ---------------------------------------------------------

    def program_loaded(self, loaded) -> None:
        self.w.loaded = loaded
        self.w.preview.show_model(loaded.preview)  # first: the picture is painted before the rest
        self.w.program_panel.show_program(loaded.program, loaded.path.name)
        self.w.sd_panel.suggest_for(loaded.path)
        self.w.retranslate_ui()  # the title names the file
        add_recent(self.w, loaded.path)
        self.w.binder.refresh_enabled()
        # A big program is millions of long-lived objects: keep the cyclic GC from
        # re-scanning them every few seconds (each pass would stall the event loop).
        gc.freeze()
        self.w.loader.shown()  # the loader may now build the rest (zoom levels, device lines)
        errors = list(loaded.program.errors)
        opened = self.tr("Opened %1: %n line(s) in %2 s", "", len(loaded.program.lines))
        seconds = decimal(loaded.load_s + loaded.model_s, 2)
        opened = opened.replace("%1", loaded.path.name).replace("%2", seconds)
        self.w.status.showMessage(opened + "; " + localize(loaded.program.start.note()), 10000)
        if errors:
            text = self.tr("%1: %n error(s); see the Problems list. It can be previewed but not run.", "",
                           len(errors))
            self.w.notifier.warning(self.tr("Program has errors"), text.replace("%1", loaded.path.name))

    def program_updated(self, loaded) -> None:
        """The device lines and the planner's time estimate are ready (``prepared``), or a
        big program's checks have run (``checked``): the summary and the Problems list say it."""
        if self.w.program_panel.program is loaded.program:
            self.w.program_panel.show_program(loaded.program, loaded.path.name, keep_tab=True)

    def program_refined(self, loaded) -> None:
        """The preview of the open program at the real tolerance (the first was coarser)."""
        if self.w.loaded is not None and self.w.loaded.program is loaded.program:
            self.w.loaded = loaded
            self.w.preview.replace_model(loaded.preview)

    def show_source_line(self, line: int) -> None:
        if self.w.loaded is not None:
            self.w.preview.highlight_move(self.w.loaded.preview.move_of_source_line(line))

    def edit_settings(self) -> SettingsDialog:
        dialog = SettingsDialog(self.w.profile, self.w)
        dialog.accepted.connect(lambda: self.apply_settings(dialog.profile))
        dialog.language_chosen.connect(self.w.set_language)
        dialog.open()
        return dialog

    def apply_settings(self, profile) -> None:
        self.w.profile = profile
        self.link.set_link_timing(profile.link)
        self.w.preflight.run()
        self.w.loader.tolerance = profile.motion.arc_tolerance_mm
        try:
            save_settings(self.w.config_dir / FILE_NAME, profile)
        except OSError as exc:
            self.w.notifier.error(self.tr("Settings not saved"),
                                  self.tr("Cannot write the settings file: %1").replace("%1", str(exc)))
        if self.w.binder.connected:
            for name, value in machine_settings(profile):
                self.link.call("send_command", f"SET {name} {value}")
        saved = self.tr("Settings saved and sent to the machine") if self.w.binder.connected else \
            self.tr("Settings saved")
        self.w.status.showMessage(saved, 5000)
