"""The point-list importer's G-code: compact words, one plain comment for its header, a
program every control reads and the loader takes on its fast path."""

from __future__ import annotations

import re

import numpy as np
import pytest

from app.gcode import bulk, load_text, sniff
from app.gcode.lexer import lex_line
from app.gcode.pointlist import ImportOptions, read_points, to_gcode
from app.gcode.pointlist.gcode import comment, feed_lines

COMPACT = re.compile(r"G01( [XYZ]-?\d+\.\d{3})+")
COMMENT = re.compile(r"\([^();\n]*\)")  # one comment, nothing nested, no ';' inside


@pytest.mark.parametrize("text", ["plain", "a (b) c", "x; y", "((", "))", "two\nlines\r", "tab\there",
                                  "bell\x07"])
def test_a_comment_is_one_line_with_nothing_nested(text):
    line = comment(text)
    assert line.endswith("\n") and COMMENT.fullmatch(line[:-1]), line
    lexed = lex_line(line[:-1], 1)
    assert lexed.error is None and not lexed.words


def test_feed_lines_are_compact_and_round_to_three_decimals():
    rng = np.random.default_rng(5)
    edges = [[0, -0.0004, 0.0004], [-0.0006, 9.9996, -99.9995]]
    values = np.concatenate([rng.uniform(-250, 250, (500, 3)), edges])
    lines = feed_lines(values, "XYZ").splitlines()
    assert len(lines) == len(values)
    assert all(COMPACT.fullmatch(line) for line in lines), [ln for ln in lines if not COMPACT.fullmatch(ln)]
    read = np.array([[float(w[1:]) for w in line.split()[1:]] for line in lines])
    assert np.abs(read - values).max() <= 0.0005 + 1e-9
    assert "-0.000" not in " ".join(lines)
    assert feed_lines(values[:, :2], "XY").splitlines()[0].count(" ") == 2


def test_import_output_is_plain_and_read_whole_on_the_fast_path():
    rows = (b"%.4f %.4f -0.%d\n" % (40 + i * 0.37, 70 - i * 0.11, i % 7) for i in range(300))
    raw = b"# a drawing\n" + b"".join(rows)
    points = read_points(raw, "drawing (v2); final.xyz")
    text, _ = to_gcode(points, ImportOptions())
    lines = text.splitlines()
    assert COMMENT.fullmatch(lines[0]), lines[0]
    assert sum(bool(COMPACT.fullmatch(line)) for line in lines) == 299
    data = text.encode()
    assert not sniff.needs_expander(data)
    scan = bulk.scan(data, len(lines))
    state_lines = [i for i, line in enumerate(lines) if line.startswith(("G21 G90", "M30"))]
    assert np.flatnonzero(~scan.simple).tolist() == state_lines  # all else on the fast path
    program = load_text(text)
    assert not program.errors and len(program.toolpath) > 299
