"""The job's bounds before it starts: the open program checked against the travel with
the machine's real work offset (``checks.preflight``).

The offset is read from the machine (``GET OFFSET_X|Y|Z`` on connect) and follows every
``ZERO`` answer; until the machine has answered, the profile's default offset stands.
The travel is the profile's, or a GRBL machine's own ``$130``-``$132`` (from its ``$$``
print-out and every ``$13x=`` written), as ``app.comm.grbl.dialect.grbl_travel`` reads them.
A GRBL machine without homing (``$22=0``) is not checked: its machine coordinates start
where it powered up, so its travel says nothing of where a program goes.
The check runs again when a file is opened (a big program's once its own checks have
run, ``ProgramLoader.checked``; Start waits until then), the work zero changes or the
settings change. A program that would leave the travel cannot start (``blocks_start``); only in
check mode may the operator override it (the "Override travel check" switch).
"""

from __future__ import annotations

from dataclasses import replace

from PySide6.QtCore import QObject

from app.comm.grbl.dialect import grbl_travel
from app.comm.grbl.settings import homing_enabled
from app.gcode.checks import preflight
from app.i18n import localize

OFFSET_NAMES = ("OFFSET_X", "OFFSET_Y", "OFFSET_Z")


def sentence(text: str) -> str:
    """``text`` ending as a sentence (a full stop added unless it ends with one already)."""
    text = text.rstrip()
    return text if not text or text[-1] in ".!?…:" else text + "."


class Preflight(QObject):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.offset: list[float | None] = [None, None, None]
        self.travel = None  # a GRBL machine's own travel ($130-$132), else the profile's
        self._settings: dict[int, str] = {}
        self._homing = True  # the machine homes: its travel is where its coordinates are
        self.errors: list = []
        worker = window.link.worker
        worker.connected.connect(self.ask_offset)
        worker.command_finished.connect(self.on_command)
        window.loader.loaded.connect(self.on_loaded)
        window.loader.checked.connect(self.on_loaded)  # a big program's own checks, after its picture
        window.controls.check_mode.toggled.connect(lambda _on: self.w.binder.refresh_enabled())
        window.controls.override_travel.toggled.connect(lambda _on: self.w.binder.refresh_enabled())

    def ask_offset(self, url: str = "") -> None:
        self.travel, self._settings, self._homing = None, {}, True  # another machine: its own travel
        for name in OFFSET_NAMES:
            self.w.link.call("send_command", f"GET {name}")

    def on_command(self, result) -> None:
        if not result.ok:
            return
        if result.verb == "GET" and result.args[:1] and result.args[0] in OFFSET_NAMES:
            name, value = result.info.split()[:2]
            self.offset[OFFSET_NAMES.index(name)] = float(value)
            if None not in self.offset:
                self.run()
        elif result.verb == "$$" or result.verb.startswith(("$13", "$22=")):
            self._grbl_settings(result.rows if result.verb == "$$" else (result.verb,))
        elif result.verb == "ZERO":
            words = dict((w[0], float(w[1:])) for w in result.info.split() if w[:1] in "XYZ")
            self.offset = [words.get(axis, old) for axis, old in zip("XYZ", self.offset, strict=True)]
            self.run()

    def _grbl_settings(self, rows) -> None:
        """``$n=value`` rows of a GRBL machine: its travel once ``$130``-``$132`` are known."""
        for row in rows:
            number, _, value = row.lstrip("$").partition("=")
            if number.isdigit():
                self._settings[int(number)] = value
        try:
            travel = grbl_travel(self._settings, (0.0, 0.0, 0.0), self.w.profile)[0].travel
        except ValueError:
            travel = self.travel  # not all three reported yet (or not a travel): the profile's stands
        if travel != self.travel or homing_enabled(self._settings) != self._homing:
            self.travel, self._homing = travel, homing_enabled(self._settings)
            self.run()

    def on_loaded(self, loaded) -> None:
        self.run()

    def current_offset(self) -> tuple[float, float, float]:
        default = self.w.profile.travel.work_offset()
        return tuple(d if v is None else v for v, d in zip(self.offset, default, strict=True))

    def run(self) -> None:
        """Check the open program again and say what stands in the way of Start."""
        loaded = self.w.loaded
        program = getattr(loaded, "program", None)
        old = [str(e) for e in self.errors]
        self.errors = []
        if self._unchecked():  # run again once they have (``checked``)
            self.w.binder.refresh_enabled()
            return
        if program is not None and not program.errors and self._homing:
            profile = self.w.profile if self.travel is None else replace(self.w.profile, travel=self.travel)
            self.errors = preflight(program.ops, profile, program.lines, self.current_offset(),
                                    program.envelope)  # the lines unsplit; the load's check reused
        if self.errors and [str(e) for e in self.errors] != old:
            self.w.notifier.error(self.tr("Program leaves the travel"), self.message())
        self.w.binder.refresh_enabled()

    def _unchecked(self) -> bool:
        """True while the open program's own checks have not run (a big program's come a
        moment after its picture): until then it is not known to stay in the travel."""
        program = getattr(self.w.loaded, "program", None)
        return bool(getattr(program, "checks_pending", False))

    def title(self) -> str:
        if self._unchecked():
            return self.tr("Program not checked yet")
        return self.tr("Program leaves the travel")

    def message(self) -> str:
        if self._unchecked():
            return self.tr("Start waits until the program is checked against the travel (a moment "
                           "after it opens).")
        first = self.errors[0]
        more = len(self.errors) - 1
        text = self.tr("Start is disabled: line %1: %2").replace("%1", str(first.line)).replace(
            "%2", localize(first.message))
        if more:
            text += " " + self.tr("(and %n more axis/direction(s))", "", more)
        advice = self.tr("Move the work zero or fix the program; in check mode it may be overridden.")
        return sentence(text) + " " + advice

    def blocks_start(self) -> bool:
        if self._unchecked():
            return True
        if not self.errors:
            return False
        controls = self.w.controls
        return not (controls.check_mode.isChecked() and controls.override_travel.isChecked())
