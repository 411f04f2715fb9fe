"""The serial worker: a QObject on its own QThread that owns the transport and the Session.

The only Qt module of ``app.comm``. The GUI never calls the worker directly: it uses
``SerialController`` (GUI thread), whose methods queue a call into the worker thread
and return at once, so nothing in the GUI thread ever waits on I/O. The worker opens
the transport inside its own thread, pumps the session with a 5 ms QTimer (read what
arrived, ``feed``, ``tick``; every 2 ms while a GRBL job streams, every 50 ms while no
port is open) and turns the session's listener calls into signals.

Signals (all carry one frozen dataclass of ``app.comm.events`` unless said otherwise):

============================  =============================================================
``state_changed``             ``StateEvent(old, new)``: session state (``SessionState`` names)
``status_changed``            ``StatusEvent``: every ``S`` frame (position, state, flags, ...)
``progress_changed``          ``ProgressEvent``: job/upload progress in program line indices
``link_changed``              ``LinkEvent``: CONNECTED / DEGRADED / LOST / DISCONNECTED,
                              resend rate of the last minute and link-quality warning
``alarm_raised``              ``AlarmEvent``: an ``X`` frame (LIMIT, HOST_LOST, BOOT, ...)
``log_added``                 ``LogEvent``: a line for the log (host or machine)
``frame_logged``              ``FrameEvent``: console traffic; D/A/F/S only when verbose
``command_finished``          ``CommandResult``: a command answered, refused or timed out
``job_finished``              ``JobEvent``: a job or SD upload ended (completed or why not)
``error_occurred``            ``ErrorEvent``: LINK_LOST, RETRIES_EXHAUSTED, MACHINE_RESET, ...
``resume_offered``            ``ResumeOffer``: after a reconnect mid-job (same or new boot)
``program_stopped``           ``ProgramStopEvent``: the machine holds at M00/M01/M06 (RESUME goes on)
``hold_reported``             ``HoldEvent``: why the machine holds or stopped (status ``why``), once
``connected``                 ``str``: the URL just opened
``capabilities_changed``      ``driver.Capabilities`` of the machine just connected
``machine_info_changed``      ``grbl.events.MachineInfo``: a GRBL machine's welcome and ``$I``
``connect_failed``            ``str``: why a URL could not be opened
``disconnected``              ``str``: why the transport closed (operator, unplug, ...)
``finished``                  no argument: the worker has shut down (thread may quit)
============================  =============================================================

Connect these signals to methods of QObjects living in the GUI thread (widgets,
models): Qt then queues the call into the GUI thread. A lambda or plain function
would run in the worker thread; relay through a QObject signal instead.
Frames of kind D, A, F and S reach ``frame_logged`` only after ``set_verbose_frames(True)``.

Slots (call them through ``SerialController`` of the same name, or a queued signal):
``connect_to(url)``, ``disconnect_from()``, ``send_command(text)``, ``start_job(program[, start])``
(a ``Program`` or a list of device lines), ``pause()``, ``resume()``, ``stop()``,
``jog(axis, distance_mm, feed_mm_min)``, ``home(mode)``, ``upload_to_sd(name, lines)``,
``run_from_sd(name)``, ``list_sd()``, ``delete_sd(name)``, ``resume_after_reconnect()``,
``confirm_restart()``, ``set_verbose_frames(on)``, ``shutdown()``, ``machine_call(name, args)``
(what only some drivers have: overrides, jog cancel, unlock, ...). ``connect_to(url, driver)``
picks the session: the frame protocol's ``Session`` or ``GrblSession`` (``app/comm/driver.py``).
The session's timers
run on the wall clock (a machine simulated N times faster keeps its link timers in
wall-clock time), on the transport's ``clock()`` if it has one (``sim://``), or on
the ``clock`` given to the worker (tests).
"""

from __future__ import annotations

import contextlib
import time

from PySide6.QtCore import QObject, Qt, QThread, QTimer, Signal, Slot

from app.comm.driver import DRIVERS, FRAME_CAPABILITIES, kind_for_url, make_session, probe
from app.comm.events import FrameEvent, LogEvent
from app.comm.grbl.protocol import STREAM_KINDS
from app.comm.listener import SessionListener
from app.comm.session import Session
from app.comm.transport import open_transport

SLOT_NAMES = frozenset({
    "connect_to", "disconnect_from", "send_command", "start_job", "pause", "resume", "stop",
    "jog", "jog_hold", "home", "upload_to_sd", "run_from_sd", "list_sd", "delete_sd",
    "resume_after_reconnect", "confirm_restart", "set_verbose_frames", "shutdown",
    "machine_call",
})
MACHINE_CALLS = frozenset({"set_feed_override", "set_rapid_override", "set_spindle_override", "jog_cancel",
                           "jog_to_limit", "unlock", "reset", "read_settings", "write_setting"})
PUMP_MS = 5
GRBL_PUMP_MS = 2  # GRBL's only window is its 128-byte buffer (11 ms at 115200): answer its oks sooner
#                  while a job streams; otherwise PUMP_MS (fewer wake-ups competing with the GUI)
IDLE_PUMP_MS = 50  # with no port open: nothing arrives, the session's timers are coarse
READ_CHUNK = 65536
QUIET_KINDS = frozenset({*"DAFS", *STREAM_KINDS})  # the mill's stream frames and GRBL's stream kinds


class _Relay(SessionListener):
    """Turns listener calls into the worker's signals."""

    def __init__(self, worker: SerialWorker) -> None:
        self.w = worker

    def on_state_changed(self, event):
        self.w.state_changed.emit(event)

    def on_status(self, event):
        self.w.status_changed.emit(event)

    def on_progress(self, event):
        self.w.progress_changed.emit(event)

    def on_link_changed(self, event):
        self.w.link_changed.emit(event)

    def on_alarm(self, event):
        self.w.alarm_raised.emit(event)

    def on_log(self, event):
        self.w.log_added.emit(event)

    def on_frame(self, event: FrameEvent):
        if self.w.verbose_frames or event.kind not in QUIET_KINDS or not event.ok:
            self.w.frame_logged.emit(event)

    def on_command_done(self, event):
        self.w.command_finished.emit(event)

    def on_job_finished(self, event):
        self.w.job_finished.emit(event)

    def on_error(self, event):
        self.w.error_occurred.emit(event)

    def on_resume_offer(self, event):
        self.w.resume_offered.emit(event)

    def on_program_stop(self, event):
        self.w.program_stopped.emit(event)

    def on_hold(self, event):
        self.w.hold_reported.emit(event)

    def on_machine_info(self, event):
        self.w.machine_info_changed.emit(event)


class SerialWorker(QObject):
    """Owns transport and Session in the worker thread (see the module docstring)."""

    state_changed = Signal(object)
    status_changed = Signal(object)
    progress_changed = Signal(object)
    link_changed = Signal(object)
    alarm_raised = Signal(object)
    log_added = Signal(object)
    frame_logged = Signal(object)
    command_finished = Signal(object)
    job_finished = Signal(object)
    error_occurred = Signal(object)
    resume_offered = Signal(object)
    program_stopped = Signal(object)
    hold_reported = Signal(object)
    connected = Signal(str)
    capabilities_changed = Signal(object)  # driver.Capabilities of the session just connected
    machine_info_changed = Signal(object)  # grbl.events.MachineInfo: welcome and $I
    connect_failed = Signal(str)
    disconnected = Signal(str)
    finished = Signal()

    def __init__(self, clock=None, opener=open_transport) -> None:
        super().__init__()
        self._fixed_clock = clock
        self.session = Session(None, _Relay(self), clock or time.monotonic)
        self.session.capabilities = FRAME_CAPABILITIES
        self.transport = None
        self.url = ""
        self.verbose_frames = False
        self._opener = opener
        self._timer: QTimer | None = None

    # ------------------------------------------------------------------ life cycle

    @Slot()
    def start(self) -> None:
        """Connected to ``QThread.started``: create the pump timer in this thread."""
        self._timer = QTimer(self)
        self._timer.setInterval(IDLE_PUMP_MS)
        self._timer.timeout.connect(self.pump)
        self._timer.start()

    @Slot()
    def shutdown(self) -> None:
        """Close the transport, stop the timer and emit ``finished``."""
        self._close("shut down")
        if self._timer is not None:
            self._timer.stop()
        self.finished.emit()

    @Slot()
    def pump(self) -> None:
        """Read whatever arrived, feed the session, let it tick."""
        if self.transport is not None:
            try:
                waiting = self.transport.in_waiting
                data = self.transport.read(min(max(waiting, 1), READ_CHUNK)) if waiting else b""
            except (OSError, ValueError, TypeError) as exc:
                self._lost(f"read failed: {exc}")
                return
            if data:
                self.session.feed(data)
        self.session.tick()
        if self.transport is not None and not self.session.attached:
            self._lost("write failed")
        elif self.transport is not None:
            self._pump_every(self._pump_ms())

    # ------------------------------------------------------------------ slots

    @Slot(str, object)
    def invoke(self, name: str, args: tuple) -> None:
        """Call the slot ``name`` with ``args`` (how SerialController reaches this thread)."""
        if name not in SLOT_NAMES:
            raise AttributeError(f"SerialWorker has no slot {name!r}")
        getattr(self, name)(*args)

    @Slot(str)
    def connect_to(self, url: str, driver: str = "") -> None:
        """Open ``url`` and talk to it with ``driver``: "frame", "grbl", "auto" (by the URL,
        else by what the machine says first: ``driver.probe``); "" by the URL, else frame."""
        self._close("reconnecting")
        try:
            self.transport = self._opener(url)
        except (OSError, ValueError, ImportError) as exc:
            self.transport = None
            self.log_added.emit(LogEvent("error", f"cannot open {url or 'sim://'}: {exc}"))
            self.connect_failed.emit(str(exc))
            return
        self.url = url
        kind = driver if driver in DRIVERS else kind_for_url(url) or (
            driver == "auto" and probe(self.transport)) or "frame"
        if getattr(self.session, "capabilities", FRAME_CAPABILITIES).driver != kind:
            self.session = make_session(kind, _Relay(self))
        self.session.clock = self._clock_for(self.transport)
        self.session.attach(self._write)
        early = getattr(self.transport, "probe_bytes", b"")
        if early:
            self.session.feed(early)
        self._pump_every(self._pump_ms())
        self.capabilities_changed.emit(getattr(self.session, "capabilities", FRAME_CAPABILITIES))
        self.connected.emit(url)

    @Slot(str, object)
    def machine_call(self, name: str, args: tuple = ()) -> None:
        """A call only some drivers have (overrides, jog cancel, unlock...): ignored by the
        session that has none (its capabilities say so)."""
        if name not in MACHINE_CALLS:
            raise AttributeError(f"no machine call {name!r}")
        method = getattr(self.session, name, None)
        if method is not None:
            method(*args)

    @Slot()
    def disconnect_from(self) -> None:
        self._close("disconnected by the operator")

    @Slot(str)
    def send_command(self, text: str) -> None:
        self.session.send_command(text)

    @Slot(object)
    def start_job(self, program, start: int = 0, mdi: bool = False) -> None:
        """The job from device line ``start`` (0: the whole program; else the modal state
        before ``start`` is restored first); ``mdi``: lines the operator typed."""
        self.session.start_job(program, start, mdi=mdi)

    @Slot()
    def pause(self) -> None:
        self.session.pause()

    @Slot()
    def resume(self) -> None:
        self.session.resume()

    @Slot()
    def stop(self) -> None:
        self.session.stop()

    @Slot(str, float, float)
    def jog(self, axis: str, distance_mm: float, feed_mm_min: float) -> None:
        self.session.jog(axis, distance_mm, feed_mm_min)

    @Slot(object, float)
    def jog_hold(self, keys: tuple, feed_mm_min: float) -> None:
        """Hold-to-jog: the jog keys held now (``()`` on release); see Session.jog_hold."""
        self.session.jog_hold(tuple(keys), feed_mm_min)

    @Slot(str)
    def home(self, mode: str = "NORMAL") -> None:
        self.session.home(mode or "NORMAL")

    @Slot(str, object)
    def upload_to_sd(self, name: str, lines) -> None:
        self.session.upload_to_sd(name, lines)

    @Slot(str)
    def run_from_sd(self, name: str) -> None:
        self.session.run_from_sd(name)

    @Slot()
    def list_sd(self) -> None:
        self.session.list_sd()

    @Slot(str)
    def delete_sd(self, name: str) -> None:
        self.session.delete_sd(name)

    @Slot()
    def resume_after_reconnect(self) -> None:
        self.session.resume_after_reconnect()

    @Slot()
    def confirm_restart(self) -> None:
        self.session.confirm_restart()

    @Slot(bool)
    def set_verbose_frames(self, on: bool) -> None:
        self.verbose_frames = bool(on)

    # ------------------------------------------------------------------ internals

    def _clock_for(self, transport):
        """The injected clock, else the transport's own (``sim://``), else the wall clock."""
        return self._fixed_clock or getattr(transport, "clock", None) or time.monotonic

    def _write(self, data: bytes) -> None:
        self.transport.write(data)

    def _pump_ms(self) -> int:
        """GRBL_PUMP_MS while a GRBL job streams, else PUMP_MS."""
        grbl = getattr(self.session, "capabilities", FRAME_CAPABILITIES).driver == "grbl"
        return GRBL_PUMP_MS if grbl and self.session.busy else PUMP_MS

    def _pump_every(self, ms: int) -> None:
        if self._timer is not None and self._timer.interval() != ms:
            self._timer.setInterval(ms)

    def _lost(self, reason: str) -> None:
        self.session.detach(reason)
        self._close(reason)

    def _close(self, reason: str) -> None:
        transport, self.transport = self.transport, None
        if transport is None:
            return
        self._pump_every(IDLE_PUMP_MS)
        self.session.detach(reason)
        with contextlib.suppress(OSError, ValueError):
            transport.close()
        self.disconnected.emit(reason)


class SerialController(QObject):
    """Owns the worker thread for the GUI; every method returns at once.

    ``controller = SerialController(); controller.start()``; connect to
    ``controller.worker.<signal>``; call ``controller.connect_to(url)`` etc.;
    ``controller.shutdown()`` at exit (finished -> quit -> deleteLater).
    """

    _called = Signal(str, object)

    def __init__(self, parent: QObject | None = None, worker: SerialWorker | None = None) -> None:
        super().__init__(parent)
        self.thread = QThread()
        self.thread.setObjectName("serial-worker")
        self.worker = worker or SerialWorker()
        self.worker.moveToThread(self.thread)
        self.thread.started.connect(self.worker.start)
        self.worker.finished.connect(self.thread.quit, Qt.ConnectionType.DirectConnection)
        self.thread.finished.connect(self.worker.deleteLater)
        self._called.connect(self.worker.invoke)

    def start(self) -> None:
        self.thread.start()

    def call(self, name: str, *args) -> None:
        """Queue ``worker.<name>(*args)`` in the worker thread."""
        self._called.emit(name, args)

    def shutdown(self, wait_ms: int = 3000) -> bool:
        """Stop the worker and its thread; True if the thread ended within ``wait_ms``."""
        if not self.thread.isRunning():
            return True
        self.call("shutdown")
        return self.thread.wait(wait_ms)

    def __getattr__(self, name: str):
        if name in SLOT_NAMES:
            return lambda *args: self.call(name, *args)
        raise AttributeError(name)
