"""What the window adds on a GRBL machine (issue 23), in one place beside the panels it
feeds; on the frame protocol's mill it stays out of the way.

- The ``$$`` table as the machine last printed it (``settings``, ``settings_changed``),
  and *Machine > Machine settings ($$)…* (``app/ui/grbl_settings.py``), enabled by the
  state table's ``machine_settings`` control (off, with a word why, on a machine
  without a settings table of its own).
- *Machine > Unlock ($X)* and the alarm banner (``app/ui/grbl_alarm.py``).
- ``$G``: the machine's modal state (with ``$#``'s G92 offset) into the live modal state
  panel between jobs;
  ``$#`` and ``$G`` again after every job and MDI line (a program may change the
  work systems), through the DRO's own reading (``GET WCS``, which the GRBL session
  answers from ``$#`` and ``$G``).
- Why the machine holds (``Hold:0/1``, ``Door:0..3``, the status's ``why``) in words in
  the status bar, as the mill's hold reasons.
- A read of the work systems that failed (``$#`` refused, say in check mode or while the
  machine runs, or lost to a reset): said in the status bar and the console, the DRO
  left showing none (``WorkSystems`` keeps them unknown, never the one live offset), and
  read again once the machine is back at rest (another state or boot than at the
  failure, or ``REREAD_S`` later, twice as long after each failure in a row), not in
  check mode, where GRBL refuses ``$#``.
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject, Signal
from PySide6.QtGui import QAction

from app.comm.grbl.settings import homing_enabled
from app.comm.grbl.status import hold_event
from app.i18n import localize
from app.ui.grbl_alarm import GrblAlarmBar
from app.ui.live_modal import machine_modes
from app.ui.menus import SOURCE_TEXT
from app.ui.work_offsets import NO_SYSTEMS

REREAD_S = 5.0  # a failed read of the work systems is tried again this long after, at rest,
REREAD_MAX_S = 60.0  # twice as long after each failure in a row, up to this
AT_REST = ("IDLE", "ALARM")

ACTIONS = {
    "machine_settings": QT_TRANSLATE_NOOP("Menus", "Machine settings (&$$)…"),
    "unlock": QT_TRANSLATE_NOOP("Menus", "&Unlock ($X)"),
}


def settings_of(rows) -> dict[int, str]:
    """The ``$n=value`` rows of a ``$$`` answer as ``{n: value}`` (other rows left out)."""
    out = {}
    for row in rows:
        number, sep, value = row[1:].partition("=")
        if row.startswith("$") and sep and number.isdigit():
            out[int(number)] = value.strip()
    return out


def g92_of(rows) -> str:
    """The ``[G92:x,y,z]`` row of a ``$#`` answer as ``X.. Y.. Z..`` ("" when all are 0)."""
    for row in rows:
        if row.startswith("[G92:") and row.endswith("]"):
            try:
                values = [float(v) for v in row[5:-1].split(",")]
            except ValueError:
                return ""
            return " ".join(f"{a}{v:g}" for a, v in zip("XYZ", values, strict=False)) if any(values) else ""
    return ""


class GrblWindow(QObject):
    settings_changed = Signal()

    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.settings: dict[int, str] = {}
        self.dialog = None
        self.why = ""  # the hold last shown in the status bar
        self.g92 = ""  # the G92 offset of the last $# ("" when none is in force)
        self.unread: tuple | None = None  # (boot, state, time) when the work systems' read failed
        self.failed_reads = 0  # failed reads of the work systems in a row
        self.alarm = GrblAlarmBar(window)
        self.actions = self._add_actions(window)
        worker = window.link.worker
        worker.command_finished.connect(self.on_command)
        worker.status_changed.connect(self.on_status)
        worker.job_finished.connect(self.on_job_finished)
        worker.disconnected.connect(self.on_disconnected)
        worker.capabilities_changed.connect(window.controls.overrides.set_ranges)

    def _add_actions(self, window) -> dict[str, QAction]:
        home = window.actions_by_name["home"]
        menu = next(w for w in home.associatedObjects() if hasattr(w, "insertAction"))
        slots = {"machine_settings": self.open_settings, "unlock": self.alarm.unlock}
        actions = {}
        for name, text in ACTIONS.items():
            action = QAction(QCoreApplication.translate("Menus", text), window)
            action.setProperty(SOURCE_TEXT, text)
            action.triggered.connect(slots[name])
            menu.insertAction(window.actions_by_name["home_recover"], action)
            actions[name] = window.actions_by_name[name] = action
        return actions

    @property
    def on_grbl(self) -> bool:
        return getattr(self.w.link.capabilities, "driver", "frame") == "grbl"

    # -- the machine's answers ---------------------------------------------------------

    def on_command(self, result) -> None:
        if not result.ok:
            self._offsets_not_read(result)
            return
        if (result.verb, tuple(result.args[:1])) == ("GET", ("WCS",)):
            self.failed_reads = 0
        if result.verb == "$$":
            self.settings = settings_of(result.rows)
            self._settings_read()
        elif settings_of([result.verb]) and self.settings:  # a write from anywhere (the console too)
            self.settings.update(settings_of([result.verb]))
            self._settings_read()
        elif result.verb == "$#":
            self.g92 = g92_of(result.rows)
        elif result.verb == "$G":
            words = next((row[4:-1] for row in result.rows if row.startswith("[GC:")), None)
            if words is not None:
                view = machine_modes(words)
                view.g92 = self.g92
                self.w.live_panel.show_machine(view)

    def _settings_read(self) -> None:
        self.alarm.set_homing(homing_enabled(self.settings))
        self.settings_changed.emit()

    def on_job_finished(self, event) -> None:
        """After a job or MDI line: the work systems (not in check mode, where GRBL refuses
        ``$#`` and a program changed nothing) and the modal state again."""
        if event.kind != "job" or not self.on_grbl:
            return
        if not self.w.controls.check_mode.isChecked():
            self.w.dro.read_all()
        self.w.link.call("send_command", "$G")

    def _offsets_not_read(self, result) -> None:
        """``GET WCS`` failed for a reason that passes (not "no work systems", not a lost link,
        after which the DRO reads them at the reconnect): say so, read again when back."""
        if not self.on_grbl or (result.verb, tuple(result.args[:1])) != ("GET", ("WCS",)):
            return
        if result.code in NO_SYSTEMS or result.code == "LINK_LOST":
            return
        status = self.w.binder.status
        self.unread = (status.boot, status.state, status.time) if status is not None else (None, None, 0.0)
        self.failed_reads += 1
        why = localize(result.info) or result.code
        text = self.tr("The work offsets could not be read (%1): the DRO shows none until they are read "
                       "again, once the machine is at rest.").replace("%1", why)
        self.w.status.showMessage(text, 15000)
        self.w.console.add_log("warning", text)

    def _reread_when_back(self, event) -> None:
        if self.unread is None or event.state not in AT_REST or self.w.controls.check_mode.isChecked():
            return
        boot, state, time = self.unread
        wait = min(REREAD_S * 2 ** (self.failed_reads - 1), REREAD_MAX_S)
        if event.boot == boot and event.state == state and event.time - time < wait:
            return
        self.unread = None
        self.w.dro.read_all()

    def on_status(self, event) -> None:
        """GRBL's hold and door states in words (``binder.on_hold``: the mill's hold reasons);
        a failed read of the work systems tried again once the machine is back."""
        self._reread_when_back(event)
        if event.why == self.why or not (self.on_grbl or self.why):
            return
        self.why = event.why
        self.w.binder.on_hold(hold_event(event))

    def on_disconnected(self, _reason: str) -> None:
        self.why, self.unread = "", None
        self.w.live_panel.show_machine(None)

    # -- the operator ------------------------------------------------------------------

    def open_settings(self):
        """The settings dialog (one, reused); the state table decides whether it opens."""
        if not self.w.operator.allowed("machine_settings"):
            return None
        from app.ui.grbl_settings import GrblSettingsDialog

        if self.dialog is None:
            self.dialog = GrblSettingsDialog(self.w, self)
        if not self.settings:
            self.dialog.read()
        self.dialog.show()
        self.dialog.raise_()
        return self.dialog
