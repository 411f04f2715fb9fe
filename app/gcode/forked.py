"""A second core for a one-shot load: a forked child shares the scan of a big file.

The window keeps a helper process warm (``workers.py``); a single ``cnc-gcode`` run has
none, and starting one costs more than it would save. A process that has read its file
can fork instead: the child already holds the bytes and every module. The scan's groups
of chunks are jobs taken in order (``Shared``): the parent interprets each group as it
comes, the child scans (and tables) the free groups from the second on and sends each
through a pipe, and the parent scans a free group ahead itself whenever the one it needs
next is still in the child's hands. A byte of shared memory per group says who has
claimed it, so no group is done twice (but when both claim it at the same instant).
(Before, the child scanned from the last group back and stopped where it met the
parent, then waited while the parent interpreted its groups; measured on arcs.ngc, 8
interleaved runs on 2 cores, both orders take the same 0.32 s median for the scan and
interpretation on a slow day, and this one leaves the child no idle end.) A child that
fails simply sends nothing: the parent then does every group, as without it.

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
import sys
import threading
import time

_allowed = False
PIPE_BYTES = 1 << 20  # Linux lets any process have pipes this big (fs.pipe-max-size)
STUCK_S = 1.0  # a job the child has held this long without a word is done here (each takes ~10 ms)
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


FREE, CHILD, PARENT = 0, 1, 2  # who has claimed a job (one byte each in shared memory)


class Shared:
    """``fn(k)`` for jobs ``k = 0 .. count - 1``, taken in order by this process and
    worked on by it and a forked child together.

    The child takes the free jobs from 1 on, in order, and sends each result through a
    pipe; ``take(k)`` gives job ``k``'s result: the child's when it has sent it, else
    this process's own. While the child is still busy with ``k``, this process works on
    the next free job instead (kept for later), so neither side waits while work is
    left. A job is claimed by a byte in shared memory before it is begun; when both
    sides claim one at the same instant, both do it and the results are the same. A
    child that fails or dies simply sends nothing more: this process then does the rest.
    ``received``: the jobs whose result came from the child."""

    def __init__(self, fn, count: int):
        self._fn = fn
        self._results: dict[int, object] = {}
        self._arrived = threading.Condition()
        self._next, self._child_gone = 0, False  # the job this process takes next
        self.received: list[int] = []
        self._claims = mmap.mmap(-1, max(count, 1))  # shared with the child: FREE, CHILD, PARENT
        self._claims[0] = PARENT
        read_end, write_end = os.pipe()
        with contextlib.suppress(OSError, AttributeError):  # a job's result (~2 MB) in fewer turns:
            fcntl.fcntl(write_end, fcntl.F_SETPIPE_SZ, PIPE_BYTES)  # the child waits less on this reader
        self.pid = os.fork()
        if self.pid == 0:  # the child: never returns
            os.close(read_end)
            _child(fn, count, write_end, self._claims)
        os.close(write_end)
        self._pipe = os.fdopen(read_end, "rb", buffering=1 << 20)
        self._reader = threading.Thread(target=self._read, name="gcode-scan-shared", daemon=True)
        self._reader.start()

    def _read(self) -> None:
        try:
            with contextlib.suppress(Exception):  # end of the pipe, or a child that died mid-way
                while True:
                    k, result = pickle.load(self._pipe)
                    with self._arrived:
                        if k >= self._next:  # (a job both sides did is kept once)
                            self._results[k] = result
                            self.received.append(k)
                        self._arrived.notify_all()
        finally:
            with self._arrived:
                self._child_gone = True
                self._arrived.notify_all()

    def take(self, k: int):
        """Job ``k``'s result (jobs are taken in order: 0, 1, 2, ...)."""
        self._next = k
        while True:
            with self._arrived:
                if k in self._results:
                    self._next = k + 1
                    return self._results.pop(k)
                job = k if self._claims[k] != CHILD or self._child_gone else self._claims.find(b"\0", k + 1)
                if job < 0:  # the child holds k and every later job is claimed: wait for k
                    if not self._arrived.wait(STUCK_S):
                        self._claims[k] = PARENT  # a child this slow is no help: do k here
                    continue
                self._claims[job] = PARENT
            result = self._fn(job)
            with self._arrived:  # (when both did a job, the child's copy is the one kept: ``received``)
                if job == k:
                    self._next = k + 1
                    return self._results.pop(k, result)
                self._results.setdefault(job, result)

    def close(self) -> None:
        """Stop the child (it may be on a job no longer needed) and reap it."""
        with contextlib.suppress(ProcessLookupError):
            os.kill(self.pid, signal.SIGKILL)
        with contextlib.suppress(ChildProcessError):
            os.waitpid(self.pid, 0)
        self._reader.join()
        self._pipe.close()
        self._claims.close()


def _child(fn, count: int, write_end: int, claims: mmap.mmap) -> None:
    try:
        with contextlib.suppress(BaseException), os.fdopen(write_end, "wb") as out:  # on any
            for k in range(1, count):  # failure the parent does the rest itself
                if claims[k] != FREE:
                    continue
                claims[k] = CHILD
                pickle.dump((k, fn(k)), out, protocol=pickle.HIGHEST_PROTOCOL)
                out.flush()
    finally:
        os._exit(0)
