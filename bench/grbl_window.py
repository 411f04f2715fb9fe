"""The window streaming to a machine on a real pseudo-terminal, for ``bench_grbl``: the GUI's
stall (the lateness of a 10 ms timer on the GUI thread, goal <= 50 ms) while the window
streams a job in check mode, beside what explains it: each busy thread's time on a CPU
and waiting for one (the scheduler's own count), the worker's signals per second (what
reaches the GUI thread), the garbage collector's pauses, when the stalls came, and the
load average. ``driver`` "grbl" streams to ``cnc-sim --grbl --pty`` (115200 baud, real
time; share of the character-counting ceiling), "frame" to ``cnc-sim --pty --speed 2``
(the student mill's protocol, as ``bench_ui`` does): the same window, job and figures.
``BENCH_GRBL_PUMP_MS`` tries another pump period of the worker for GRBL;
``BENCH_GRBL_VERBOSE=1`` streams with the console showing every line each way.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BAUD = 115200


class _Collections:
    """How long the garbage collector held every thread (``gc.callbacks``), per generation."""

    def __init__(self) -> None:
        self.times: dict[int, list[float]] = {0: [], 1: [], 2: []}
        self._began = 0.0

    def __call__(self, phase: str, info: dict) -> None:
        if phase == "start":
            self._began = time.perf_counter()
        else:
            self.times[info["generation"]].append(time.perf_counter() - self._began)

    def __enter__(self):
        import gc

        gc.callbacks.append(self)
        return self

    def __exit__(self, *exc) -> None:
        import gc

        gc.callbacks.remove(self)

    def describe(self) -> str:
        return ", ".join(f"gen {g}: {len(t)} taking at most {max(t, default=0) * 1000:.1f} ms"
                         for g, t in self.times.items())


class _Timeline:
    """When the event loop was late by more than 50 ms, in seconds after the start: a
    10 ms timer of its own beside the bench's probe."""

    def __init__(self) -> None:
        from PySide6.QtCore import Qt, QTimer

        self.late: list[tuple[float, float]] = []
        self.timer = QTimer(interval=10, timeout=self._tick)
        self.timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._start = self._last = 0.0

    def _tick(self) -> None:
        now = time.perf_counter()
        if now - self._last - 0.010 > 0.05:
            self.late.append((self._last - self._start, now - self._last - 0.010))
        self._last = now

    def __enter__(self):
        self._start = self._last = time.perf_counter()
        self.timer.start()
        return self

    def __exit__(self, *exc) -> None:
        self.timer.stop()

    def describe(self) -> str:
        worst = sorted(self.late, key=lambda x: -x[1])[:8]
        return "stalls over 50 ms (s after Start: ms): " + (", ".join(
            f"{at:.1f}: {ms * 1000:.0f}" for at, ms in sorted(worst)) or "none")


def _thread_times() -> dict[int, tuple[str, float, float]]:
    """Per thread of this process (by its id): its name, seconds on a CPU and seconds
    runnable but waiting for one, from the scheduler's own count (Linux ``schedstat``)."""
    times = {}
    for task in Path("/proc/self/task").iterdir():
        try:
            name = (task / "comm").read_text().strip()
            ran, waited = (int(x) / 1e9 for x in (task / "schedstat").read_text().split()[:2])
        except (OSError, ValueError):
            continue
        times[int(task.name)] = (name, ran, waited)
    return times


def _times_since(before: dict[int, tuple[str, float, float]], seconds: float) -> str:
    """Each busy thread's share of the wall time on a CPU, and waiting for one."""
    after = _thread_times()
    used = [(name, ran - before.get(tid, ("", 0.0, 0.0))[1], waited - before.get(tid, ("", 0.0, 0.0))[2])
            for tid, (name, ran, waited) in after.items()]
    top = sorted(used, key=lambda u: -u[1])[:3]
    return ", ".join(f"{name} {ran / seconds:.0%} running, {waited / seconds:.0%} waiting for a CPU"
                     for name, ran, waited in top if ran / seconds >= 0.005)


SIGNALS = ("state_changed", "status_changed", "progress_changed", "link_changed", "log_added", "frame_logged",
           "command_finished", "alarm_raised", "error_occurred")


def _count_signals(worker) -> dict[str, int]:
    """How many times each of the worker's signals is emitted (counted where it is emitted)."""
    from PySide6.QtCore import Qt

    counts = dict.fromkeys(SIGNALS, 0)
    for name in SIGNALS:
        def count(*_, name=name):
            counts[name] += 1
        getattr(worker, name).connect(count, Qt.ConnectionType.DirectConnection)
    return counts


def _head(path, lines: int, folder):
    """``path`` cut to its first ``lines`` source lines (the whole file when it has fewer)."""
    with path.open() as src:
        head = [line for _, line in zip(range(lines), src, strict=False)]
    if len(head) < lines:
        return path
    cut = folder / f"head_{lines}.ngc"
    cut.write_text("".join(head) + "M5\nM2\n")
    return cut


def _step(ok: bool, what: str) -> None:
    if not ok:
        raise RuntimeError(f"bench_grbl: no {what} from the simulator")


def _machine(driver: str, folder: Path):
    args = ["--grbl", "--pty"] if driver == "grbl" else ["--pty", "--speed", "2", "--sd", str(folder)]
    proc = subprocess.Popen([sys.executable, "-m", "backend_sim", *args], stdout=subprocess.PIPE, text=True)
    return proc, proc.stdout.readline().split()[-1]


def _ready(app, window, driver: str) -> None:
    """Connected with ``driver``, unlocked and in check mode."""
    from app.ui.connection_bar import DRIVERS
    from bench.bench_ui import _wait

    binder = window.binder
    _step(_wait(app, lambda: binder.status is not None, 30), "status")
    if driver == "grbl":
        window.link.call("send_command", "$X")
        _step(_wait(app, lambda: binder.status.state == "IDLE", 30), "unlock")
    window.controls.check_mode.setChecked(True)
    _step(_wait(app, lambda: binder.status.state == "IDLE" and window.controls.check_mode.isChecked()
                and getattr(window.link.worker.session, "check_mode", True), 30), "check mode")
    assert window.connection.driver_choice() == driver, [key for key, _ in DRIVERS]


def bench_window(lines_limit: int = 100_000, driver: str = "grbl") -> None:
    """The window streaming bench_ui's job (100,000 device lines), or its first
    ``lines_limit`` source lines (see the module)."""
    from app.ui.connection_bar import DRIVERS
    from bench.bench_ui import JOB_LINES, _describe, _lateness, _wait, _window, job_file

    pump_ms = os.environ.get("BENCH_GRBL_PUMP_MS")
    if pump_ms:
        from app.comm import worker

        worker.GRBL_PUMP_MS = int(pump_ms)
    with tempfile.TemporaryDirectory() as config:
        app, window = _window(Path(config))
        binder = window.binder
        job = job_file()
        window.open_file(job if lines_limit >= JOB_LINES else _head(job, lines_limit, Path(config)))
        _wait(app, lambda: window.loaded is not None, 120)
        proc, pty = _machine(driver, Path(config) / "sd")
        try:
            window.connection.driver.setCurrentIndex([key for key, _ in DRIVERS].index(driver))
            window.operator.connect_to(pty)
            _ready(app, window, driver)
            if os.environ.get("BENCH_GRBL_VERBOSE") == "1":
                window.console.show_stream.setChecked(True)
                window.link.call("set_verbose_frames", True)
            idle_before = _thread_times()
            idle = _lateness(app, 5.0)
            idle_threads = _times_since(idle_before, 5.0)
            load_before = os.getloadavg()[0]
            times_before = _thread_times()
            emitted = _count_signals(window.link.worker)
            started = time.monotonic()
            window.operator.start()
            trace = os.environ.get("BENCH_UI_TRACE") == "1"  # where the GUI thread was when late
            with _Collections() as collections, _Timeline() as timeline:
                busy = _lateness(app, 900.0, lambda: binder.last_job_event is not None, trace)
            took = time.monotonic() - started
            threads = _times_since(times_before, took)
            event = binder.last_job_event
        finally:
            window.close()
            proc.terminate()
            proc.wait(5)
    lines = window.loaded.program.device_lines
    if driver == "grbl":
        sent = sum(len(line) + 1 for line in lines) + len("$G\nG21 G90 G94 G17\nG4 P0\n")
        ceiling = sent * 10 / BAUD
        share = f"; ceiling {ceiling:.1f} s, share {ceiling / took:.1%}"
    else:
        share = ""
    machine = "cnc-sim --grbl --pty" if driver == "grbl" else "cnc-sim --pty --speed 2 (the mill's protocol)"
    print(f"window -> {machine}, check mode: {len(lines):,} lines in {took:.1f} s "
          f"({len(lines) / took:,.0f} lines/s{share}); completed {event.completed if event else None}")
    print(f"  10 ms timer lateness while streaming: {_describe(busy)} (goal max <= 50 ms)")
    print(f"  {timeline.describe()}")
    print(f"  threads while streaming: {threads}")
    per_second = ", ".join(f"{name} {n / took:.1f}" for name, n in emitted.items() if n)
    print(f"  worker signals per second: {per_second}")
    print(f"  garbage collections while streaming: {collections.describe()}")
    print(f"  same timer, window idle, 5 s before: {_describe(idle)}; load average {load_before:.1f} at the "
          f"start, {os.getloadavg()[0]:.1f} at the end ({os.cpu_count()} cores)")
    print(f"  threads, window idle: {idle_threads}")
