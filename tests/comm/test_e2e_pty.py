"""End to end through real pyserial: the simulator as its own process on a pseudo-terminal.

``python -m backend_sim --pty --speed 5`` runs as a subprocess; the worker (on its
QThread, its timers on the wall clock: the machine keeps its link timers in wall time
at any speed factor) connects to the printed path. A
real Inkscape sample streams to the end (in check mode, so it is quick); then a job
in motion is cut off by killing the simulator process (the link loss shows within
3 s), a new process (a new boot id) is started, the worker reconnects, re-homes,
confirms, and the job restarts at done+1 to the end.
"""

import subprocess
import sys

import pytest
from PySide6.QtCore import QObject, Slot

from app.comm.worker import SerialController
from app.gcode import load

SAMPLE = "resources/samples/arcs_circles.ngc"
SPEED = "5"
"""A speed the simulator sustains on this machine, so the job's timing is realistic."""


class Collector:
    """Collects every worker signal in the test's thread, as a GUI would (QObject slots)."""

    NAMES = ("state_changed", "status_changed", "progress_changed", "link_changed",
             "command_finished", "job_finished", "error_occurred", "resume_offered")

    def __init__(self, worker) -> None:
        self.events: dict[str, list] = {name: [] for name in self.NAMES}
        self._sinks = [_Sink(self.events[name]) for name in self.NAMES]
        for name, sink in zip(self.NAMES, self._sinks, strict=True):
            getattr(worker, name).connect(sink.store)

    def last(self, name: str):
        return self.events[name][-1] if self.events[name] else None


class _Sink(QObject):
    def __init__(self, store: list) -> None:
        super().__init__()
        self._list = store

    @Slot(object)
    def store(self, event) -> None:
        self._list.append(event)


def start_sim(tmp_path, tag: str) -> tuple[subprocess.Popen, str]:
    profile = tmp_path / "fast_homing.toml"
    profile.write_text("[motion]\nhoming_mm_min = 900\n")
    proc = subprocess.Popen(
        [sys.executable, "-m", "backend_sim", "--pty", "--speed", SPEED, "--sd", str(tmp_path / "sd"),
         "--exec-log", str(tmp_path / f"exec-{tag}.log"), "--profile", str(profile)],
        stdout=subprocess.PIPE, text=True,
    )
    line = proc.stdout.readline().strip()
    assert line.startswith("PTY "), f"simulator said {line!r}"
    return proc, line.split(" ", 1)[1]


@pytest.fixture
def rig(qtbot, tmp_path):
    controller = SerialController()
    collector = Collector(controller.worker)
    controller.start()
    procs = []
    yield controller, collector, procs
    controller.shutdown()
    for proc in procs:
        proc.kill()
        proc.wait(5)
        proc.stdout.close()


def command(qtbot, controller, collector, text: str, timeout: int = 20000):
    before = len(collector.events["command_finished"])
    controller.send_command(text)
    qtbot.waitUntil(lambda: len(collector.events["command_finished"]) > before, timeout=timeout)
    result = collector.events["command_finished"][before]
    assert result.ok, result
    return result


@pytest.mark.slow
def test_pty_stream_kill_restart_resume(qtbot, tmp_path, rig):
    controller, collector, procs = rig
    lines = load(SAMPLE).device_lines
    proc, path = start_sim(tmp_path, "1")
    procs.append(proc)
    controller.connect_to(path)
    qtbot.waitUntil(lambda: collector.last("status_changed") is not None, timeout=10000)

    # 1. a real sample to the end (check mode: every line parsed and acknowledged)
    command(qtbot, controller, collector, "SET CHECK 1")
    controller.start_job(lines)
    qtbot.waitUntil(lambda: collector.last("job_finished") is not None, timeout=60000)
    job = collector.last("job_finished")
    assert job.completed and job.done == len(lines) - 1, job
    command(qtbot, controller, collector, "SET CHECK 0")

    # 2. in motion, killed mid-job: the link loss shows at once (within 3 s)
    command(qtbot, controller, collector, "HOME", timeout=60000)
    mark = len(collector.events["progress_changed"])
    controller.start_job(lines)
    progress = lambda: collector.events["progress_changed"][mark:] or [job]  # noqa: E731
    qtbot.waitUntil(lambda: progress()[-1].done >= 8 and progress()[-1] is not job, timeout=60000)
    proc.kill()
    proc.wait(5)
    qtbot.waitUntil(lambda: collector.last("link_changed").state in ("LOST", "DISCONNECTED"), timeout=3000)
    qtbot.waitUntil(lambda: collector.last("state_changed").new == "INTERRUPTED", timeout=3000)
    done = collector.last("progress_changed").done

    # 3. a new process is a new boot: re-home and confirm, then the job restarts at done+1
    proc, path = start_sim(tmp_path, "2")
    procs.append(proc)
    controller.connect_to(path)
    qtbot.waitUntil(lambda: collector.last("resume_offered") is not None, timeout=10000)
    offer = collector.last("resume_offered")
    assert not offer.same_boot and offer.needs_home and offer.from_seq == done + 1
    assert collector.last("state_changed").new == "RESTART_REQUIRED"
    command(qtbot, controller, collector, "HOME", timeout=60000)
    command(qtbot, controller, collector, "SET CHECK 1")
    finished = len(collector.events["job_finished"])
    controller.confirm_restart()
    qtbot.waitUntil(lambda: len(collector.events["job_finished"]) > finished, timeout=60000)
    job = collector.last("job_finished")
    assert job.completed and job.done == len(lines) - 1, job
    logged = (tmp_path / "exec-1.log").read_text().splitlines()
    checked, executed = logged[: len(lines)], logged[len(lines) :]  # the dry run, then the cut
    assert checked == [f"{seq}\t{line}" for seq, line in enumerate(lines)]
    assert [int(row.split("\t")[0]) for row in executed] == list(range(len(executed)))
    assert [row.split("\t", 1)[1] for row in executed] == lines[: len(executed)]
    assert done < len(executed) + 1  # the host never claims more than the machine finished
