"""The G-code core against LinuxCNC's interpreter, from the committed rs274 recordings.

``tests/oracle/record.py`` ran ``rs274 -g`` on every sample and case; these tests only
read ``tests/oracle/data/*.canon`` (CI has no rs274) and compare them with
``app.gcode.load(path).moves``, move by move:

* same count, same kind (rapid / feed / arc / dwell), same 1-based source line;
* end points and arc centres within 0.001 mm, plus rs274's print resolution (``%.4f``
  in the program's units: 0.00005 mm, or 0.00005 in = 0.00127 mm in inch programs);
* arcs: same plane and same direction (sign of ``turn``); feeds within 0.001 mm/min
  plus the print resolution; dwell times within 0.0001 s.

Where rs274 refused a program, the loader must report an error on exactly that line
(and nowhere else, in these one-arc files); where rs274 accepted it, no error at all.
"""

from __future__ import annotations

import hashlib
import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from app.gcode import load as _load
from app.gcode.tools import Tool
from tests.oracle import record
from tests.oracle.canon import MM_PER_INCH, CanonRecord, compare_moves, drop_axisless_moves, read_record
from tests.oracle.record import SEM_PREFIX, SEM_TOOLS

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(__file__).resolve().parent / "data"
SAMPLES = ROOT / "resources" / "samples"
CASES = Path(__file__).resolve().parent / "cases"

RECORDS = sorted(p for p in DATA.glob("*.canon") if "+" not in p.stem)
VARIANT_STEMS = {p.stem.split("+")[0] for p in DATA.glob("*+*.canon")}  # tested on their own
ACCEPTED = [p for p in RECORDS if read_record(p).error_line is None and p.stem not in VARIANT_STEMS]
REFUSED = [p for p in RECORDS if read_record(p).error_line is not None]
SAMPLE_FILES = sorted(SAMPLES.glob("*.ngc"))


SEM_TABLE = {n: Tool(n, d, z) for n, (d, z) in SEM_TOOLS.items()}


def load(path: Path):
    """The loader, with the tool table rs274 had for this source (``record.tool_table_for``)."""
    return _load(path, tools=SEM_TABLE if Path(path).stem.startswith(SEM_PREFIX) else None)


def held_lines(ours: list[dict], theirs: list[dict], rec: CanonRecord) -> list[dict]:
    """rs274's moves, with the source line of a compensated move taken from ours.

    Under cutter compensation rs274ngc holds each move back until the next one; ``-g``
    prints the ``N`` of the block being run when a move is finally issued, so a held
    move carries a later line than the one that programmed it. Ours keep the line that
    programmed them, which must not be after rs274's."""
    if not Path(rec.source or "").stem.startswith(SEM_PREFIX + "comp"):
        return theirs
    out = []
    for mine, move in zip(ours, theirs, strict=False):
        assert mine.get("line", 0) <= move.get("line", 0), (mine, move)
        out.append(dict(move, line=mine.get("line")))
    return out + theirs[len(out):]


def _ids(paths: list[Path]) -> list[str]:
    return [p.stem for p in paths]


# --- the loader's interface, as docs/architecture.md describes it -------------------------


def _diagnostics(program, severity: str) -> list:
    """The program's diagnostics of one severity ("error" or "warning").

    ``Program.diagnostics`` is a list of ``Diagnostic(line, column, severity, message)``
    (``Program.errors`` / ``.warnings`` filter it); an object with ``errors`` and
    ``warnings`` lists is read too.
    """
    diags = program.diagnostics
    name = "errors" if severity == "error" else "warnings"
    if hasattr(diags, name):
        return list(getattr(diags, name))
    return [d for d in diags if d.severity == severity]


def error_lines(program) -> list[int]:
    return sorted({d.line for d in _diagnostics(program, "error")})


def describe_errors(program) -> str:
    return "; ".join(str(d) for d in _diagnostics(program, "error")[:5]) or "none"


def source_of(rec: CanonRecord) -> Path:
    assert rec.source, f"{rec.path}: no source in the header"
    return ROOT / rec.source


def lines_as_recorded(moves: list[dict]) -> list[dict]:
    """Our moves with the line a subroutine file's move has in the recording
    (``record.LIB_LINES`` per library file) and without the ``file`` key."""
    libs = {p.name: record.LIB_LINES * (i + 1) for i, p in enumerate(record.libraries())}
    out = []
    for move in moves:
        move = dict(move)
        name = move.pop("file", None)
        if name is not None:
            move["line"] += libs.get(name, 0)
        out.append(move)
    return out


def expected_moves(rec: CanonRecord) -> list[dict]:
    """rs274's moves, less its zero-length moves for G0/G1 blocks without axis words."""
    if source_of(rec).stem.startswith(SEM_PREFIX + "comp"):
        return rec.moves  # held moves carry a later line (see held_lines); none is axisless
    lines = source_of(rec).read_text().splitlines()
    return drop_axisless_moves(rec.moves, lines)


# --- the recordings themselves ------------------------------------------------------------


def test_every_sample_and_case_has_a_recording():
    cases = [p for p in sorted(CASES.glob("*.ngc")) if p not in record.libraries()]
    sources = sorted(SAMPLES.glob("*.ngc")) + cases
    recorded = {p.stem for p in RECORDS}
    missing = [p.name for p in sources if p.stem not in recorded]
    assert not missing, f"run tests/oracle/record.py for {missing}"
    assert len(SAMPLE_FILES) >= 4


@pytest.mark.parametrize("path", sorted(DATA.glob("*.canon")), ids=lambda p: p.stem)
def test_recording_matches_its_source(path):
    rec = read_record(path)
    assert rec.header["rs274"].startswith("linuxcnc"), rec.header
    source = source_of(rec)
    digest = hashlib.sha256(source.read_bytes()).hexdigest()
    assert digest == rec.header["sha256"], f"{source} changed since it was recorded: rerun record.py"


# --- moves ----------------------------------------------------------------------------------


@pytest.mark.parametrize("path", ACCEPTED, ids=_ids(ACCEPTED))
def test_moves_match_rs274(path):
    rec = read_record(path)
    program = load(source_of(rec))
    assert not error_lines(program), f"rs274 accepts it; errors: {describe_errors(program)}"
    ours = lines_as_recorded(program.moves)
    problems = compare_moves(ours, held_lines(ours, expected_moves(rec), rec))
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("path", SAMPLE_FILES, ids=_ids(SAMPLE_FILES))
def test_sample_loads_without_error(path):
    program = load(path)
    assert not error_lines(program), describe_errors(program)
    assert len(program.moves) > 50


@pytest.mark.parametrize("switch", [False, True])
def test_block_delete_matches_rs274_with_the_switch_off_and_on(switch):
    """LinuxCNC runs "/" lines when its block delete switch is off (rs274's default, and
    the loader's) and skips them when it is on (-b; ``load(..., block_delete=True)``)."""
    rec = read_record(DATA / ("block_delete+b.canon" if switch else "block_delete.canon"))
    moves = list(_load(source_of(rec), block_delete=switch).moves)
    assert not compare_moves(moves, expected_moves(rec))


# --- refusals -------------------------------------------------------------------------------


@pytest.mark.parametrize("path", REFUSED, ids=_ids(REFUSED))
def test_refused_where_rs274_refuses(path):
    rec = read_record(path)
    program = load(source_of(rec))
    assert error_lines(program) == [rec.error_line], (
        f"rs274 refused line {rec.error_line}: {rec.error_message}\nour errors: {describe_errors(program)}"
    )
    before = [m for m in program.moves if m.get("line", 0) < rec.error_line]
    expected = expected_moves(rec)
    if Path(rec.source or "").stem.startswith(SEM_PREFIX + "comp"):
        before = before[: len(expected)]  # rs274 stops with the last moves still held
    problems = compare_moves(before, held_lines(before, expected, rec))
    assert not problems, "\n".join(problems)


# Where our reason is worded differently from rs274's (the refusal is the same).
OWN_WORDING = {
    "sem_cycle_refuse_5": "a negative Q: rs274 calls it missing, we say it is negative",
    "sem_offset_refuse_5": "our list of G10 L numbers adds Fanuc's L12 and L13 (and has no L0)",
}
SEM_REFUSED = [p for p in REFUSED if p.stem.startswith(SEM_PREFIX)]


@pytest.mark.parametrize("path", SEM_REFUSED, ids=_ids(SEM_REFUSED))
def test_refusal_gives_rs274s_reason(path):
    """The interpreter's refusals (issue 9) give rs274's reason, in its words."""
    rec = read_record(path)
    program = load(source_of(rec))
    ours = " ".join(d.message for d in _diagnostics(program, "error")).lower()
    theirs = (rec.error_message or "").split(":")[0].strip().lower()
    if path.stem in OWN_WORDING:
        pytest.skip(OWN_WORDING[path.stem])
    assert theirs in ours, f"rs274: {rec.error_message!r}; ours: {ours!r}"


def test_refusal_cases_cover_both_outcomes_in_mm_and_inch_centre_and_radius():
    kinds = {}
    for p in sorted(DATA.glob("arctol_*.canon")):
        m = re.match(r"arctol_(mm|in)_(ijk|r)_", p.stem)
        if m:
            kinds.setdefault(m.groups(), set()).add(read_record(p).error_line is None)
    for units in ("mm", "in"):
        for fmt in ("ijk", "r"):
            assert kinds.get((units, fmt)) == {True, False}, (units, fmt, kinds)


# --- the rule rs274 applies, checked against what it did ----------------------------------

_WORD = re.compile(r"([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")


def _words(line: str) -> dict[str, float]:
    return {k: float(v) for k, v in _WORD.findall(line.upper().split("(")[0])}


def linuxcnc_refuses(text: str) -> bool:
    """LinuxCNC 2.9's arc check (interp_arc.cc, no ini) for the one-arc arctol files."""
    lines = text.splitlines()
    inch = "G20" in lines[1]
    plane = "XZ" if "G18" in lines[1] else "XY"
    start, arc = _words(lines[2]), _words(lines[4])
    a, b, i, j = ("Z", "X", "K", "I") if plane == "XZ" else ("X", "Y", "I", "J")
    s1, s2 = start[a], start[b]
    e1, e2 = arc.get(a, s1), arc.get(b, s2)
    if "R" in arc:  # arc_data_r: half chord longer than |R| by more than RADIUS_TOLERANCE
        if (e1, e2) == (s1, s2):
            return True
        tol = 0.00005 if inch else 0.00005 * MM_PER_INCH
        return math.hypot(e1 - s1, e2 - s2) / 2 - abs(arc["R"]) > tol
    c1, c2 = s1 + arc.get(i, 0.0), s2 + arc.get(j, 0.0)
    r1, r2 = math.hypot(s1 - c1, s2 - c2), math.hypot(e1 - c1, e2 - c2)
    if min(r1, r2) < (0.00005 if inch else 0.00005 * MM_PER_INCH):
        return True  # zero-radius arc
    tol = 2 * (0.001 if inch else 0.01) * math.sqrt(2)  # CENTER_ARC_RADIUS_TOLERANCE
    err = abs(r1 - r2)
    return err > 100 * tol or (err / max(r1, r2) > 0.001 and err > tol)


ARCTOL = sorted(DATA.glob("arctol_*.canon"))


@pytest.mark.parametrize("path", ARCTOL, ids=_ids(ARCTOL))
def test_documented_tolerance_rule_predicts_rs274(path):
    rec = read_record(path)
    refused = rec.error_line is not None
    assert linuxcnc_refuses(source_of(rec).read_text()) == refused, rec.error_message


# --- the moves format -----------------------------------------------------------------------

MOVE_KEYS = {
    "rapid": {"line", "kind", "end"},
    "feed": {"line", "kind", "end", "feed"},
    "arc": {"line", "kind", "end", "center", "plane", "turn", "feed"},
    "dwell": {"line", "kind", "seconds"},
}


@pytest.mark.parametrize("name", ["arcs_circles", "inch_plate"])
def test_moves_have_exactly_the_cnc_gcode_moves_format(name):
    moves = list(load(SAMPLES / f"{name}.ngc").moves)
    for move in moves:
        assert set(move) == MOVE_KEYS[move["kind"]], move
        assert isinstance(move["line"], int) and move["line"] >= 1, move
        if "end" in move:
            assert len(move["end"]) == 3, move
        if move["kind"] == "arc":
            assert len(move["center"]) == 2 and move["plane"] in ("XY", "XZ", "YZ"), move
    assert {m["kind"] for m in moves} == {"rapid", "feed", "arc"}


@pytest.mark.parametrize("source", ["resources/samples/inch_plate.ngc", "tests/oracle/cases/plane_g19.ngc"])
def test_cli_moves_match_rs274(source):
    """``cnc-gcode moves FILE`` (as ``python -m app.gcode``) prints the same moves, as JSON Lines."""
    out = subprocess.run(
        [sys.executable, "-m", "app.gcode", "moves", source],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    ).stdout
    moves = [json.loads(line) for line in out.splitlines() if line.strip()]
    rec = read_record(DATA / f"{Path(source).stem}.canon")
    problems = compare_moves(moves, expected_moves(rec))
    assert not problems, "\n".join(problems)
