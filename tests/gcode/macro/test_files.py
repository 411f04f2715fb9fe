"""The files a program reads besides itself (issue 19): where they are looked for, the
main file's checks on each, names that are not plain file names, and mixed styles."""

import os

import pytest

from app.gcode import load, load_text
from app.gcode.macro.calls import MAX_NAME


def _errors(program):
    return [(d.line, d.message) for d in program.errors]


def test_a_subroutine_file_is_found_beside_the_program_or_in_its_subs_folder(tmp_path):
    (tmp_path / "subs").mkdir()
    (tmp_path / "subs" / "inner.ngc").write_text("o<inner> sub\nG1 X9\no<inner> endsub\n")
    (tmp_path / "outer.ngc").write_text("o<outer> sub\nG1 X8\no<inner> call\no<outer> endsub\n")
    (tmp_path / "main.ngc").write_text("G21 F100\no<outer> call\nM2\n")
    program = load(tmp_path / "main.ngc")
    assert not program.errors
    assert [(m["end"][0], m.get("file")) for m in program.moves] == [(8.0, "outer.ngc"), (9.0, "inner.ngc")]


def test_a_missing_subroutine_says_where_it_was_looked_for(tmp_path):
    (tmp_path / "main.ngc").write_text("G21 F100\no<nothere> call\nM2\n")
    ((line, message),) = _errors(load(tmp_path / "main.ngc"))
    assert line == 2
    assert f"nothere.ngc in {tmp_path} or {tmp_path / 'subs'}" in message


@pytest.mark.parametrize("name", ["../x", "/etc/passwd", "subs/x", "a\\\\b", ".."])
def test_a_name_with_a_path_is_refused(tmp_path, name):
    (tmp_path / "x.ngc").write_text("o<x> sub\no<x> endsub\n")
    (tmp_path / "main.ngc").write_text(f"G21 F100\no<{name}> call\nM2\n")
    ((line, message),) = _errors(load(tmp_path / "main.ngc"))
    assert line == 2 and "cannot hold a path" in message


def test_a_name_too_long_for_a_file_is_refused_without_a_traceback(tmp_path):
    (tmp_path / "main.ngc").write_text(f"G21 F100\no<{'a' * 200}> call\nM2\n")
    ((line, message),) = _errors(load(tmp_path / "main.ngc"))
    assert line == 2 and f"longer than {MAX_NAME} characters" in message


def _call(tmp_path, name: str):
    (tmp_path / "main.ngc").write_text(f"G21 F100\nG1 X1\no<{name}> call\nG1 X2\nM2\n")
    program = load(tmp_path / "main.ngc")
    ((line, message),) = _errors(program)
    assert line == 3 and len(program.moves) == 1
    return message


def test_every_file_read_passes_the_main_files_checks(tmp_path):
    with open(tmp_path / "huge.ngc", "wb") as f:  # sparse: no disk used
        f.truncate(600 << 20)
    assert "is 600 MiB: files up to 256 MiB can be loaded" in _call(tmp_path, "huge")
    os.mkfifo(tmp_path / "pipe.ngc")
    assert "is not a regular file" in _call(tmp_path, "pipe")  # and nothing blocks
    (tmp_path / "nul.ngc").write_bytes(b"o<nul> sub\nG1 X1\x00\no<nul> endsub\n")
    assert "contains NUL bytes" in _call(tmp_path, "nul")
    (tmp_path / "latin.ngc").write_bytes("o<latin> sub\n(caf\xe9)\no<latin> endsub\n".encode("latin-1"))
    assert "not UTF-8 text" in _call(tmp_path, "latin")


@pytest.mark.parametrize("text, line", [
    ("O0001\nG21 F100\no100 sub\nG1 X1\no100 endsub\no100 call\nM30\n", 3),
    ("G21 G90 F100\nO100\nG1 X1\no100 endsub\nM98 P100\nM2\n", 4),  # rs274 refuses it there too
    ("G21 G90 F100\nO100 sub\nG1 X1\nM99\nM98 P100\nM2\n", 2),
])
def test_fanuc_o_numbers_mixed_with_o_word_statements_are_refused(text, line):
    program = load_text(text)
    assert program.errors[0].line == line
    assert all("one style per program" in d.message for d in program.errors)


@pytest.mark.parametrize("text", ["O0001\nG21 G90 F100\nG1 X1\nM99\n",
                                  "%\nO0001\nG21 G90 F100\nG1 X1\nM99\n%\n"])
def test_a_main_program_ended_by_m99_is_stopped_after_one_pass_saying_why(text):
    program = load_text(text)
    ((line, message),) = _errors(program)
    assert text.splitlines()[line - 1] == "M99"
    assert "starts it again, for ever" in message and len(program.moves) == 1


def test_a_numbered_main_program_ended_by_the_closing_percent_runs(tmp_path):
    """No M30: the closing % ends it (the subprogram in its own file beside it)."""
    (tmp_path / "O0002.nc").write_text("O0002\nG1 Y4\nM99\n")
    (tmp_path / "main.nc").write_text("%\nO0001\nG21 G90 G17 F100\nG1 X1 Y1\nM98 P2\nG1 X3\n%\n")
    program = load(tmp_path / "main.nc")
    assert not program.errors
    assert [m["end"][:2] for m in program.moves] == [[1.0, 1.0], [1.0, 4.0], [3.0, 4.0]]
