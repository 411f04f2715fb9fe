"""OpBuffer: rows written in place, in room made ahead and doubled when full, give the
same Ops as rows joined at the end, whatever the room; the starts are a view."""

import numpy as np
import pytest

from app.gcode.ops import ARC_CW, FEED, PAUSE, XZ, OpBuffer


def _fill(buffer: OpBuffer, rng) -> list[tuple]:
    """Rows added one at a time and in blocks, mixed; each row as a tuple, in order."""
    expected = []
    line = 1
    for _ in range(40):
        if rng.random() < 0.5:
            n = int(rng.integers(1, 50))
            end, center = rng.normal(size=(n, 3)), rng.normal(size=(n, 3))
            kind = rng.choice([FEED, ARC_CW], size=n).astype(np.int8)
            turn, value = rng.integers(-2, 3, size=n).astype(np.int32), rng.random(n)
            plane = rng.integers(0, 3, size=n).astype(np.int8)
            lines = np.arange(line, line + n)
            buffer.add_block(lines, kind, end, center, turn, value, plane=plane)
            expected += [(int(lines[i]), int(kind[i]), *end[i], *center[i], int(plane[i]), int(turn[i]),
                          value[i]) for i in range(n)]
            line += n
        else:
            end = tuple(rng.normal(size=3))
            buffer.add(line, PAUSE, end, plane=XZ, turn=1, value=2.5, message=f"stop {line}")
            expected.append((line, PAUSE, *end, *(np.nan,) * 3, XZ, 1, 2.5))
            line += 1
    return expected


@pytest.mark.parametrize("reserve", [0, 1, 7, 100_000])
def test_rows_come_back_in_order_whatever_the_room(reserve):
    rng = np.random.default_rng(reserve)
    buffer = OpBuffer(reserve=reserve)
    expected = _fill(buffer, rng)
    ops = buffer.finish()
    got = np.column_stack([ops.line, ops.kind, ops.end, ops.center, ops.plane, ops.turn, ops.value])
    np.testing.assert_array_equal(got, np.array(expected, float))
    assert ops.messages == [f"stop {int(row[0])}" for row in expected if row[1] == PAUSE]
    assert (ops.line.dtype, ops.kind.dtype, ops.turn.dtype) == (np.int64, np.int8, np.int32)


def test_the_starts_are_a_view_of_the_ends_from_the_origin():
    buffer = OpBuffer(reserve=3)  # outgrown: the view holds after the room doubled
    for i in range(10):
        buffer.add(i + 1, FEED, (float(i), 2.0 * i, 0.0))
    ops = buffer.finish()
    ops.origin = (5.0, 6.0, 7.0)
    starts = ops.starts()
    assert np.shares_memory(starts, ops.end)
    np.testing.assert_array_equal(starts[0], [5.0, 6.0, 7.0])
    np.testing.assert_array_equal(starts[1:], ops.end[:-1])


def test_an_empty_buffer_gives_empty_columns():
    ops = OpBuffer().finish()
    assert len(ops) == 0 and ops.end.shape == (0, 3) and ops.center.shape == (0, 3)
    assert ops.starts().shape == (0, 3)


def test_lines_from_renumbers_the_rows_written_since():
    buffer = OpBuffer(reserve=2)
    buffer.add(9, FEED, (1.0, 0.0, 0.0))
    buffer.flush()
    before = buffer.written
    nan3 = np.full((3, 3), np.nan)
    kind, turn = np.full(3, FEED, np.int8), np.zeros(3, np.int32)
    buffer.add_block(np.array([1, 2, 3]), kind, np.zeros((3, 3)), nan3, turn, np.zeros(3))
    buffer.lines_from(before)[:] = [40, 41, 42]
    np.testing.assert_array_equal(buffer.finish().line, [9, 40, 41, 42])
