"""``cnc-gui --demo``: open a file, connect to the simulator, home, run to the end,
save a screenshot, print one line. Driven by the worker's signals (no sleeping)."""

from __future__ import annotations

import time
from pathlib import Path

from PySide6.QtCore import QObject, QTimer
from PySide6.QtWidgets import QApplication


class DemoRunner(QObject):
    def __init__(self, window, path: Path, speed: float, screenshot: str | None):
        super().__init__(window)
        self.w = window
        self.path = path
        self.speed = speed
        self.screenshot = screenshot
        self.exit_code = 1
        self.outcome = "did not finish"
        self.started = time.monotonic()
        self.step = "open"
        worker = window.link.worker
        window.loader.loaded.connect(self._loaded)
        window.loader.failed.connect(self._load_failed)
        worker.connect_failed.connect(self._fail)
        worker.status_changed.connect(self._status)
        worker.command_finished.connect(self._command)
        worker.job_finished.connect(self._job_finished)
        self.deadline = QTimer(self, singleShot=True, timeout=self._timed_out)

    def start(self) -> None:
        self.deadline.start(600_000)
        self.w.open_file(self.path)

    def _loaded(self, loaded) -> None:
        if self.step != "open":
            return
        if loaded.program.errors:
            self._fail(f"{self.path.name} has errors")
            return
        estimate = loaded.program.toolpath.estimated_time
        self.deadline.start(int(1000 * (120 + 3 * estimate / max(self.speed, 0.01))))
        self.step = "connect"
        self.w.operator.connect_to(f"sim://?speed={self.speed:g}")

    def _load_failed(self, _path: str, text: str) -> None:
        self._fail(text)

    def _status(self, status) -> None:
        """Each step once the window's state table allows it (as an operator waits for the
        button to light up)."""
        if self.step == "connect" and self._allowed("home"):
            self.step = "home"
            self.w.operator.home("NORMAL")
        elif self.step == "homed" and status.homed and status.state == "IDLE" and self._allowed("start"):
            self.step = "run"
            self.w.operator.start()

    def _allowed(self, control: str) -> bool:
        from app.ui.state_table import decide

        return decide(control, self.w.binder.inputs()).allowed

    def _command(self, result) -> None:
        if self.step != "home" or result.verb != "HOME":
            return
        if not result.ok:
            self._fail(f"homing refused: {result.code} {result.info}")
            return
        self.step = "homed"

    def _job_finished(self, event) -> None:
        if self.step != "run" or event.kind != "job":
            return
        self.step = "done"
        status = self.w.binder.status
        where = f"X{status.x:.3f} Y{status.y:.3f} Z{status.z:.3f}" if status else "?"
        if event.completed:
            self.exit_code = 0
            self.outcome = f"completed {event.total} lines, final {where}"
        else:
            self.outcome = f"stopped at line {event.done + 1}/{event.total}: {event.reason}"
        QTimer.singleShot(300, self._finish)  # let the 30 Hz refresh show the end

    def _timed_out(self) -> None:
        self._fail(f"timed out at step {self.step}")

    def _fail(self, text: str) -> None:
        self.outcome = f"failed: {text}"
        self.exit_code = 1
        QTimer.singleShot(0, self._finish)

    def _finish(self) -> None:
        self.w.binder.tick()
        if self.screenshot:
            Path(self.screenshot).parent.mkdir(parents=True, exist_ok=True)
            self.w.grab().save(self.screenshot)
        self.w.close()
        QApplication.instance().quit()

    def summary(self) -> str:
        took = time.monotonic() - self.started
        shot = f"; screenshot {self.screenshot}" if self.screenshot else ""
        return f"demo {self.path.name} on sim at {self.speed:g}x: {self.outcome} in {took:.1f} s{shot}"
