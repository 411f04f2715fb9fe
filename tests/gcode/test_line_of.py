"""Lines of byte offsets from the chunk table (``Lines.line_of``): the closing ``%`` and an
``(ABORT, ...)`` comment are found on the lines that counting every newline gives."""

import random

import pytest

from app.gcode import load, load_text, source
from app.gcode.source import Lines


@pytest.fixture
def small_chunks(monkeypatch):
    monkeypatch.setattr(source, "CHUNK_BYTES", 64)  # many chunks in a short file


def test_every_offset_is_on_the_line_counting_gives(small_chunks):
    rng = random.Random(7)
    rows = ["".join(rng.choice("G1 X2.5;(,)\r") for _ in range(rng.randrange(0, 40))) for _ in range(300)]
    for data in ("\n".join(rows).encode(), ("\n".join(rows) + "\n").encode(), b"", b"\n\n"):
        lines = Lines(data=data)
        assert len(lines.chunks) > 10 or len(data) < 1000
        for offset in range(len(data) + 1):
            assert lines.line_of(data, offset) == data.count(b"\n", 0, offset) + 1
        other = bytes(data)  # equal bytes, not the ones the lines hold: counted
        assert lines.line_of(other + b"\n", len(other) + 1) == other.count(b"\n") + 2


@pytest.mark.parametrize("tail", [
    "%\nG0 X9\n",  # the closing %, words after it
    "G1 X3 (abort , stop here)\nG0 X9\nM2\n",  # an ABORT ends the program there
    "G1 X3 (ABORT,, two commas)\n(abort, later)\nM2\n",
    "G1 X3 (comma, but no abort)\nM2\n",
])
def test_percent_and_abort_lines_of_a_file_are_those_of_its_text(tmp_path, small_chunks, tail):
    head = "%\n" if tail.startswith("%") else ""
    text = head + "".join(f"G1 X{k % 7}.5 Y{k % 5} F300 (row {k})\n" for k in range(400)) + tail
    path = tmp_path / "p.ngc"
    path.write_text(text)
    from_file, from_text = load(path), load_text(text)
    assert len(from_file.lines) > 400 and len(Lines(data=text.encode()).chunks) > 100
    assert [str(d) for d in from_file.diagnostics] == [str(d) for d in from_text.diagnostics]
    assert len(from_file.toolpath) == len(from_text.toolpath)
    if "abort" in tail.lower() and "no abort" not in tail:
        assert from_file.errors and from_file.errors[0].line == 402 + len(head) - 1
