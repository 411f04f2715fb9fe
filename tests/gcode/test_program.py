"""Loading files: bad input gives an error, never an exception; CLI commands."""

import json

import pytest

from app.gcode import load, load_text
from app.gcode.cli import main


def test_binary_and_non_utf8(tmp_path):
    binary = tmp_path / "a.ngc"
    binary.write_bytes(b"G0 X1\n\x00\x01\x02")
    latin = tmp_path / "b.ngc"
    latin.write_bytes(b"G0 X1\n(caf\xe9)\n")
    for path, fragment in ((binary, "NUL"), (latin, "UTF-8")):
        program = load(path)
        assert len(program.errors) == 1 and fragment in program.errors[0].message
        assert program.device_lines == [] and len(program.toolpath) == 0


def test_missing_file(tmp_path):
    program = load(tmp_path / "none.ngc")
    assert "cannot read" in program.errors[0].message


def test_crlf_and_no_final_newline():
    program = load_text("G0 X1\r\nG0 X2")
    assert program.source_lines == ["G0 X1", "G0 X2"] and not program.errors
    assert [m["line"] for m in program.moves] == [1, 2]


def test_errors_everywhere_still_load_the_rest():
    program = load_text("G0 X1\nG81\nG0 X2\nQ1\nG0 X3\nG0 A2\nG0 X4")
    assert [d.line for d in program.errors] == [2, 4, 6]
    assert [m["end"][0] for m in program.moves] == [1, 2, 3, 4]


@pytest.fixture
def sample(tmp_path):
    path = tmp_path / "s.ngc"
    path.write_text("G21\nG0 X1 Y2 Z3\nG1 X4 F100\nG2 X6 Y2 I1 J0\nG4 P0.5\nM2\n")
    return path


def test_cli_moves_format(sample, capsys):
    assert main(["moves", str(sample)]) == 0
    rows = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert rows[0] == {"line": 2, "kind": "rapid", "end": [1.0, 2.0, 3.0]}
    assert rows[1] == {"line": 3, "kind": "feed", "end": [4.0, 2.0, 3.0], "feed": 100.0}
    assert rows[2] == {"line": 4, "kind": "arc", "end": [6.0, 2.0, 3.0], "center": [5.0, 2.0],
                       "plane": "XY", "turn": -1, "feed": 100.0}
    assert rows[3] == {"line": 5, "kind": "dwell", "seconds": 0.5}


def test_cli_normalize(sample, capsys):
    assert main(["normalize", str(sample)]) == 0
    assert capsys.readouterr().out.splitlines()[0] == "G00 X1 Y2 Z3"


def test_cli_check_exit_status(sample, tmp_path, capsys):
    assert main(["check", str(sample)]) == 0
    out = capsys.readouterr().out
    assert "moves: 4" in out and "errors: 0" in out and "estimated time" in out
    bad = tmp_path / "bad.ngc"
    bad.write_text("G0 X1\nG84 X1\n")
    assert main(["check", str(bad)]) == 1
    assert "error: line 2, column 1: G84" in capsys.readouterr().out


def test_cli_usage_error(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["frobnicate", "x"])
    assert exc.value.code == 2
