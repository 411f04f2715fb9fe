"""A second core for a one-shot load: a forked child scans the tail of a big file.

The window keeps a helper process warm (``workers.py``); a single ``cnc-gcode`` run has
none, and starting one costs more than it would save. A process that has read its file
can fork instead: the child already holds the bytes and every module, scans groups of
chunks from the last one back (as the helper does) and sends each group's words back
through a pipe; the parent scans from the first group on and takes a group from the
child when the child has finished it, else scans it itself. Each side stops where the
other has been (the parent's position is in a word of shared memory), so no group is
scanned twice for long. A child that fails simply sends nothing: the parent then does
every group, as without it.

Only on Linux (macOS's system libraries are not fork-safe, Windows has no fork), only
when allowed (``allowed()``: the command line turns it on for its own load), only while
the process runs a single thread (forking a process with threads can leave the child
holding a lock no one will release), and only when the machine has a core to spare
(``usable``): at least half a core stood idle since this module was imported (the
machine's idle time in ``/proc/stat``, over the ~0.1 s of start-up and reading), else,
where that cannot be told, by the last minute's load average.
"""

from __future__ import annotations

import contextlib
import fcntl
import mmap
import os
import pickle
import signal
import struct
import sys
import threading
import time

_allowed = False
PIPE_BYTES = 1 << 20  # Linux lets any process have pipes this big (fs.pipe-max-size)
MIN_WATCH_S = 0.03  # the idle time of a shorter span is too coarse (it counts in 10 ms ticks)


def _idle_now() -> tuple[float, float] | None:
    """(monotonic seconds, seconds every core has stood idle since boot), or None where
    ``/proc/stat`` cannot tell."""
    try:
        with open("/proc/stat", "rb") as stat:
            fields = stat.readline().split()
        ticks = os.sysconf("SC_CLK_TCK")
        return time.monotonic(), (int(fields[4]) + int(fields[5])) / ticks  # idle, iowait
    except (OSError, ValueError, IndexError):
        return None


_WATCHED_FROM = _idle_now()  # (this module is imported early in a load: see cli.py)


def spare_core() -> bool | None:
    """True when at least half a core stood idle since this module was imported (a
    forked child then runs beside this process instead of taking turns with it); None
    when that cannot be told (no ``/proc/stat``, or too short a time to tell)."""
    now = _idle_now()
    if now is None or _WATCHED_FROM is None or now[0] - _WATCHED_FROM[0] < MIN_WATCH_S:
        return None
    return now[1] - _WATCHED_FROM[1] >= 0.5 * (now[0] - _WATCHED_FROM[0])


@contextlib.contextmanager
def allowed():
    """Let loads inside this block fork a child for their scan (see the module docstring)."""
    global _allowed
    was, _allowed = _allowed, True
    try:
        yield
    finally:
        _allowed = was


def usable() -> bool:
    """True when a load may fork now: allowed, one thread, and a core to spare
    (``spare_core``; where it cannot tell, the last minute's load average at most the
    cores less one, which a command run just before raises by about 1 for a minute).
    Measured on 2 cores: quiet, the load took 0.67-0.73 s with the child against
    0.72-0.78 s alone (far.ngc, 8 runs each); at load 2-3 the child only took turns with
    its parent and the load took longer (0.95 s against 0.82 s)."""
    if not (_allowed and sys.platform.startswith("linux") and threading.active_count() == 1):
        return False  # (macOS's system libraries are not fork-safe; Windows has no fork)
    spare = spare_core()
    if spare is not None:
        return spare
    try:
        busy = os.getloadavg()[0]
    except OSError:  # not known: as if idle
        busy = 0.0
    return busy <= (os.cpu_count() or 1) - 1


class Tail:
    """Groups ``1..len(groups)-1`` of ``fn(data, group)`` computed by a forked child,
    from the last one back; ``take(k)`` gives group ``k``'s result, or ``None`` when the
    child has not sent it (the caller then computes it), and marks where the parent is."""

    def __init__(self, fn, data: bytes, groups: list):
        self._results: dict[int, object] = {}
        self._lock = threading.Lock()
        self._reached = mmap.mmap(-1, 8)  # shared with the child: the group the parent is at
        read_end, write_end = os.pipe()
        with contextlib.suppress(OSError, AttributeError):  # a group's words (~2 MB) in fewer turns:
            fcntl.fcntl(write_end, fcntl.F_SETPIPE_SZ, PIPE_BYTES)  # the child waits less on this reader
        self.pid = os.fork()
        if self.pid == 0:  # the child: never returns
            os.close(read_end)
            _child(fn, data, groups, write_end, self._reached)
        os.close(write_end)
        self._pipe = os.fdopen(read_end, "rb", buffering=1 << 20)
        self._reader = threading.Thread(target=self._read, name="gcode-scan-tail", daemon=True)
        self._reader.start()

    def _read(self) -> None:
        with contextlib.suppress(Exception):  # end of the pipe, or a child that died mid-way
            while True:
                k, result = pickle.load(self._pipe)
                with self._lock:
                    self._results[k] = result

    def take(self, k: int):
        """Group ``k``'s result if the child has sent it, else ``None``."""
        self._reached[:8] = struct.pack("q", k)
        with self._lock:
            return self._results.pop(k, None)

    def close(self) -> None:
        """Stop the child (it may be scanning a group the parent has done) and reap it."""
        with contextlib.suppress(ProcessLookupError):
            os.kill(self.pid, signal.SIGKILL)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(self.pid, 0)
        self._reader.join()
        self._pipe.close()
        self._reached.close()


def _child(fn, data: bytes, groups: list, write_end: int, reached: mmap.mmap) -> None:
    try:
        with contextlib.suppress(BaseException), os.fdopen(write_end, "wb") as out:  # on any
            for k in range(len(groups) - 1, 0, -1):  # failure the parent does the rest itself
                if struct.unpack("q", reached[:8])[0] >= k:  # the parent is there already
                    break
                pickle.dump((k, fn(data, groups[k])), out, protocol=pickle.HIGHEST_PROTOCOL)
                out.flush()
    finally:
        os._exit(0)
