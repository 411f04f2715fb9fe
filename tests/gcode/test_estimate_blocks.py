"""The estimate in bounded memory (issue 24) gives the numbers the whole-array estimate
gave, to the last bit: each program's figures are pinned by a digest of the figures the
whole-array version (before the passes ran in chunks) computed, and any chunk size gives
the same ones."""

import hashlib
from pathlib import Path

import numpy as np
import pytest

from app.gcode import load, load_text
from app.gcode.estimate import estimate
from bench import arcfile
from bench.bench_estimate import short_segments
from tests.gcode.test_estimate import ARCS_AND_STOPS

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"

# sha256 (first 16 hex digits) of every figure as the whole-array estimate computed it
WHOLE_ARRAY_DIGESTS = {
    'arcs_circles': '05418a40a7c66a86',
    'inch_plate': '0ce713cded0f3ecd',
    'potrace_logo': '1c7bd3c64f248af0',
    'star_passes': '0bb94fe33d2f0944',
    'text_round4': '05cae5ba90d2b57a',
    'traced_drawing': '436fa0b28a900ac9',  # recorded with the whole-array estimate before 30ad8cb
    'arcs and stops': 'fd5d6e1ed6b7a793',
    'arcs and stops from a start': '545ca2e710ca56cc',
    'short segments': 'eb8c23e485df045f',
    'gcodetools': 'c0f221e185f1c5b3',
    'nothing': 'dc38c07cffa723ae',
    'events only': '47d3f173eea99cd1',
    'moves that go nowhere': '6aa90590aab9bba6',
    'one move from a start': 'def5c63661b249a6',
}


def _digest(est) -> str:
    h = hashlib.sha256()
    for array in (est.row_seconds, est.line_seconds):
        h.update(np.ascontiguousarray(array, dtype=np.float64).tobytes())
    for value in (est.motion, est.dwell, est.spin_up, est.stop_seconds):
        h.update(float(value).hex().encode())
    h.update(f"{est.stops} {est.tool_changes}".encode())
    return h.hexdigest()[:16]


def _programs(tmp: Path) -> dict:
    """name -> (Program, start or None)."""
    out = {path.stem: (load(path), None) for path in sorted(SAMPLES.glob("*.ngc"))}
    out["arcs and stops"] = (load_text(ARCS_AND_STOPS), None)
    out["arcs and stops from a start"] = (load_text(ARCS_AND_STOPS), (1.0, -2.0, 3.0))
    out["short segments"] = (load_text(short_segments(0.025, 600)), None)
    out["gcodetools"] = (load(arcfile.build(tmp / "arcs.ngc", 20_000)), None)
    out["nothing"] = (load_text(""), None)
    out["events only"] = (load_text("M3 S1000\nG4 P1\nM0\nM5\nM2\n"), None)
    out["moves that go nowhere"] = (load_text("G0 X0 Y0 Z0\nG1 X0 F100\nG4 P0.5\nG1 X1\nG1 X1\nM2\n"), None)
    out["one move from a start"] = (load_text("G1 X10 Y5 F600\n"), (0.0, 0.0, 0.0))
    return out


@pytest.fixture(scope="module")
def programs(tmp_path_factory):
    return _programs(tmp_path_factory.mktemp("estimate"))


def _estimate(program, start):
    return estimate(program.toolpath, program.device_lines, program.profile, start=start)


def test_the_estimate_is_the_whole_array_estimate_to_the_last_bit(programs):
    assert {name: _digest(_estimate(*p)) for name, p in programs.items()} == WHOLE_ARRAY_DIGESTS


@pytest.mark.parametrize("chunk", [1, 7, 1000])
def test_any_chunk_size_gives_the_same_figures(programs, monkeypatch, chunk):
    from app.gcode import estimate as module
    from app.gcode import estimate_passes as passes

    monkeypatch.setattr(passes, "CHUNK", chunk)
    monkeypatch.setattr(module, "BLOCK", chunk)
    assert {name: _digest(_estimate(*p)) for name, p in programs.items()} == WHOLE_ARRAY_DIGESTS


def test_the_trailing_search_finds_what_a_search_of_the_whole_path_finds():
    """``_blocks_up_to`` searches only the ends between its smallest and largest point;
    zero-length blocks (equal ends), points outside the path, inf and NaN included."""
    from app.gcode.estimate_passes import _blocks_up_to

    rng = np.random.default_rng(24)
    for _ in range(2000):
        ends = np.cumsum(rng.choice([0.0, 0.5, 1.0, 2.5], size=int(rng.integers(0, 60))))
        special = np.array([-1.0, 0.0, 1e9, -np.inf, np.inf, np.nan])
        points = rng.choice(np.concatenate((ends, special)), size=int(rng.integers(0, 20)))
        points[rng.random(len(points)) < 0.5] += rng.normal(scale=0.3)
        assert np.array_equal(_blocks_up_to(ends, points), np.searchsorted(ends, points, side="right"))
