"""The estimate in bounded memory (issue 24) gives the numbers the whole-array estimate
gave: each program's figures are pinned (``FIGURES``), and any chunk size gives the
same ones to the last bit.

The figures were pinned first as a sha256 digest of every bit the whole-array version
(before the passes ran in chunks) computed. Those bits hold only on one kind of
machine: the digests of the programs with arcs failed on an AMD EPYC with every numpy
from 2.2 to 2.4 (and with numpy's AVX2 loops turned off), the same code that met them
where they were recorded; the arcs' angles and radii come from ``atan2``, ``hypot``,
``sin`` and ``cos``, most likely the C library's, whose last bit is not the same
everywhere. So the pins are now moments of
the figures, recorded with that code (``python -m tests.gcode.test_estimate_blocks``
prints them), met within a relative 1e-9: a change of any row's time by a
millionth of a second shows, a C library's last bit does not."""

import sys
from pathlib import Path

import numpy as np
import pytest

from app.gcode import load, load_text
from app.gcode.estimate import estimate
from bench import arcfile
from bench.bench_estimate import short_segments
from tests.gcode.test_estimate import ARCS_AND_STOPS, PROGRAMS

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"
RTOL = 1e-9

# name -> ((sum, sum of squares, sum weighted by place) of the rows' seconds, the same
# of the lines' seconds, (motion, dwell, spin-up, stop seconds), (stops, tool changes))
FIGURES = {
    'arcs_circles': (
        (176.7239386431449, 505.1845934675155, 84.14383563995851),
        (176.72393864314486, 502.77901522332763, 83.7036337123688),
        (175.88893864314488, 0.0, 0.835, 0.0), (0, 0)),
    'inch_plate': (
        (463.08009046155206, 2945.8845118887266, 264.7311841052474),
        (463.080090461552, 2942.95602794593, 264.1849349420191),
        (462.24509046155214, 0.0, 0.835, 0.0), (0, 0)),
    'potrace_logo': (
        (172.9378462040769, 596.7302987593723, 84.96827011498073),
        (172.93784620407686, 593.9766223552954, 84.66611743167738),
        (172.10284620407688, 0.0, 0.835, 0.0), (0, 0)),
    'star_passes': (
        (817.7014567595309, 9470.94776206408, 539.8424041170697),
        (817.7014567595306, 9468.308778401164, 536.1239908408633),
        (816.8664567595308, 0.0, 0.835, 0.0), (0, 0)),
    'text_round4': (
        (405.1035393654362, 2214.986751350986, 209.26307111352565),
        (405.1035393654362, 2213.4658700152204, 208.08587243846736),
        (404.26853936543614, 0.0, 0.835, 0.0), (0, 0)),
    'traced_drawing': (
        (5306.3929185300585, 13409.067016852561, 2805.5025421300707),
        (5306.3929185300585, 13407.036111765356, 2805.3660154027084),
        (5305.557918530059, 0.0, 0.835, 0.0), (0, 0)),
    'arcs and stops': (
        (22.68325387400622, 85.76557894542212, 14.132196600283377),
        (22.68325387400622, 83.03917476641467, 12.63511256416797),
        (21.358253874006216, 0.5, 0.825, 3.7249999999999996), (2, 1)),
    'arcs and stops from a start': (
        (22.750899084519283, 86.1077224721827, 14.135604400282018),
        (22.75089908451928, 83.26492362843948, 12.640628956271604),
        (21.42589908451928, 0.5, 0.825, 3.7249999999999996), (2, 1)),
    'short segments': (
        (8.297021725968602, 10.767008308633473, 1.8251054713529533),
        (8.297021725968602, 10.763847777997775, 1.822161681184872),
        (8.297021725968602, 0.0, 0.0, 0.0), (0, 0)),
    'gcodetools': (
        (7729.565853183892, 31009.070942412243, 3863.2303820575607),
        (7729.565853183893, 31003.017046504003, 3863.0527300686754),
        (7728.730853183893, 0.0, 0.835, 0.0), (0, 0)),
    'nothing': (
        (0.0, 0.0, 0.0),
        (0.0, 0.0, 0.0),
        (0.0, 0.0, 0.0, 0.0), (0, 0)),
    'events only': (
        (1.835, 3.367225, 1.835),
        (1.835, 1.697225, 0.5670000000000001),
        (0.0, 1.0, 0.835, 0.0), (1, 0)),
    'moves that go nowhere': (
        (1.1833333333333333, 0.653611111111111, 0.8566666666666667),
        (1.1833333333333333, 0.653611111111111, 0.7222222222222222),
        (0.6833333333333333, 0.5, 0.0, 0.0), (0, 0)),
    'one move from a start': (
        (1.318033988749895, 1.7372135954999586, 1.318033988749895),
        (1.318033988749895, 1.7372135954999586, 1.318033988749895),
        (1.318033988749895, 0.0, 0.0, 0.0), (0, 0)),
    'arcs sent as chords': (
        (73.72869952062146, 981.3107844329273, 57.173245672846214),
        (73.72869952062146, 88.19009037330534, 44.62404873200026),
        (73.72869952062145, 0.0, 0.0, 0.0), (0, 0)),
}


def _moments(array) -> tuple[float, float, float]:
    a = np.asarray(array, np.float64)
    place = np.arange(1, len(a) + 1) / max(len(a), 1)
    return float(a.sum()), float((a * a).sum()), float((a * place).sum())


def _figures(est) -> tuple:
    """What ``FIGURES`` pins, of one estimate."""
    seconds = tuple(float(v) for v in (est.motion, est.dwell, est.spin_up, est.stop_seconds))
    counts = (int(est.stops), int(est.tool_changes))
    return _moments(est.row_seconds), _moments(est.line_seconds), seconds, counts


def _bits(est) -> bytes:
    """Every bit of an estimate's figures."""
    parts = [np.ascontiguousarray(a, dtype=np.float64).tobytes() for a in (est.row_seconds, est.line_seconds)]
    parts += [float(v).hex().encode() for v in (est.motion, est.dwell, est.spin_up, est.stop_seconds)]
    parts.append(f"{est.stops} {est.tool_changes}".encode())
    return b"|".join(parts)


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
    chorded = PROGRAMS["XZ and YZ arcs"].replace("M02\n", "") + PROGRAMS["three turns"]
    out["arcs sent as chords"] = (load_text(chorded), None)
    return out


@pytest.fixture(scope="module")
def programs(tmp_path_factory):
    return _programs(tmp_path_factory.mktemp("estimate"))


def _estimate(program, start, threads=1):
    return estimate(program.toolpath, program.device_lines, program.profile, start=start, plan=program.plan,
                    threads=threads)


def test_the_estimate_gives_the_whole_array_estimates_figures(programs):
    assert programs.keys() == FIGURES.keys()
    for name, p in programs.items():
        *moments, counts = _figures(_estimate(*p))
        *pinned, pinned_counts = FIGURES[name]
        assert counts == pinned_counts, name
        np.testing.assert_allclose(np.concatenate(moments), np.concatenate(pinned), rtol=RTOL, atol=1e-12,
                                   err_msg=name)


SMALL = 5_000  # moves: a chunk of one block is tried on programs up to this size (the others take 30 s)


@pytest.mark.parametrize("threads", [1, 2])
@pytest.mark.parametrize("chunk", [1, 7, 1000])
def test_any_chunk_size_gives_the_same_figures(programs, monkeypatch, chunk, threads):
    """On one thread, and with the chunks and blocks shared by two (``threads`` 2: each
    block's first junction then met with the last move of a block the other one did)."""
    from app.gcode import estimate as module
    from app.gcode import estimate_passes as passes

    chosen = {name: p for name, p in programs.items() if chunk > 1 or len(p[0].toolpath) <= SMALL}
    assert chunk > 1 or 0 < len(programs) - len(chosen) < len(programs) // 3
    whole = {name: _bits(_estimate(*p)) for name, p in chosen.items()}
    monkeypatch.setattr(passes, "CHUNK", chunk)
    monkeypatch.setattr(module, "BLOCK", chunk)
    assert {name: _bits(_estimate(*p, threads)) for name, p in chosen.items()} == whole


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


if __name__ == "__main__":  # print FIGURES as this code computes them
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        for name, p in _programs(Path(folder)).items():
            print(f"    {name!r}: {_figures(_estimate(*p))},", file=sys.stdout)
