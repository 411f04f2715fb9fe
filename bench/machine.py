"""How fast this machine is right now, for reading the other figures.

On a shared virtual machine the same code runs 10-50% slower on some days, and our
Python and numpy slow down more than the compiled peers do. ``state()`` times three
fixed kernels so that a reader can tell a slow day from a regression: compare this
line between the runs whose figures are compared. ``stolen()`` is the CPU time the
virtual machine's host has taken from it (Linux's steal time): on a shared host it
reached 1-2 s in a 3 s load, which no calibration before or after a bench can show.
"""

from __future__ import annotations

import os
import time

import numpy as np

LOOP_STEPS = 10_000_000
SORT_VALUES = 10_000_000
FRESH_MB = 256


def _best(fn, runs: int = 3) -> float:
    best = float("inf")
    for _ in range(runs):
        started = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - started)
    return best


def _loop() -> None:
    for _ in range(LOOP_STEPS):
        pass


def state() -> str:
    """One line: the best of 3 of a Python loop, a numpy sort and a first touch of fresh
    memory (what a big load spends its page faults on)."""
    values = np.random.default_rng(0).random(SORT_VALUES)
    loop = _best(_loop)
    sort = _best(lambda: np.sort(values))
    fresh = _best(lambda: np.ones(FRESH_MB << 17))  # 8-byte values: FRESH_MB MB, touched once
    return (f"this machine now: a {LOOP_STEPS // 1_000_000} M-step Python loop {loop:.2f} s, a sort of "
            f"{SORT_VALUES // 1_000_000} M doubles {sort:.2f} s, {FRESH_MB} MB of fresh memory filled "
            f"{fresh:.2f} s (best of 3 each)")


def stolen() -> float | None:
    """Seconds of CPU the host has taken from this virtual machine since it booted, over
    every core (the steal column of ``/proc/stat``), or None where that is not known."""
    try:
        with open("/proc/stat", "rb") as stat:
            fields = stat.readline().split()
        return int(fields[8]) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError):
        return None


def stolen_since(before: float | None) -> str:
    """A clause for a figure's line: the CPU seconds the host took since ``before`` (a
    ``stolen()``), or "" where that is not known."""
    now = stolen()
    if before is None or now is None:
        return ""
    return f"; the host took {now - before:.1f} s of CPU from this machine meanwhile (steal time)"
