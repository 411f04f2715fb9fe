"""Features as programs: the plain text through the project's loader, validation
errors naming their parameter, the travel check, tool changes, the command line."""

from __future__ import annotations

import pytest

from app.gcode import load_text
from app.gcode.cli import main
from app.gcode.features import (
    Cutting,
    Face,
    FeatureError,
    PocketCircle,
    PocketRect,
    Profile,
    Slot,
    holes_circle,
    holes_row,
    parse_contour,
    program_moves,
    write_plain,
)
from app.gcode.features.moves import ARC, FEED, RAPID

from .test_geometry import PAPER

# the paper's part sits near X0 Y0; with the stock around it, it needs room from the travel's edge
PAPER_MOVED = """G00 X40 Y40
G01 X35 Y55
G02 X45 Y65 R10
G03 X70 Y65 R30
G02 X80 Y55 R10
G01 Y50
G01 X75 Y40
G01 X60 Y37
G01 X40 Y40
"""

CUT = Cutting(tool_diameter=6, depth=2, stepdown=1, finish_xy=0.2)

FEATURES = [
    Face(10, 10, 40, 20, CUT),
    PocketRect(20, 20, 40, 25, CUT, corner_radius=4, angle=30),
    PocketCircle(60, 60, 24, CUT),
    Slot(20, 20, 60, 40, 8, CUT),
    Profile(parse_contour(PAPER, "paper"), "inside", CUT),
    Profile(parse_contour(PAPER_MOVED, "paper"), "outside", CUT, stock=8),
    holes_circle(70, 70, 40, 6, CUT, start_angle=15, peck=0.7, dwell=0.5),
    holes_row(20, 100, 5, 10, CUT, angle=10),
]


@pytest.mark.parametrize("feature", FEATURES, ids=lambda f: f.kind)
def test_plain_output_loads_without_errors_and_gives_the_same_moves(feature):
    moves = program_moves([feature])
    program = load_text(write_plain(moves, feature.kind), "feature.nc")
    assert program.errors == []
    assert [w for w in program.warnings if "beyond travel" in w.message] == []
    motion = [m for m in moves if m.kind in (RAPID, FEED, ARC)]
    loaded = [m for m in program.moves if m["kind"] != "dwell"][1:]  # [0]: straight up to the safe height
    assert len(loaded) == len(motion)
    for mine, theirs in zip(motion, loaded, strict=True):
        assert max(abs(a - b) for a, b in zip(mine.end, theirs["end"], strict=True)) <= 0.001
        assert theirs["kind"] == {RAPID: "rapid", FEED: "feed", ARC: "arc"}[mine.kind]


def test_a_tool_change_pause_only_where_the_tool_differs():
    other = Cutting(tool_diameter=3, depth=4, tool=2, rpm=3000)
    job = [FEATURES[1], FEATURES[2], holes_row(20, 100, 3, 10, other), holes_row(20, 110, 3, 10, other)]
    program = load_text(write_plain(program_moves(job)), "job.nc")
    assert program.errors == []
    assert program.source_lines.count("M06 T2") == 1
    assert len(program.pauses) == 1 and "T2" in program.pauses[0][1]
    assert program.source_lines.count("M03 S3000") == 1


BAD = [
    (lambda: Cutting(tool_diameter=6, depth=-1), "depth",
     "must be a number above 0 and at most 100000 (got -1)"),
    (lambda: Cutting(tool_diameter=6, depth=1, stepover=0), "stepover", "above 0 and at most 100 (got 0)"),
    (lambda: Cutting(tool_diameter=6, depth=1, stepover=101), "stepover", "(got 101)"),
    (lambda: Cutting(tool_diameter=0, depth=1), "tool_diameter", "from 0.1 to 100000 (got 0)"),
    (lambda: Cutting(tool_diameter=6, depth=1, finish_z=1), "finish_z", "less than the depth"),
    (lambda: PocketRect(0, 0, 5, 20, CUT), "tool_diameter", "narrower than the pocket (5 mm)"),
    (lambda: PocketCircle(0, 0, 6, CUT), "tool_diameter", "narrower than the pocket"),
    (lambda: Slot(0, 0, 10, 0, 5, CUT), "tool_diameter", "wider than the slot (5 mm)"),
    (lambda: PocketRect(0, 0, 20, 10, CUT, corner_radius=6), "corner_radius", "half the smaller side"),
    (lambda: holes_circle(0, 0, 10, 0, CUT), "count", "from 1 to 10000 (got 0)"),
    (lambda: parse_contour("G00 X0 Y0\nG01 X10 Y0\nG01 X10 Y10\n", "open.nc"), "contour",
     "open.nc, line 3: the contour is not closed"),
    (lambda: parse_contour("G00 X0 Y0\nG01 X10 Y10\nG01 X10 Y0\nG01 X0 Y10\nG01 X0 Y0\n", "bow.nc"),
     "contour", "crosses itself"),
    (lambda: parse_contour("G00 X0 Y0\nG01 X10 Q3\n", "q.nc"), "contour", "q.nc, line 2, column 9: Q"),
    (lambda: parse_contour("G00 X0 Y0\nG02 X10 Y0 R2\nG01 X0 Y0\n", "r.nc"), "contour",
     "r.nc, line 2, column 12: an arc of radius 2 cannot reach"),
    (lambda: program_moves([PocketRect(130, 10, 30, 20, CUT)]), "x", "X+ beyond travel (157.000 > 150)"),
    (lambda: program_moves([PocketRect(10, -5, 30, 20, CUT)]), "y", "Y- beyond travel"),
    (lambda: program_moves([PocketRect(10, 10, 30, 20, Cutting(tool_diameter=6, depth=25))]), "depth",
     "Z- beyond travel (-25.000 < -20)"),
]


@pytest.mark.parametrize(("make", "field", "words"), BAD)
def test_bad_parameters_name_the_field_and_the_rule(make, field, words):
    with pytest.raises(FeatureError) as caught:
        make()
    assert caught.value.field == field
    assert words in str(caught.value)


def test_cli_prints_a_program_the_loader_reads(capsys):
    assert main(["feature", "pocket-circle", "--x", "50", "--y", "50", "--diameter", "20",
                 "--tool-diameter", "4", "--depth", "3", "--stepdown", "1.5"]) == 0
    program = load_text(capsys.readouterr().out)
    assert program.errors == []
    assert program.toolpath.bounds[0][2] == pytest.approx(-3)


def test_cli_profile_from_a_contour_file(tmp_path, capsys):
    contour = tmp_path / "island.nc"
    contour.write_text(PAPER_MOVED)
    args = ["feature", "profile", "--contour", str(contour), "--side", "outside", "--stock", "15",
            "--tool-diameter", "12", "--depth", "5", "--stepover", "75", "--finish-xy", "0.5"]
    assert main(args) == 0
    assert load_text(capsys.readouterr().out).errors == []


@pytest.mark.parametrize(("args", "message"), [
    (["--stepover", "120"], "--stepover: must be a number above 0 and at most 100 (got 120)"),
    (["--depth", "-2"], "--depth: must be a number above 0"),
    (["--x", "145"], "--x: X+ beyond travel"),
])
def test_cli_bad_parameter_names_the_option(args, message, capsys):
    base = {"--x": "10", "--y": "10", "--width": "30", "--height": "20",
            "--tool-diameter": "6", "--depth": "2"}
    base.update(dict(zip(args[::2], args[1::2], strict=True)))
    argv = ["feature", "pocket-rect"] + [item for pair in base.items() for item in pair]
    if "--stepover" in args:
        argv += args
    assert main(argv) == 2
    assert message in capsys.readouterr().err


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_cli_macro_dialects(dialect, capsys):
    assert main(["feature", "pocket-circle", "--x", "50", "--y", "50", "--diameter", "20",
                 "--tool-diameter", "4", "--depth", "3", "--macro", dialect]) == 0
    out = capsys.readouterr().out
    assert out.startswith("%\nO0001") and "O1001" in out and "M99" in out
    assert ("WHILE" in out) == (dialect == "fanuc31")


@pytest.mark.parametrize("dialect", ["fanuc21", "fanuc31"])
def test_cli_profile_in_the_papers_macro_form(dialect, tmp_path, capsys):
    from app.gcode.tools import Tool

    contour = tmp_path / "island.nc"
    contour.write_text(PAPER_MOVED)
    args = ["feature", "profile", "--contour", str(contour), "--side", "outside", "--stock", "15",
            "--tool", "2", "--tool-diameter", "12", "--depth", "5", "--stepover", "75", "--finish-xy", "0.5",
            "--macro", dialect]
    assert main(args) == 0
    out = capsys.readouterr().out
    assert "G10 L12 P2 R" in out and "G41 D2" in out
    assert load_text(out, tools={2: Tool(2, 12)}).errors == []
    assert load_text(out).errors == []  # Fanuc offset registers exist without a tool table (issue 19)
