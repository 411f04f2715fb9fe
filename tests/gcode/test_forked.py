"""The forked child that shares the scan of a big file in a one-shot load: the same
result as a scan alone, and a child that fails or sticks costs time, never the result."""

import os
import sys
import time

import numpy as np
import pytest

from app.gcode import bulk, forked, load, sniff, workers
from tests.gcode.scans import assert_same_scan, big_program

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="forks only on Linux")


@pytest.fixture(scope="module")
def big() -> bytes:
    return big_program()


@pytest.fixture
def one_shot(monkeypatch):
    """As the command line loads: no helper process, forking allowed (the test runner
    may have threads of its own; the child only scans and writes to its pipe)."""
    monkeypatch.setattr(forked, "_allowed", True)
    monkeypatch.setattr(forked.threading, "active_count", lambda: 1)
    monkeypatch.setattr(forked, "spare_core", lambda: None)  # not known: the load average decides
    monkeypatch.setattr(forked.os, "getloadavg", lambda: (0.0, 0.0, 0.0))  # a quiet machine
    workers.set_enabled(False)
    taken = []  # per shared scan: how many groups came from the child
    close = forked.Shared.close

    def spy(self):
        taken.append(len(self.received))
        close(self)

    monkeypatch.setattr(forked.Shared, "close", spy)
    yield taken
    workers.set_enabled(True)


def test_a_scan_shared_with_a_forked_child_equals_a_scan_alone(big, one_shot, monkeypatch):
    n = big.count(b"\n")
    parent, real = os.getpid(), bulk.scan_chunks

    def scan_chunks(data, parts):  # this process slower than the child: its groups are used
        if os.getpid() == parent:
            time.sleep(0.05)
        return real(data, parts)

    monkeypatch.setattr(bulk, "scan_chunks", scan_chunks)
    shared = bulk.scan(big, n, share_bytes=0)
    monkeypatch.setattr(bulk, "scan_chunks", real)
    assert one_shot and one_shot[0] > 0, "the child sent no group"
    monkeypatch.setattr(forked, "_allowed", False)
    assert_same_scan(shared, bulk.scan(big, n))


def test_a_child_that_fails_costs_time_not_the_result(big, one_shot, monkeypatch):
    n = big.count(b"\n")
    parent, real = os.getpid(), bulk.scan_chunks

    def scan_chunks(data, parts):  # fails in the child only
        if os.getpid() != parent:
            raise RuntimeError("the child failed")
        return real(data, parts)

    monkeypatch.setattr(bulk, "scan_chunks", scan_chunks)
    failed = bulk.scan(big, n, share_bytes=0)
    monkeypatch.setattr(bulk, "scan_chunks", real)
    assert one_shot == [0]  # asked, and nothing came
    monkeypatch.setattr(forked, "_allowed", False)
    assert_same_scan(failed, bulk.scan(big, n))


def test_a_busy_machine_or_a_second_thread_keeps_the_load_in_one_process(monkeypatch):
    monkeypatch.setattr(forked, "spare_core", lambda: None)
    monkeypatch.setattr(forked, "_allowed", True)
    monkeypatch.setattr(forked.threading, "active_count", lambda: 1)
    monkeypatch.setattr(forked.os, "cpu_count", lambda: 2)
    monkeypatch.setattr(forked.os, "getloadavg", lambda: (0.4, 0.4, 0.4))
    assert forked.usable()
    monkeypatch.setattr(forked.os, "getloadavg", lambda: (2.5, 2.0, 1.0))
    assert not forked.usable()
    monkeypatch.setattr(forked.os, "getloadavg", lambda: (0.0, 0.0, 0.0))
    monkeypatch.setattr(forked.threading, "active_count", lambda: 2)
    assert not forked.usable()
    monkeypatch.setattr(forked, "_allowed", False)
    monkeypatch.setattr(forked.threading, "active_count", lambda: 1)
    assert not forked.usable()


def test_the_idle_time_since_start_up_decides_before_the_load_average(monkeypatch):
    """Half a core idle since the module was imported: a core to spare, whatever the last
    minute's load average says (a command that ended a moment ago still weighs on it)."""
    monkeypatch.setattr(forked, "_allowed", True)
    monkeypatch.setattr(forked.threading, "active_count", lambda: 1)
    monkeypatch.setattr(forked.os, "getloadavg", lambda: (1.6, 1.0, 0.5))
    monkeypatch.setattr(forked, "_WATCHED_FROM", (100.0, 5000.0))
    for elapsed, idle, spare in [(0.1, 0.09, True), (0.1, 0.06, True), (0.1, 0.02, False), (0.1, 0.0, False)]:
        monkeypatch.setattr(forked, "_idle_now", lambda e=elapsed, i=idle: (100.0 + e, 5000.0 + i))
        assert forked.spare_core() is spare
        assert forked.usable() is spare
    monkeypatch.setattr(forked, "_idle_now", lambda: (100.01, 5000.01))  # too short a time to tell
    assert forked.spare_core() is None
    assert not forked.usable()  # the load average decides: 1.6 on 2 cores
    monkeypatch.setattr(forked, "_idle_now", lambda: None)  # no /proc/stat
    assert forked.spare_core() is None


def test_the_idle_time_is_read_from_the_machine():
    reading = forked._idle_now()
    if not os.path.exists("/proc/stat"):
        assert reading is None
        return
    assert reading is not None and reading[1] > 0
    assert forked._WATCHED_FROM is not None and forked._WATCHED_FROM[1] <= reading[1]


def _job(parent: int, k: int, slow_parent_s: float = 0.0, stuck_child_job: int = -1) -> tuple[int, int]:
    """Job ``k`` of the tests below: (who did it, its value)."""
    me = os.getpid()
    if me == parent:
        time.sleep(slow_parent_s)
    elif k == stuck_child_job:
        time.sleep(600)
    return me, k * 10


def test_shared_jobs_come_in_order_from_both_sides():
    parent = os.getpid()
    shared = forked.Shared(lambda k: _job(parent, k, slow_parent_s=0.02), 24)
    try:
        results = [shared.take(k) for k in range(24)]
    finally:
        shared.close()
    assert [value for _, value in results] == [k * 10 for k in range(24)]
    by_child = [k for k, (who, _) in enumerate(results) if who != parent]
    assert by_child and by_child == sorted(shared.received)  # both sides worked: the child's
    assert results[0][0] == parent and 0 not in by_child  # jobs are those it sent; the parent began


def test_a_child_stuck_on_a_job_costs_time_not_the_result(monkeypatch):
    monkeypatch.setattr(forked, "STUCK_S", 0.2)
    parent = os.getpid()
    shared = forked.Shared(lambda k: _job(parent, k, stuck_child_job=1), 6)
    try:
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and shared._claims[1] != forked.CHILD:  # the child has job 1
            time.sleep(0.01)
        assert shared._claims[1] == forked.CHILD  # (else the stuck path would go untried)
        results = [shared.take(k) for k in range(6)]
    finally:
        shared.close()
    assert results == [(parent, k * 10) for k in range(6)]  # all done here, job 1 after the wait
    assert shared.received == []


def test_the_command_line_load_with_a_child_gives_the_same_program(big, one_shot, tmp_path, monkeypatch):
    path = tmp_path / "big.ngc"
    plain = big.replace(b"(unclosed\n", b"")  # an unclosed comment sends a file to the expander
    assert not sniff.needs_expander(plain)
    path.write_bytes(plain)
    monkeypatch.setattr(bulk, "SHARE_BYTES", 0)
    shared = load(path)
    monkeypatch.setattr(forked, "_allowed", False)
    alone = load(path)
    assert one_shot  # a child was forked
    assert [str(d) for d in shared.diagnostics] == [str(d) for d in alone.diagnostics]
    assert shared.errors  # the repeated X at least
    np.testing.assert_array_equal(shared.toolpath.end, alone.toolpath.end)
    np.testing.assert_array_equal(shared.toolpath.source_line, alone.toolpath.source_line)


def test_a_big_file_found_to_need_the_expander_mid_scan_stops_its_child(big, one_shot, tmp_path, monkeypatch):
    from app.gcode import program

    path = tmp_path / "big.ngc"
    path.write_bytes(big)  # its unclosed comment near the end: the expander's, found mid-scan
    monkeypatch.setattr(bulk, "SHARE_BYTES", 0)
    folded = load(path)
    assert one_shot  # a child was forked and stopped (the fixture counts at its close)
    monkeypatch.setattr(forked, "_allowed", False)
    monkeypatch.setattr(program, "FOLD_BYTES", 1 << 40)
    sniffed = load(path)
    assert folded.ops.source is not None and sniffed.ops.source is not None
    assert [str(d) for d in folded.diagnostics] == [str(d) for d in sniffed.diagnostics]
    np.testing.assert_array_equal(folded.toolpath.end, sniffed.toolpath.end)
    np.testing.assert_array_equal(folded.toolpath.source_line, sniffed.toolpath.source_line)
