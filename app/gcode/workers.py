"""A second core for loading big programs: one helper process that runs part of a scan.

The fast path (``bulk.py``) reads a file chunk by chunk, and chunks are independent,
so a big file's tail can be scanned by another process while this one scans its head.
Most of that work holds the GIL (``bytes.translate``, ``re``, numpy's text parser),
so a thread would not help; a process does.

``submit(fn, *args)`` hands a call to the helper and returns a ``Future``, or ``None``
when there is no second core or the helper is not running (yet); ``result(future)`` is
its value, or ``None`` when the helper failed (the caller then does the work itself,
so a broken helper costs time, never a result). The helper is a child of a
forkserver (a fresh, thread-free interpreter, so forking it is safe even from a GUI
with threads) or, where there is none, a spawned interpreter. It starts on first use,
which takes a few tenths of a second on a thread of its own: until it answers, loads
simply run alone. ``warm_up()`` starts it ahead of time (the GUI does so when it
opens, the benchmark before timing). It is shut down when the interpreter exits. As with any use of
``multiprocessing``, a script that loads programs keeps its top level under
``if __name__ == "__main__":`` (the helper imports the main module).
"""

from __future__ import annotations

import atexit
import contextlib
import os
import sys
import threading
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # multiprocessing and concurrent.futures are imported when the helper starts
    from concurrent.futures import Future, ProcessPoolExecutor

PIPE_BYTES = 1 << 20  # Linux lets any process have pipes this big (fs.pipe-max-size)
PRELOAD = ["app.gcode.bulk"]  # imported once by the forkserver, not by every helper
_lock = threading.Lock()
_pool: ProcessPoolExecutor | None = None
_starting = False
_ready = threading.Event()
_disabled = False


def available() -> bool:
    """True when a helper may be used: more than one core, and not disabled."""
    if _disabled or (os.cpu_count() or 1) < 2:
        return False
    mp = sys.modules.get("multiprocessing")  # a helper has it imported; a fresh CLI need not
    parent = getattr(mp, "parent_process", None)  # absent while the helper's start-up thread
    return parent is None or parent() is None  # is still importing it here; never a helper's helper


def _context():
    import multiprocessing

    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("forkserver" if "forkserver" in methods else "spawn")
    if ctx.get_start_method() == "forkserver":
        ctx.set_forkserver_preload(PRELOAD)
    return ctx


def _executor() -> ProcessPoolExecutor | None:
    """The helper's pool once it is running; until then ``None``, and it is started
    on a thread (starting blocks for a few tenths of a second: never make a load wait)."""
    global _starting
    with _lock:
        if _pool is not None or not available():
            return _pool
        if not _starting:
            _starting = True
            threading.Thread(target=_start, name="gcode-helper-start", daemon=True).start()
        return None


def _start() -> None:
    global _pool, _disabled, _starting
    from concurrent.futures import ProcessPoolExecutor

    try:
        pool = ProcessPoolExecutor(max_workers=1, mp_context=_context())
        _widen_pipes(pool)
        pool.submit(int).result()  # the helper process exists and answers
    except Exception:  # no semaphores, no pipes, no processes: work alone
        with _lock:
            _disabled, _starting = True, False
        return
    with _lock:
        _starting = False
        if not _disabled:
            _pool = pool
            _ready.set()
            atexit.register(_drop, pool)  # before the late-imported pool modules are torn down
    if _pool is not pool:  # forbidden while it started
        pool.shutdown(wait=False)


def _widen_pipes(pool: ProcessPoolExecutor) -> None:
    """Pipes of PIPE_BYTES to and from the helper, where the system allows (Linux): a
    group's 1.5 MB of source then crosses in two writes, not 24 of 64 kB, each of which
    waits for the other side to be scheduled (measured: 6.0 -> 1.3 ms a group)."""
    try:
        import fcntl
    except ImportError:  # Windows
        return
    setpipe = getattr(fcntl, "F_SETPIPE_SZ", None)
    ends = (("_call_queue", "_writer"), ("_result_queue", "_reader"))  # the pool's own, if it has them
    for end in (getattr(getattr(pool, queue, None), name, None) for queue, name in ends):
        with contextlib.suppress(OSError, ValueError, AttributeError, TypeError):
            fcntl.fcntl(end.fileno(), setpipe, PIPE_BYTES)


def _drop(pool: ProcessPoolExecutor) -> None:
    global _pool
    with _lock:
        if _pool is pool:
            _pool = None
            _ready.clear()
    pool.shutdown(wait=False, cancel_futures=True)


def ready() -> bool:
    """True when the helper is running (when it is not, this starts it)."""
    return _executor() is not None


def submit(fn, *args) -> Future | None:
    """Run ``fn(*args)`` in the helper (``fn`` importable at module level), or ``None``."""
    pool = _executor()
    if pool is None:
        return None
    from concurrent.futures.process import BrokenProcessPool

    try:
        return pool.submit(fn, *args)
    except (BrokenProcessPool, RuntimeError, OSError):
        _drop(pool)
        return None


def result(future: Future | None):
    """The helper's result, or ``None`` when it failed (the caller falls back)."""
    if future is None:
        return None
    from concurrent.futures.process import BrokenProcessPool

    try:
        return future.result()
    except BrokenProcessPool:
        if _pool is not None:
            _drop(_pool)
        return None
    except Exception:  # a bug raises again when the caller does the work itself
        return None


def warm_up(wait: float = 0.0) -> bool:
    """Start the helper now; wait up to ``wait`` seconds for it. True when it is ready."""
    _executor()
    return _ready.wait(wait) if available() else False


def helper_pids() -> list[int]:
    """Process ids of the running helper (for measuring it; empty when there is none)."""
    pool = _pool
    return list(getattr(pool, "_processes", None) or {}) if pool is not None else []


def enabled() -> bool:
    """False once the helper is forbidden (``set_enabled``) or found unusable."""
    return not _disabled


def set_enabled(enabled: bool) -> None:
    """Allow or forbid the helper (tests compare both; a forbidden one is shut down)."""
    global _disabled
    _disabled = not enabled
    if not enabled and _pool is not None:
        _drop(_pool)
