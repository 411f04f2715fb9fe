"""A program as a job from where the machine stands (issue 19), the window responsive.

A program whose first moves are relative to where the tool stands (``G91`` first moves,
an arc or a cycle from the start) is read by the loader from (0, 0, 0); as a job it must
be read again from the position the machine reports (``Program.from_start``). Start,
Start here and Save to SD all go through ``request(program, then)``: ``then(job)`` is
called at once when nothing needs reading again, else once the loader's thread has read
it (seconds for a million lines), provided the same program is still open, no newer
request came and the machine still stands where it was read from (else it is read again
from the new position).
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject

from app.gcode.start import SAME_PLACE


class MachineStart(QObject):
    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self._waiting: tuple[object, tuple, Callable] | None = None  # (token, position, then)
        window.loader.read_again.connect(self._answered)

    @property
    def busy(self) -> bool:
        """A program is being read again for a request not answered yet."""
        return self._waiting is not None

    def position(self) -> tuple[float, float, float] | None:
        """The work position the machine last reported (None: not connected yet)."""
        status = self.w.binder.status
        return None if status is None else (float(status.x), float(status.y), float(status.z))

    def request(self, program, then: Callable) -> None:
        """``then(job)``: ``program`` as a job from the machine's position (module docstring)."""
        position = self.position()
        if position is None or not program.start.needs_reading_from(position):
            self._waiting = None
            then(program)
            return
        token = object()
        self._waiting = (token, position, then)
        self.w.status.showMessage(self.tr("Reading the program again from where the machine stands…"))
        self.w.loader.read_from(program, position, token)

    def cancel(self) -> None:
        """Forget the request waiting for its answer (the operator gave up)."""
        self._waiting = None

    def _answered(self, answer) -> None:
        if self._waiting is None or answer.token is not self._waiting[0]:
            return  # cancelled, or a newer request
        _, position, then = self._waiting
        self._waiting = None
        self.w.status.clearMessage()
        if answer.error:
            self.w.notifier.error(self.tr("Program not started"), answer.error)
            return
        if self.w.loaded is None or self.w.loaded.program is not answer.program:
            return  # another program was opened meanwhile
        now = self.position()
        if now is not None and max(abs(a - b) for a, b in zip(now, position, strict=True)) > SAME_PLACE:
            self.request(answer.program, then)  # the machine moved while it was read: read again
            return
        then(answer.job)
