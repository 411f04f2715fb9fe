"""Helpers shared by the tests of the scan's parallel paths (helper process, forked child)."""

import numpy as np

from app.gcode import bulk


def assert_same_scan(a: bulk.Scan, b: bulk.Scan) -> None:
    """Every column of the two scans is equal."""
    np.testing.assert_array_equal(a.simple, b.simple)
    np.testing.assert_array_equal(a.g, b.g)
    np.testing.assert_array_equal(a.units, b.units)
    for letter in a.values:
        np.testing.assert_array_equal(a.values[letter], b.values[letter])
