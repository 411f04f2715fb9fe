"""Start from a line: the program panel's "Start here" (right-click a source line).

The job starts at the first device line of that source line with the modal state of
the lines before it restored by the preamble of ``app.comm.modal`` (spindle and speed,
feed, then the position: retract, rapid over, feed down; units, distance mode and plane
need no line: the machine's dialect is absolute millimetres in the XY plane). A
window-modal confirmation shows that state and the preamble before anything moves.
A program whose first moves are relative is first read again from the position the
machine reports (``app.ui.machine_start``, off the GUI thread): the state, the preamble
and the lines sent are that job's, never a reading from (0, 0, 0).
"""

from __future__ import annotations

from PySide6.QtCore import QObject
from PySide6.QtWidgets import QMessageBox

from app.comm.modal import device_index_of, modal_state, restart_preamble


def _fill(text: str, *values) -> str:
    """``text`` with %1, %2, ... replaced by ``values`` (translated texts keep the markers)."""
    for n, value in enumerate(values, start=1):
        text = text.replace(f"%{n}", str(value))
    return text


def tool_before(lines: list[str], index: int) -> int | None:
    """The tool of the last ``M06 [T<n>]`` device line before ``index`` (0: an M06 that
    names no tool; None: no tool change before it)."""
    for line in reversed(lines[:index]):
        if line.startswith("M06"):
            words = line.split()
            named = [w[1:] for w in words[1:] if w.startswith("T") and w[1:].isdigit()]
            return int(named[0]) if named else 0
    return None


class StartHere(QObject):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.dialog: QMessageBox | None = None
        self.pending: int | None = None  # the device line the dialog would start at
        self.job = None  # the program as a job from the machine's position, for the dialog
        window.program_panel.start_here_requested.connect(self.ask)

    def ask(self, source_line: int) -> None:
        """Show the confirmation for starting at ``source_line`` (if the program may start),
        once the program is read as a job from where the machine stands (``MachineStart``)."""
        if not self.w.operator.allowed("start_here") or not self.w.operator.can_start():
            return
        confirm = lambda job: self._confirm(job, source_line)  # noqa: E731
        self.w.operator.machine_start.request(self.w.loaded.program, confirm)

    def _confirm(self, job, source_line: int) -> None:
        """The confirmation of starting ``job`` at ``source_line``: the state and the preamble
        as the job's own lines give them (read from the machine's position)."""
        if not self.w.operator.allowed("start_here") or not self.w.operator.can_start():
            return
        index = device_index_of(job.line_map.tolist(), source_line)
        if index is None:
            self.w.notifier.warning(self.tr("Start here"), _fill(self.tr("Nothing runs from line %1 on."),
                                                                 source_line))
            return
        lines = job.device_lines
        self.pending, self.job = index, job
        self.dialog = box = QMessageBox(QMessageBox.Icon.Question, self.tr("Start here"),
                                        self._text(source_line, len(job.lines)), parent=self.w)
        box.setInformativeText(self._state(lines, index))
        box.setDetailedText("\n".join(restart_preamble(lines, index)) or self.tr("(nothing to restore)"))
        self.start_button = box.addButton(self.tr("Start"), QMessageBox.ButtonRole.AcceptRole)
        box.addButton(QMessageBox.StandardButton.Cancel)
        box.buttonClicked.connect(self._answered)
        box.open()
        self.w.binder.refresh_enabled()  # a dialog waits

    def _text(self, source_line: int, total: int) -> str:
        """The question, in source lines of the file the operator opened."""
        return _fill(self.tr("Start the job at line %1 of %2?"), source_line, total)

    def _state(self, lines: list[str], index: int) -> str:
        state = modal_state(lines, index)
        rows = [self._tool(lines, index)]
        rows.append(self.tr("Units mm, absolute distances, XY plane (the machine's dialect)."))
        rows.append(_fill(self.tr("Feed F%1."), f"{state.feed:g}") if state.feed else self.tr("No feed yet."))
        if state.spindle_rpm is not None:
            spindle = self.tr("Spindle on at S%1, up to speed before moving.")
            rows.append(_fill(spindle, f"{state.spindle_rpm:g}"))
        else:
            rows.append(self.tr("Spindle off."))
        if state.x is not None and state.y is not None:
            rows.append(_fill(self.tr("Retract to Z%1, rapid to X%2 Y%3, feed down to Z%4."),
                              *(f"{v:.3f}" for v in (state.top_z, state.x, state.y, state.z))))
        return "\n".join(rows)

    def _tool(self, lines: list[str], index: int) -> str:
        """Which tool must be in the spindle at ``index``: the last tool change before it."""
        tool = tool_before(lines, index)
        if tool is None:
            return self.tr("No tool change comes before this line: the tool the program starts with must be "
                           "in the spindle.")
        if tool == 0:
            return self.tr("The tool of the last tool change before this line (it names no number) must be "
                           "in the spindle.")
        text = self.tr("Tool T%1 must be in the spindle (the last tool change before this line).")
        return _fill(text, tool)

    def _answered(self, button) -> None:
        index, self.pending = self.pending, None
        job, self.job = self.job, None
        self.w.binder.refresh_enabled()
        if button is not self.start_button or index is None:
            return
        operator = self.w.operator
        if not operator.allowed("start_here") or not operator.can_start() or operator.job_refused(job):
            return
        position = operator.machine_start.position()
        moved = position is not None and job.start.needs_reading_from(position)
        if job is not self.w.loaded.program and moved:
            self.w.notifier.warning(self.tr("Start here"), self.tr(
                "The machine moved since the program was read from its position: choose Start here again."))
            return
        self.w.binder.begin_job(self.w.loaded, index)
        self.w.link.call("start_job", job, index)
