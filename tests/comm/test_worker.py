"""The QThread worker against a scripted in-memory machine (qtbot.waitSignal, no sleeps)."""

import threading

import pytest
from PySide6.QtCore import QObject, Signal

from app.comm import deframer as dfr
from app.comm import frame as fr
from app.comm.events import JobEvent, StatusEvent
from app.comm.worker import SerialController, SerialWorker


class EchoMachine:
    """A pyserial-shaped port that answers like a machine in check mode, at once."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._out = bytearray()
        self._rx = dfr.Deframer(legacy=True)
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
        if isinstance(item, fr.RealtimeCommand):
            return [fr.Ok(item.id, item.verb, "IDLE")]
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


class KeptSim:
    """An opener for ``sim://`` that keeps one machine across disconnects (as a real one is)."""

    def __init__(self, sd) -> None:
        from backend_sim import Simulator
        from tests.comm.simlink import FAST_HOMING

        self.sim = Simulator(profile=FAST_HOMING, sd_dir=sd, seed=5)
        self.sim.start(speed=50.0)

    def __call__(self, url):
        port = self.sim.host_port
        port.open()
        return _PortOnly(self.sim)


class _PortOnly:
    def __init__(self, sim) -> None:
        self.sim, self.port = sim, sim.host_port
        self.port.timeout = 0

    def clock(self) -> float:
        return self.sim.clock.now

    in_waiting = property(lambda self: self.port.in_waiting)

    def read(self, n: int) -> bytes:
        return self.port.read(n)

    def write(self, data: bytes) -> int:
        return self.port.write(data)

    def close(self) -> None:
        self.port.close()


def test_unplug_mid_job_then_replug_and_resume(qtbot, tmp_path):
    from tests.comm.simlink import assert_oracle
    from tests.comm.test_faults_machine import motion_program

    opener = KeptSim(tmp_path)
    controller = SerialController(worker=SerialWorker(opener=opener))
    worker = controller.worker
    controller.start()
    try:
        with qtbot.waitSignal(on_gui(worker.status_changed), timeout=5000):
            controller.connect_to("sim://")
        with qtbot.waitSignal(on_gui(worker.command_finished), timeout=30000) as homed:
            controller.home("NORMAL")
        assert homed.args[0].ok
        lines = motion_program(30)
        progress = on_gui(worker.progress_changed)
        controller.start_job(lines)
        with qtbot.waitSignal(progress, timeout=10000, check_params_cb=lambda e: e.done >= 3):
            pass
        with qtbot.waitSignal(on_gui(worker.disconnected, text=True), timeout=5000) as gone:
            opener.sim.faults.unplug()
        assert "failed" in gone.args[0]  # read or write, whichever the worker tried first
        opener.sim.faults.replug()
        with qtbot.waitSignal(on_gui(worker.resume_offered), timeout=10000) as offered:
            controller.connect_to("sim://")
        assert offered.args[0].same_boot
        with qtbot.waitSignal(on_gui(worker.job_finished), timeout=30000) as finished:
            controller.resume_after_reconnect()
        assert finished.args[0].completed
        assert_oracle(list(opener.sim.exec_log), lines)
    finally:
        assert controller.shutdown()
        opener.sim.stop()
