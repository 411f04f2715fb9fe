"""What every driver's session shares: the write seam, the state, the log and the
silence timer's bookkeeping.

``SessionCore`` is the base of ``app.comm.session.Session`` (the frame protocol) and
``app.comm.grbl.session.GrblSession`` (GRBL). A subclass sets ``listener``, ``clock``,
``state``, ``link`` (a ``heartbeat.LinkMonitor``), ``_write`` and ``_out`` in its
``__init__`` and provides ``_emit_link(reason)`` (its ``LinkEvent``),
``_link_lost(reason)`` (what a loss means to its jobs and commands) and
``_silence_reason()`` (a loss by silence, in words). Bytes queued in
``_out`` go out with ``_flush``; a failed write (``OSError``, pyserial's
``SerialException`` is one) is a link loss, never a crash.
"""

from __future__ import annotations

from collections.abc import Callable

from app.comm.events import ErrorEvent, LogEvent, StateEvent
from app.comm.heartbeat import LinkState
from app.comm.listener import TRANSITIONS, SessionState

S = SessionState


class SessionCore:
    """The common half of a driver's session (see the module docstring)."""

    def _open_link(self, write: Callable[[bytes], object]) -> None:
        """A transport was opened: writes go to ``write``, the silence timer starts,
        and a disconnected session is connecting."""
        self._write = write
        self.link.attach(self.clock())
        self._emit_link()
        if self.state is S.DISCONNECTED:
            self._set_state(S.CONNECTING)

    def detach(self, reason: str = "disconnected") -> None:
        """The transport is gone (closed, unplugged, write failed): a link loss."""
        if self._write is None:
            return
        self._write = None
        self._out.clear()
        self.link.detach()
        self._emit_link(reason)
        self._link_lost(reason)
        self._after_detach()

    def _after_detach(self) -> None:
        """The state once the transport is gone and the loss has been handled."""

    @property
    def attached(self) -> bool:
        return self._write is not None

    # ------------------------------------------------------------------ the silence timer

    def _heard(self, now: float) -> None:
        """Something valid arrived: the link is alive (reported when that changes it)."""
        self.link.heard(now)
        if self.link.update(now):
            self._emit_link()

    def _check_silence(self, now: float) -> None:
        """Degraded, then lost, as the silence grows (``_silence_reason()`` words a loss)."""
        if self.link.update(now):
            self._emit_link()
            if self.link.state is LinkState.LOST:
                self._link_lost(self._silence_reason())

    # ------------------------------------------------------------------ out, state, log

    def _flush(self) -> None:
        if not self._out or self._write is None:
            return
        data, self._out = bytes(self._out), bytearray()
        try:
            self._write(data)
        except OSError as exc:
            self.detach(f"write failed: {exc}")

    def _set_state(self, new: SessionState) -> None:
        """The one place the state changes: checked against TRANSITIONS, logged, notified."""
        old = self.state
        if new is old:
            return
        if new not in TRANSITIONS[old]:
            raise RuntimeError(f"session state {old.name} -> {new.name} is not allowed")
        self.state = new
        self.listener.on_state_changed(StateEvent(old.name, new.name))

    def _log(self, level: str, text: str, source: str = "host") -> None:
        self.listener.on_log(LogEvent(level, text, source))

    def _error(self, code: str, text: str) -> None:
        self.listener.on_error(ErrorEvent(code, text))
        self._log("error", text)
