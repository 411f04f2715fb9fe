"""How fast this machine is right now, for reading the other figures.

On a shared virtual machine the same code runs 10-50% slower on some days, and our
Python and numpy slow down more than the compiled peers do. ``state()`` times three
fixed kernels so that a reader can tell a slow day from a regression: compare this
line between the runs whose figures are compared.
"""

from __future__ import annotations

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
