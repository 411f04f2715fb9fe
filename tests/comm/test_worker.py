"""The QThread worker against a scripted in-memory machine (qtbot.waitSignal, no sleeps)."""

import threading

import pytest
from PySide6.QtCore import QObject, Signal

from app.comm import frame as fr
from app.comm.events import JobEvent, StatusEvent
from app.comm.worker import SerialController, SerialWorker


class EchoMachine:
    """A pyserial-shaped port that answers like a machine in check mode, at once."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._out = bytearray()
        self._rx = fr.Deframer(realtime=True)
        self.closed = False
        self.timeout = 0
        self.fail_reads = False

    @property
    def in_waiting(self) -> int:
        if self.fail_reads:
            raise OSError("device reports readiness to read but returned no data")
        with self._lock:
            return len(self._out)

    def read(self, n: int = 1) -> bytes:
        with self._lock:
            data, self._out[:] = bytes(self._out[:n]), self._out[n:]
        return data

    def write(self, data: bytes) -> int:
        for item in self._rx.feed(data, 0.0):
            for reply in self._answer(item):
                with self._lock:
                    self._out += fr.encode(reply)
        return len(data)

    def _answer(self, item):
        status = fr.Status("CAFE", "IDLE", 0, 0, 10, -1, -1, 16, 0, "H")
        if isinstance(item, fr.Command):
            if item.verb in ("PING", "STATUS"):
                return [status]
            return [fr.Ok(item.id, item.verb, " ".join(item.args))]
        if isinstance(item, fr.Data):
            return [fr.Ack(item.seq, 16), fr.Finished(item.seq)]
        return []

    def reset_input_buffer(self) -> None:
        pass

    def close(self) -> None:
        self.closed = True


class MainThread(QObject):
    """Re-emits worker signals in the test's (GUI) thread: a queued signal-to-signal hop.

    pytest-qt's waitSignal connects a plain callable, which Qt would run in the
    emitting (worker) thread; the GUI connects QObject methods, which are queued.
    """

    relayed = Signal(object)
    relayed_text = Signal(str)

    def __init__(self, signal, text: bool) -> None:
        super().__init__()
        self.out = self.relayed_text if text else self.relayed
        signal.connect(self.out)


def on_gui(signal, text: bool = False) -> Signal:
    relay = MainThread(signal, text)
    on_gui.keep.append(relay)
    return relay.out


on_gui.keep = []


@pytest.fixture
def controller(qtbot):
    machine = EchoMachine()
    worker = SerialWorker(opener=lambda url: machine)
    ctl = SerialController(worker=worker)
    ctl.machine = machine
    ctl.start()
    yield ctl
    assert ctl.shutdown()


def test_connect_streams_a_job_and_reports_it(qtbot, controller):
    worker = controller.worker
    with qtbot.waitSignal(on_gui(worker.status_changed), timeout=5000) as status:
        controller.connect_to("scripted://")
    assert isinstance(status.args[0], StatusEvent)
    lines = [f"G01 X{i} F300" for i in range(50)]
    with qtbot.waitSignal(on_gui(worker.job_finished), timeout=10000) as finished:
        controller.start_job(lines)
    event = finished.args[0]
    assert isinstance(event, JobEvent) and event.completed and event.done == 49


def test_read_error_is_a_link_loss_not_a_crash(qtbot, controller):
    worker = controller.worker
    with qtbot.waitSignal(on_gui(worker.status_changed), timeout=5000):
        controller.connect_to("scripted://")
    with qtbot.waitSignal(on_gui(worker.disconnected, text=True), timeout=5000) as gone:
        controller.machine.fail_reads = True
    assert "read failed" in gone.args[0]
    assert controller.machine.closed


def test_unknown_slot_is_refused():
    with pytest.raises(AttributeError):
        SerialController.__getattr__(SerialController.__new__(SerialController), "explode")
