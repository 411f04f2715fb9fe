"""``vector._ffill``, the fast path's modal fill: each NaN takes the last number before it
(the state's value at the start), whatever mix of words and gaps a run has."""

import numpy as np
import pytest

from app.gcode.vector import _ffill


def _reference(values, first):
    out, last = [], first
    for v in values:
        last = last if np.isnan(v) else v
        out.append(last)
    return np.array(out, float)


@pytest.mark.parametrize("first", [0.0, -0.0, 7.5, np.nan])
@pytest.mark.parametrize("share", [0.0, 0.01, 0.5, 0.99, 1.0])  # of lines with the word
def test_a_fill_is_the_last_number_before_each_gap(first, share):
    rng = np.random.default_rng(24)
    for n in (0, 1, 2, 17, 1000):
        values = rng.normal(size=n)
        values[rng.random(n) >= share] = np.nan
        values[rng.random(n) < 0.1] = -0.0  # a signed zero keeps its sign
        filled = _ffill(values, first)
        assert filled.dtype == np.float64 and filled.shape == (n,)
        np.testing.assert_array_equal(filled, _reference(values, first))
        assert np.array_equal(np.signbit(filled), np.signbit(_reference(values, first)))
