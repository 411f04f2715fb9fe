"""The device's number format, one at a time (``fmt``) and many at once (``texts``):
the same text for every value the device can be sent."""

import numpy as np
import pytest

from app.gcode.numbers import fmt, texts

EDGES = [0, 1, -1, 5, -5, 10, -10, 100, 999, -999, 1000, -1000, 1001, -1001, 1500, -250, 1010, 1100,
         123456, -123456, 10**9, -(10**9), 2**62, -(2**62)]


@pytest.mark.parametrize("prefix", ["", " X", " F"])
def test_texts_write_what_fmt_writes(prefix):
    rng = np.random.default_rng(24)
    values = np.concatenate([EDGES, rng.integers(-(10**7), 10**7, 20_000), rng.integers(-(2**62), 2**62, 500),
                             rng.integers(-2000, 2000, 2000) * 10])
    assert list(texts(values, prefix)) == [prefix + fmt(int(v)) for v in values]


def test_texts_of_nothing_is_empty():
    assert texts(np.empty(0, np.int64), " X").tolist() == []


def test_fmt_drops_trailing_zeros_and_never_writes_minus_zero():
    written = [fmt(k) for k in (10000, 1500, -250, 0, -0, 1, -1)]
    assert written == ["10", "1.5", "-0.25", "0", "0", "0.001", "-0.001"]
