"""The scan's table a window of lines at a time: the same program as one table of the
whole file, wherever the windows end (a run of simple lines, a line for the general
path, the program's end)."""

import numpy as np
import pytest

from app.gcode import bulk, load, source, workers
from tests.gcode.scans import assert_same_scan, big_program


@pytest.fixture(scope="module")
def big() -> bytes:
    """``scans.big_program`` without its unclosed comment (which sends it to the
    expander), a few lines for the general path in every part of it."""
    text = big_program().replace(b"(unclosed\n", b"G18 G2 X1 Z1 I1 K0\nG17\n")
    lines = text.split(b"\n")
    for at in range(len(lines) // 7, len(lines) - 2, len(lines) // 7):  # (the last line, M2, kept)
        lines[at] = b"G20 G1 X1 Y2 X3"  # refused: two X words (the units stay as they were)
    return b"\n".join(lines)


def _arrays(program) -> dict:
    tp = program.toolpath
    return {name: getattr(tp, name) for name in ("start", "end", "kind", "center", "turn", "source_line",
                                                 "device_index", "feed", "length", "time")}


@pytest.mark.parametrize("window", [1, 3 * source.CHUNK_BYTES])
def test_a_program_read_in_windows_is_the_same_program(big, tmp_path, monkeypatch, window):
    path = tmp_path / "big.ngc"
    path.write_bytes(big + b"G0 X1\n")  # words after M2: a warning
    workers.set_enabled(False)
    try:
        monkeypatch.setattr(bulk, "WINDOW_BYTES", 1 << 40)
        whole = load(path)
        monkeypatch.setattr(bulk, "WINDOW_BYTES", window)  # 1: a window per chunk
        windows = load(path)
    finally:
        workers.set_enabled(True)
    assert whole.errors and whole.warnings  # the general path's lines and the end were reached
    said = [[(d.line, d.message) for d in p.diagnostics] for p in (whole, windows)]
    assert said[0] == said[1]
    for name, column in _arrays(whole).items():
        np.testing.assert_array_equal(_arrays(windows)[name], column, err_msg=name)


def test_the_windows_cover_every_line_once(big, monkeypatch):
    monkeypatch.setattr(bulk, "WINDOW_BYTES", 1)
    n = big.count(b"\n")
    workers.set_enabled(False)
    try:
        spans = [(w.first, len(w.simple), ready) for w, ready in bulk.scan_stream(big, n)]
        assert_same_scan(bulk.scan(big, n), _whole_table(big, n, monkeypatch))
    finally:
        workers.set_enabled(True)
    assert len(spans) > 3
    assert [first for first, _, _ in spans] == [0] + [ready for *_, ready in spans[:-1]]
    assert all(first + size == ready for first, size, ready in spans) and spans[-1][2] == n


def _whole_table(data: bytes, n: int, monkeypatch) -> bulk.Scan:
    monkeypatch.setattr(bulk, "WINDOW_BYTES", 1 << 40)
    (window, ready), = bulk.scan_stream(data, n)
    assert window.first == 0 and ready == n
    return window


def test_windows_are_not_handed_to_a_helper_that_is_not_running(big, monkeypatch):
    def refused(*args):
        raise AssertionError("submitted to a helper that is not running")

    monkeypatch.setattr(bulk, "WINDOW_BYTES", 1)
    monkeypatch.setattr(workers, "ready", lambda: False)
    monkeypatch.setattr(workers, "submit", refused)
    monkeypatch.setattr(bulk.forked, "usable", lambda: False)
    n = big.count(b"\n")
    windows = list(bulk.scan_stream(big, n, share_bytes=0))
    assert len(windows) > 3 and windows[-1][1] == n
