"""Property tests: anything loads, normalising is idempotent and keeps the path,
and the numpy fast path reads exactly what the general lexer reads."""

import math
import re

import numpy as np
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from app.gcode import bulk, load_text
from app.gcode.lexer import lex_line
from app.gcode.limits import bad_rows
from tests.gcode.scans import reference_load

SETTINGS = settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])

ALPHABET = "GXYZIJKFRPMSTNgxyzij0123456789.-+ \t()%;*/#[]\r\n"
WORDISH = st.lists(st.sampled_from(["G21", "G20", "M3", "M5", "S100", "G1", "X1.5", "F10", " ", "(c)"]))
gcodeish = st.text(alphabet=ALPHABET, max_size=200)
coord = st.floats(-200, 200, allow_nan=False).map(lambda v: round(v, 4))


@SETTINGS
@given(st.one_of(gcodeish, st.text(max_size=200)))
def test_any_text_loads_without_exception(text):
    program = load_text(text)
    for d in program.diagnostics:
        assert d.line >= 0 and d.message
    assert isinstance(program.device_lines, list)
    assert len(program.line_map) == len(program.device_lines)
    program.toolpath.polyline()


@SETTINGS
@given(st.binary(max_size=200))
def test_any_bytes_load_without_exception(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("b") / "x.ngc"
    path.write_bytes(data)
    from app.gcode import load

    load(path)


def _lexed_row(line: str):
    """The lexer's words of ``line`` (a block-deleted line's too: with the switch off it
    runs), or None for an error or a ``%`` line."""
    lexed = lex_line(line, 1)
    if lexed.error or lexed.skip == "%":
        return None
    return {w.letter: w.value for w in lexed.words}


@SETTINGS
@given(st.lists(st.one_of(gcodeish.filter(lambda s: "\n" not in s), WORDISH.map("".join)), min_size=1,
                max_size=20))
@example(["F1000000000"])  # a word the scan reads and ``limits.bad_rows`` hands to the general path
def test_bulk_reads_what_the_lexer_reads(lines):
    """Every simple line reads as the lexer reads it, but those whose values the fast path
    refuses afterwards (``limits.bad_rows``: vector.run sends them to the general path),
    which the lexer refuses too."""
    lines = [line.replace("\r", "") for line in lines]
    scan = bulk.scan("\n".join(lines).encode(), len(lines))
    refused = bad_rows(scan.values)
    for i, line in enumerate(lines):
        if not scan.simple[i]:
            continue
        row = _lexed_row(line)
        if refused[i]:
            assert row is None, line
            continue
        assert row is not None, line
        assert scan.deleted[i] == (lex_line(line, 1).skip == "block delete"), line
        got = {c: scan.values[c][i] for c in "XYZIJFMS" if not np.isnan(scan.values[c][i])}
        if scan.g[i] >= 0:
            got["G"] = float(scan.g[i])
        if scan.units[i] >= 0:
            got["G"] = 20.0 if scan.units[i] else 21.0
        row.pop("N", None)
        assert got == row, line


@st.composite
def programs(draw):
    """Valid programs: straight moves, arcs in every plane, units, relative moves, dwells."""
    out = [draw(st.sampled_from(["G21", "G20"]))]
    pos = [0.0, 0.0, 0.0]
    for _ in range(draw(st.integers(1, 12))):
        kind = draw(st.sampled_from(["line", "line", "arc", "arc", "dwell", "spindle", "rel"]))
        if kind == "line":
            x, y, z = draw(coord), draw(coord), draw(coord)
            out.append(f"G{draw(st.sampled_from([0, 1]))} X{x} Y{y} Z{z} F{draw(st.integers(1, 900))}")
            pos = [x, y, z]
        elif kind == "arc":
            plane = draw(st.sampled_from([(17, 0, 1, "IJ"), (18, 2, 0, "KI"), (19, 1, 2, "JK")]))
            g, a, b, letters = plane
            r = draw(st.floats(0.5, 50))
            a0, sweep = draw(st.floats(0, 6.28)), draw(st.floats(-6.2, 6.2))
            ca, cb = pos[a] - r * math.cos(a0), pos[b] - r * math.sin(a0)
            end = list(pos)
            end[a], end[b] = ca + r * math.cos(a0 + sweep), cb + r * math.sin(a0 + sweep)
            end[3 - a - b] += draw(st.sampled_from([0.0, -1.0]))
            words = " ".join(f"{'XYZ'[i]}{end[i]:.6f}" for i in range(3))
            offs = f"{letters[0]}{ca - pos[a]:.6f} {letters[1]}{cb - pos[b]:.6f}"
            out.append(f"G{g} G{2 if sweep < 0 else 3} {words} {offs} F100")
            pos = [float(f"{v:.6f}") for v in end]
            out.append("G17")
        elif kind == "dwell":
            out.append(f"G4 P{draw(st.floats(0, 5)):.3f}")
        elif kind == "spindle":
            out.append(draw(st.sampled_from(["M3 S1000", "M5", "M3", "M4 S200"])))
        else:
            out.append(f"G91 G1 X{draw(coord)} F50\nX{draw(coord)} Y{draw(coord)}\nG3 X1 Y1 I1 J0\nG90")
            pos = None
            break
    return "\n".join(out)


@SETTINGS
@given(programs())
def test_normalising_twice_changes_nothing(text):
    first = load_text(text)
    assert not first.errors, (text, first.errors)
    second = load_text("\n".join(first.device_lines))
    assert not second.errors, (first.device_lines, second.errors)
    assert second.device_lines == first.device_lines


@SETTINGS
@given(programs())
def test_normalised_program_describes_the_same_path(text):
    source = load_text(text)
    device = load_text("\n".join(source.device_lines))
    by_source: dict[int, list[dict]] = {}
    for m in device.moves:
        by_source.setdefault(int(source.line_map[m["line"] - 1]), []).append(m)
    start = [0.0, 0.0, 0.0]
    for m in source.moves:
        if m["kind"] == "dwell":
            continue
        ours = [d for d in by_source.pop(m["line"], []) if d["kind"] != "dwell"]
        if not ours and m["end"] == start:  # a move to where it stands before any axis is set:
            sent = [source.device_lines[i] for i in np.flatnonzero(source.line_map == m["line"])]
            assert sent and all(line == "G04 P0" for line in sent), sent
            continue  # a pause of no time: the device line stays, the machine stays
        assert ours, m
        assert np.allclose(ours[-1]["end"], m["end"], atol=0.001), (m, ours[-1])
        if m["kind"] == "arc" and ours[0]["kind"] == "arc":
            assert np.allclose(ours[0]["center"], m["center"], atol=0.0015)
            assert np.sign(ours[0]["turn"]) == np.sign(m["turn"])
        elif m["kind"] == "arc":
            planes = {"XY": (0, 1), "XZ": (2, 0), "YZ": (1, 2)}
            a, b = planes[m["plane"]]
            r = math.hypot(start[a] - m["center"][0], start[b] - m["center"][1])
            for d in ours:
                p = d["end"]
                assert abs(math.hypot(p[a] - m["center"][0], p[b] - m["center"][1]) - r) <= 0.011
        start = m["end"]


@SETTINGS
@given(programs())
def test_fast_path_and_general_path_agree(text):
    fast = load_text(text)
    slow = reference_load(text)
    assert fast.moves == slow.moves
    assert fast.diagnostics == slow.diagnostics


NUMBERS = ["0", "1", "-1", "3", "5", "5.5", ".5", "-0.", "+3", "10", "2.0001", "1e"]
simple_line = st.builds(
    lambda g, words, comment: " ".join(([f"G{g}"] if g is not None else []) + words) + comment,
    st.one_of(st.none(), st.sampled_from(["0", "1", "2", "3", "01", "02", "80", "4", "17", "20", "21"])),
    st.lists(st.builds(lambda c, v: f"{c}{v}", st.sampled_from("XYZIJFNRMS"),
                       st.sampled_from(NUMBERS)),
             max_size=5, unique_by=lambda w: w[0]),
    st.sampled_from(["", "(c)", " ; x", "(a)(b)"]),
)


@SETTINGS
@given(st.lists(simple_line, max_size=25))
def test_fast_and_general_paths_agree_on_odd_programs(lines):
    test_fast_path_and_general_path_agree.hypothesis.inner_test("\n".join(lines))


DEVICE_LINE = re.compile(
    r"^(G0[01]( [XYZ]-?\d+(\.\d+)?)+( F\d+(\.\d+)?)?"
    r"|G0[23] X-?[\d.]+ Y-?[\d.]+( Z-?[\d.]+)? I-?[\d.]+ J-?[\d.]+( F[\d.]+)?"
    r"|G04 P[\d.]+|M03 S[\d.]+|M05|M02)$"
)


@SETTINGS
@given(programs())
def test_device_lines_are_dialect_and_short(text):
    for line in load_text(text).device_lines:
        assert len(line) <= 80 and DEVICE_LINE.match(line), line
        assert "-0 " not in line + " " and not re.search(r"\.\d*0( |$)", line), line
