"""Numpy work on the machine's two cores within one process (no Qt)."""

from __future__ import annotations

import threading
from functools import partial


def on_two_threads(fn, items, name: str = "numpy", second: threading.Event | None = None) -> list:
    """``[fn(item) for item in items]`` worked out by this thread and one more (``name``),
    each taking the next item as it is free: numpy's arithmetic, sorts and gathers let
    the GIL go, so both run at once. ``second``: the other thread takes no item before
    it is set (the other core is busy until then; this thread does every item left).
    Returns once every item taken is done; the first exception raised is raised here.
    (No ``concurrent.futures``: importing it costs a load 10 ms.)"""
    items = list(items)
    results: list = [None] * len(items)
    failed: list[BaseException] = []
    turns = iter(range(len(items)))
    taken = threading.Condition()
    busy = [0]  # items taken and not done

    def take() -> int | None:
        with taken:
            i = None if failed else next(turns, None)
            busy[0] += i is not None
            return i

    def work() -> None:
        while (i := take()) is not None:
            try:
                results[i] = fn(items[i])
            except BaseException as exc:  # neither thread takes another item
                failed.append(exc)
            finally:
                with taken:
                    busy[0] -= 1
                    taken.notify_all()

    def helper() -> None:
        if second is not None:
            second.wait()
        work()

    if len(items) > 1:
        threading.Thread(target=helper, name=name, daemon=True).start()
    work()
    with taken:
        taken.wait_for(lambda: busy[0] == 0)
    if failed:
        raise failed[0]
    return results


def in_order(fn, items, name: str = "") -> list:
    """``[fn(item) for item in items]`` on this thread (``on_two_threads``'s signature)."""
    return [fn(item) for item in items]


def each_on(threads: int = 1, second: threading.Event | None = None):
    """How to map work over blocks: ``in_order`` (``threads`` 1: beside a window, whose
    redraws wait for the GIL), or ``on_two_threads``, its second thread joining in once
    ``second`` is set (None: at once)."""
    return partial(on_two_threads, second=second) if threads > 1 else in_order
