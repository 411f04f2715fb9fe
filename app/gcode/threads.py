"""Numpy work on the machine's two cores within one process (no Qt)."""

from __future__ import annotations


def on_two_threads(fn, items, name: str = "numpy") -> list:
    """``[fn(item) for item in items]`` on two threads: numpy's arithmetic, sorts and
    gathers let the GIL go, so both run at once (``name``: the threads' name prefix)."""
    from concurrent.futures import ThreadPoolExecutor  # only here: a CLI start-up need not load it

    with ThreadPoolExecutor(max_workers=2, thread_name_prefix=name) as pool:
        return list(pool.map(fn, items))
