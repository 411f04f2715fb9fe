"""Tiny dense linear algebra for the motor discretisation (no scipy on the target).

``expm(a)`` is the matrix exponential by scaling and squaring of a Taylor series, exact
to float precision for the small, well-conditioned matrices of a motor model. It runs
once per profile, never in the 1 kHz loop.
"""

from __future__ import annotations

import numpy as np


def expm(a: np.ndarray) -> np.ndarray:
    """exp(a) for a small square matrix."""
    a = np.asarray(a, dtype=float)
    norm = float(np.max(np.sum(np.abs(a), axis=1))) if a.size else 0.0
    squarings = max(0, int(np.ceil(np.log2(norm))) + 4) if norm > 0 else 0
    scaled = a / (2.0**squarings)
    result = np.eye(a.shape[0])
    term = np.eye(a.shape[0])
    for k in range(1, 30):
        term = term @ scaled / k
        result = result + term
    for _ in range(squarings):
        result = result @ result
    return result


def zoh(a: np.ndarray, b: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Exact zero-order-hold discretisation: x[k+1] = ad x[k] + bd u[k]."""
    n, m = a.shape[0], b.shape[1]
    big = np.zeros((n + m, n + m))
    big[:n, :n] = a
    big[:n, n:] = b
    e = expm(big * dt)
    return e[:n, :n], e[:n, n:]
