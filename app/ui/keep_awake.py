"""Keep the computer from sleeping while a job runs, where the platform allows.

Linux: ``systemd-inhibit`` holding a lock with a sleeping child; macOS: ``caffeinate``;
Windows: ``SetThreadExecutionState``. Best effort: if none is available nothing
happens, and nothing here ever raises.
"""

from __future__ import annotations

import shutil
import subprocess
import sys


class KeepAwake:
    def __init__(self):
        self._process: subprocess.Popen | None = None
        self.active = False
        self.method = ""

    def start(self, why: str = "CNC job running") -> bool:
        if self.active:
            return True
        try:
            self.active = self._start(why)
        except (OSError, AttributeError, ValueError):
            self.active = False
        return self.active

    def _start(self, why: str) -> bool:
        if sys.platform == "win32":
            import ctypes

            flags = 0x80000000 | 0x00000001  # ES_CONTINUOUS | ES_SYSTEM_REQUIRED
            self.method = "SetThreadExecutionState"
            return bool(ctypes.windll.kernel32.SetThreadExecutionState(flags))
        tool = shutil.which("caffeinate") if sys.platform == "darwin" else shutil.which("systemd-inhibit")
        if tool is None:
            return False
        if sys.platform == "darwin":
            args = [tool, "-i", "-w", str(_own_pid())]
        else:
            args = [tool, "--what=sleep:idle", "--who=cnc-gui", f"--why={why}", "--mode=block"]
            args += ["sleep", "infinity"]
        self._process = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.method = tool
        return True

    def stop(self) -> None:
        if not self.active:
            return
        self.active = False
        try:
            if sys.platform == "win32":
                import ctypes

                ctypes.windll.kernel32.SetThreadExecutionState(0x80000000)
            elif self._process is not None:
                self._process.terminate()
                self._process.wait(timeout=2)
        except (OSError, AttributeError, subprocess.TimeoutExpired):
            pass
        self._process = None


def _own_pid() -> int:
    import os

    return os.getpid()
