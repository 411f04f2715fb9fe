"""``cnc-gcode expand [--trace]`` and ``moves`` on expanded programs."""

import json

from app.gcode.cli import main

SUB = "o<hole> sub\n  G1 Z-1 F100\n  G0 Z1\no<hole> endsub\n"


def test_expand_prints_the_device_dialect_with_the_source_line(tmp_path, capsys):
    (tmp_path / "main.ngc").write_text("#1 = 5\nG0 X#1\no<hole> call\nM2\n")
    (tmp_path / "hole.ngc").write_text(SUB)
    assert main(["expand", str(tmp_path / "main.ngc")]) == 0
    plain = capsys.readouterr().out.splitlines()
    assert plain == ["G00 X5", "G01 Z-1 F100", "G00 Z1", "M02"]
    assert main(["expand", "--trace", str(tmp_path / "main.ngc")]) == 0
    traced = capsys.readouterr().out.splitlines()
    assert traced == ["G00 X5 (line 2)", "G01 Z-1 F100 (hole.ngc line 2, called at line 3)",
                      "G00 Z1 (hole.ngc line 3, called at line 3)", "M02 (line 4)"]


def test_moves_name_the_file_of_a_subroutine(tmp_path, capsys):
    (tmp_path / "main.ngc").write_text("G0 X1\no<hole> call\nM2\n")
    (tmp_path / "hole.ngc").write_text(SUB)
    assert main(["moves", str(tmp_path / "main.ngc")]) == 0
    moves = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert [(m["line"], m.get("file")) for m in moves] == [(1, None), (2, "hole.ngc"), (3, "hole.ngc")]


def test_trace_needs_expand(tmp_path, capsys):
    (tmp_path / "a.ngc").write_text("G0 X1\n")
    try:
        main(["moves", "--trace", str(tmp_path / "a.ngc")])
    except SystemExit as exc:
        assert exc.code == 2
    assert "--trace goes with expand" in capsys.readouterr().err


def _moved_x(capsys) -> list[float]:
    return [json.loads(line)["end"][0] for line in capsys.readouterr().out.splitlines()]


def test_block_delete_lines_run_unless_the_switch_is_on(tmp_path, capsys):
    """Plain and expanded programs alike, in a subroutine file too: "/" lines run with the
    switch off (the default); ``--block-delete`` skips them."""
    (tmp_path / "plain.ngc").write_text("G1 X1 F100\n/G1 X2\n / G1 X3\nG1 X4\n")
    (tmp_path / "macro.ngc").write_text("#1 = 2\nG1 X1 F100\n/G1 X#1\n/o1 if [1]\nG1 X3\n/o1 endif\n"
                                        "o<bd> call\nM2\n")
    (tmp_path / "bd.ngc").write_text("o<bd> sub\n/G1 X5\nG1 X6\no<bd> endsub\n")
    assert main(["moves", str(tmp_path / "plain.ngc")]) == 0
    assert _moved_x(capsys) == [1, 2, 3, 4]
    assert main(["moves", "--block-delete", str(tmp_path / "plain.ngc")]) == 0
    assert _moved_x(capsys) == [1, 4]
    assert main(["moves", str(tmp_path / "macro.ngc")]) == 0
    assert _moved_x(capsys) == [1, 2, 3, 5, 6]
    assert main(["moves", "--block-delete", str(tmp_path / "macro.ngc")]) == 0
    assert _moved_x(capsys) == [1, 3, 6]
