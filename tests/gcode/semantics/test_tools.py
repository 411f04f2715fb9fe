"""The tool table: persistence, damaged files, and the words that use it."""

from __future__ import annotations

import contextlib
import io
import json

import pytest

from app.gcode import load, load_text
from app.gcode.tools import (
    FILE_NAME,
    Tool,
    ToolError,
    default_path,
    load_tools,
    save_tools,
)

from .conftest import ends


def test_round_trip_is_atomic(tmp_path):
    path = tmp_path / "cfg" / FILE_NAME
    table = {3: Tool(3, 6.0, 12.5, "6 mm end mill"), 1: Tool(1, 3.175, 0.0)}
    save_tools(path, table)
    assert load_tools(path).tools == table and load_tools(path).problem == ""
    assert [p.name for p in path.parent.iterdir()] == [FILE_NAME]  # no temporary file left


def test_missing_file_is_an_empty_table(tmp_path):
    loaded = load_tools(tmp_path / "none.json")
    assert loaded.tools == {} and loaded.problem == ""


@pytest.mark.parametrize("text, fragment", [
    ("{not json", "damaged"),
    ('{"version": 9, "tools": []}', "version"),
    ('{"version": 1, "tools": [{"number": 2, "diameter": -1}]}', "tool 2: diameter -1"),
    ('{"version": 1, "tools": [{"number": 0}]}', "tool number 0"),
    ('{"version": 1, "tools": [{"number": 4}, {"number": 4}]}', "listed twice"),
    ('{"version": 1, "tools": [{"number": 5, "length": "x"}]}', "length 'x' is not a number"),
])
def test_damaged_file_gives_an_empty_table_and_says_why(tmp_path, text, fragment):
    path = tmp_path / FILE_NAME
    path.write_text(text)
    loaded = load_tools(path)
    assert loaded.tools == {}
    assert fragment in loaded.problem and str(path) in loaded.problem


def test_tool_checks_its_fields():
    with pytest.raises(ToolError, match="diameter 200"):
        Tool(1, 200.0)
    with pytest.raises(ToolError, match="length 900"):
        Tool(1, 1.0, 900.0)


def test_default_path_is_next_to_the_settings():
    path = default_path()
    assert path.name == FILE_NAME and "cnc-mill-controller" in str(path)


def test_saved_json_lists_tools_in_order(tmp_path):
    path = tmp_path / FILE_NAME
    save_tools(path, {2: Tool(2, 1.0), 1: Tool(1, 2.0)})
    data = json.loads(path.read_text())
    assert data["version"] == 1 and [t["number"] for t in data["tools"]] == [1, 2]


def test_length_offsets_from_the_table(run):
    program = run("T2 M6\nG43\nG0 Z0\nG43 H3\nG0 Z0\nG49\nG0 Z0\nG43.1 Z2\nG0 Z0\n")
    assert [e[2] for e in ends(program)] == [12.5, -3.0, 0.0, 2.0]


def test_m61_sets_the_tool_without_a_pause(run):
    program = run("M61 Q3\nG43\nG0 Z1\n")
    assert not program.warnings and ends(program) == [[0, 0, -2]]


def test_g10_l1_changes_the_program_copy_only(run):
    from .conftest import TOOLS

    program = run("G10 L1 P1 R2 Z4\nG43 H1\nG0 Z0\n")
    assert ends(program) == [[0, 0, 4]] and TOOLS[1].length == 0.0


def test_unknown_tool(run):
    warned = run("T9 M6\n")
    assert not warned.errors and any("T9 is not in the tool table" in w.message for w in warned.warnings)
    for text in ("G43 H9", "G41 D9", "M61 Q9"):
        program = run(text + "\n")
        assert "Requested tool 9 not found" in program.errors[0].message, text


def test_fanuc_g10_l10_l12_set_length_and_radius(run):
    program = run("G10 L10 P2 R7.5\nG10 L12 P2 R1.5\nG43 H2\nG0 X-10 Z0\nG41 D2 G1 X0 F10\n"
                  "G40 G1 X0 Y-10\n")
    assert not program.errors
    assert ends(program)[0] == [-10, 0, 7.5] and ends(program)[1] == [0, 1.5, 7.5]


def test_fanuc_wear_offsets_are_refused(run):
    program = run("G10 L13 P2 R0.1\n")
    assert "wear" in program.errors[0].message


def test_fanuc_offset_registers_exist_without_a_tool_table():
    """Issue 19: on a Fanuc, G10 L12 P1 R5. writes register D1 whatever tools exist and
    G41 D1 reads it; a LinuxCNC program keeps rs274's rule (the tool must be in the table)."""
    body = "G21 G17 G90 F100\nG10 L12 P1 R5.\nG0 X0 Y0\nG41 D1 G1 X20 Y0\nG1 X20 Y20\nG40 G1 X30 Y30\n"
    fanuc = load_text(f"O0001\n{body}M30\n")
    assert not fanuc.errors
    assert fanuc.moves[1]["end"][:2] == pytest.approx([15.0, 5.0])  # R5 to the left: inside the corner
    linuxcnc = load_text(f"{body}M2\n")
    assert [d.line for d in linuxcnc.errors] == [2, 4]
    assert "not found in the tool table" in linuxcnc.errors[0].message


@pytest.mark.parametrize("macro", ["fanuc21", "fanuc31"])
def test_a_fanuc_feature_program_checks_with_an_empty_tool_table(tmp_path, macro):
    from app.gcode.features.cli import main as feature

    (tmp_path / "square.ngc").write_text("G0 X20 Y20\nG1 X60\nY50\nX20\nY20\n")
    out = tmp_path / "profile.nc"
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        assert feature(["profile", "--contour", str(tmp_path / "square.ngc"), "--side", "outside",
                        "--stock", "6", "--tool-diameter", "6", "--depth", "2", "--macro", macro]) == 0
    out.write_text(text.getvalue())
    program = load(out)
    assert "G10 L12" in text.getvalue() and not program.errors and len(program.moves) > 20
