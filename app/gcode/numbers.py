"""Device number format: millimetres rounded to 0.001, no trailing zeros, never -0."""

from __future__ import annotations

import numpy as np


def milli(values) -> np.ndarray:
    """Values rounded to whole thousandths, as int64 (the device's resolution)."""
    return np.rint(np.asarray(values, dtype=np.float64) * 1000.0).astype(np.int64)


def rounded(values) -> np.ndarray:
    """Values rounded to 0.001 as floats, bit-identical to parsing their printed form."""
    return milli(values) / 1000.0


def fmt(k: int) -> str:
    """Format a number of thousandths: 10000 -> '10', 1500 -> '1.5', -250 -> '-0.25'."""
    sign = "-" if k < 0 else ""
    whole, frac = divmod(abs(k), 1000)
    if frac == 0:
        return f"{sign}{whole}"
    return f"{sign}{whole}.{frac:03d}".rstrip("0")
