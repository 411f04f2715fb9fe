"""The helper process that scans part of a big file: same result, and never needed."""

import os
from concurrent.futures import Future
from concurrent.futures.process import BrokenProcessPool

import numpy as np
import pytest

from app.gcode import bulk, load, sniff, workers
from app.gcode.source import chunks
from tests.gcode.scans import assert_same_scan, big_program

pytestmark = pytest.mark.skipif((os.cpu_count() or 1) < 2, reason="the helper needs a second core")


@pytest.fixture(scope="module")
def big() -> bytes:
    return big_program()


@pytest.fixture
def helper():
    workers.set_enabled(True)
    assert workers.warm_up(wait=60), "the helper process did not start"
    yield
    workers.set_enabled(True)


def test_the_helper_scans_exactly_what_this_process_scans(big, helper):
    parts = chunks(big)
    future = workers.submit(bulk.scan_chunks, big, parts)
    theirs, mine = workers.result(future), bulk.scan_chunks(big, parts)
    assert theirs is not None and len(theirs) == len(mine) == len(parts) > 8
    for a, b in zip(theirs, mine, strict=True):
        for x, y in zip(a, b, strict=True):
            np.testing.assert_array_equal(x, y)


def test_a_shared_scan_equals_a_scan_alone(big, helper):
    n = big.count(b"\n")
    shared = bulk.scan(big, n, share_bytes=0)
    workers.set_enabled(False)
    assert_same_scan(shared, bulk.scan(big, n))


def test_a_failed_helper_costs_time_not_the_result(big, monkeypatch):
    broken = Future()
    broken.set_exception(BrokenProcessPool("the helper died"))
    monkeypatch.setattr(workers, "ready", lambda: True)
    monkeypatch.setattr(workers, "submit", lambda *args: broken)
    n = big.count(b"\n")
    failed = bulk.scan(big, n, share_bytes=0)
    monkeypatch.undo()
    workers.set_enabled(False)
    assert_same_scan(failed, bulk.scan(big, n))
    workers.set_enabled(True)


def test_a_helper_that_dies_is_replaced(helper):
    assert workers.result(workers.submit(os._exit, 3)) is None
    assert workers.warm_up(wait=60)
    assert workers.result(workers.submit(abs, -2)) == 2


def test_loading_with_the_helper_gives_the_same_program(big, helper, tmp_path):
    path = tmp_path / "big.ngc"
    plain = big.replace(b"(unclosed\n", b"")  # an unclosed comment sends a file to the expander
    assert not sniff.needs_expander(plain)
    path.write_bytes(plain)
    monkey = bulk.SHARE_BYTES
    try:
        bulk.SHARE_BYTES = 0
        shared = load(path)
    finally:
        bulk.SHARE_BYTES = monkey
    workers.set_enabled(False)
    alone = load(path)
    assert [str(d) for d in shared.diagnostics] == [str(d) for d in alone.diagnostics]
    assert shared.errors  # the repeated X at least
    assert len(shared.toolpath) > 60_000
    np.testing.assert_array_equal(shared.toolpath.end, alone.toolpath.end)
    np.testing.assert_array_equal(shared.toolpath.source_line, alone.toolpath.source_line)


def test_the_pipes_to_and_from_the_helper_hold_a_group_at_a_time(helper):
    fcntl = pytest.importorskip("fcntl")
    if not hasattr(fcntl, "F_GETPIPE_SZ"):
        pytest.skip("only Linux sets a pipe's size")
    pool = workers._pool
    for end in (pool._call_queue._writer, pool._result_queue._reader):
        assert fcntl.fcntl(end.fileno(), fcntl.F_GETPIPE_SZ) == workers.PIPE_BYTES


def test_a_half_imported_multiprocessing_means_this_is_no_helper(monkeypatch):
    """The helper's start-up thread imports multiprocessing; a load asking meanwhile (the
    window opens a file as it starts) meets the module half made, without parent_process."""
    import sys
    import types

    monkeypatch.setattr(workers, "_disabled", False)
    monkeypatch.setitem(sys.modules, "multiprocessing", types.ModuleType("multiprocessing"))
    assert workers.available()


def _helper_finishes_every_group(monkeypatch) -> list:
    """Each group waited for until the helper has finished it, so every group given to
    the helper is its work (else who scans which depends on their speeds); the list the
    groups it did are added to."""
    from concurrent.futures import wait

    take, theirs = bulk.Helped.take, []

    def after_the_helper(self, k):
        future = self._futures.get(k)
        if future is not None:
            wait([future])
            theirs.append(k)
        return take(self, k)

    monkeypatch.setattr(bulk.Helped, "take", after_the_helper)
    return theirs


def test_the_helper_reads_its_groups_from_the_file_itself(big, helper, tmp_path, monkeypatch):
    import zlib

    path = tmp_path / "big.ngc"
    path.write_bytes(b"\xef\xbb\xbf" + big)  # the bytes start after a byte-order mark
    parts = chunks(big)
    first, last = parts[3][0], parts[5][1]
    group = [(s - first, e - first, c) for s, e, c in parts[3:6]]
    future = workers.submit(bulk.scan_file_chunks, str(path), 3 + first, last - first, group)
    crc, theirs = workers.result(future)
    assert crc == zlib.crc32(big[first:last])
    for a, b in zip(theirs, bulk.scan_chunks(big[first:last], group), strict=True):
        for x, y in zip(a, b, strict=True):
            np.testing.assert_array_equal(x, y)
    theirs = _helper_finishes_every_group(monkeypatch)
    n = big.count(b"\n")
    shared = bulk.scan(big, n, share_bytes=0, origin=(str(path), 3))
    assert theirs == list(range(1, len(theirs) + 1)) and len(theirs) >= 8  # every group but the first
    workers.set_enabled(False)
    assert_same_scan(shared, bulk.scan(big, n))


@pytest.mark.parametrize("change", ["other words", "shorter", "gone"])
def test_a_file_changed_after_it_was_read_costs_time_not_the_result(big, helper, tmp_path, monkeypatch,
                                                                     change):
    path = tmp_path / "big.ngc"
    if change != "gone":
        path.write_bytes(big.replace(b"X", b"Y") if change == "other words" else big[: len(big) // 2])
    theirs = _helper_finishes_every_group(monkeypatch)
    n = big.count(b"\n")
    shared = bulk.scan(big, n, share_bytes=0, origin=(str(path), 0))
    assert theirs == list(range(1, len(theirs) + 1)) and len(theirs) >= 8  # every group but the first
    workers.set_enabled(False)
    assert_same_scan(shared, bulk.scan(big, n))


@pytest.mark.parametrize(("read", "offset"), [
    (b"G0 X1\nG1 Y2\n", 0), (b"\xef\xbb\xbfG0 X1\n", 3), (b"G0 X1\r\nG1 Y2\r\n", 0),
    (b"G0 X1\rG1 Y2\r", None), (b"\xef\xbb\xbfG0 X1\rG1 Y2\r", None),  # line ends made LF: not as read
])
def test_a_program_s_origin_is_where_its_bytes_lie_in_the_file(read, offset):
    from pathlib import Path

    from app.gcode.program import _origin
    from app.gcode.reading import clean_bytes

    origin = _origin(Path("f.ngc"), read, clean_bytes(read))
    assert origin == (None if offset is None else ("f.ngc", offset))
    if origin is not None:
        assert read[offset:] == clean_bytes(read)


def test_while_the_helper_holds_the_next_group_this_process_scans_the_last_ones(big, monkeypatch):
    """The helper (here a thread, held on the first group it begins until this process has
    scanned a group ahead) takes the groups in order; the loader, waiting for the one the
    helper holds, scans the last groups meanwhile, from the end: the scan is the same."""
    import threading
    from concurrent.futures import ThreadPoolExecutor

    pool, ahead, went_ahead = ThreadPoolExecutor(max_workers=1), [], threading.Event()

    def held(fn, *args):
        went_ahead.wait(60)
        return fn(*args)

    scan_ahead = bulk.Helped._scan_ahead

    def recorded(self, k):
        before = set(self._ahead)
        done = scan_ahead(self, k)
        ahead.extend(sorted(set(self._ahead) - before))
        went_ahead.set()
        return done

    monkeypatch.setattr(workers, "ready", lambda: True)
    monkeypatch.setattr(workers, "submit", lambda fn, *args: pool.submit(held, fn, *args))
    monkeypatch.setattr(bulk.Helped, "_scan_ahead", recorded)
    n = big.count(b"\n")
    shared = bulk.scan(big, n, share_bytes=0)
    pool.shutdown()
    monkeypatch.undo()
    groups = len(bulk._split(chunks(big)))
    assert ahead and ahead == list(range(groups - 1, groups - 1 - len(ahead), -1))  # the last, from the end
    workers.set_enabled(False)
    assert_same_scan(shared, bulk.scan(big, n))
    workers.set_enabled(True)
