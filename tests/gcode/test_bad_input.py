"""Issue 14 points 6-8: hostile numbers, files and encodings give clear diagnostics
(line and column), never a traceback, a hang or a silently different program."""

import os
import stat
import subprocess
import sys

import numpy as np
import pytest

from app.gcode import load, load_text
from app.gcode.limits import MAX_DWELL_S, MAX_FILE_BYTES, MAX_TURNS

BIG = "1" + "0" * 400


def errors(program):
    return [(d.line, d.column, d.message) for d in program.errors]


def only_error(program):
    found = errors(program)
    assert len(found) == 1, program.diagnostics
    return found[0]


# ---------------------------------------------------------------------- numbers (point 6)


@pytest.mark.parametrize("text,column", [
    (f"M{BIG}", 1), (f"G4 P{BIG}", 4), (f"G2 X0 Y0 I5 J0 F100 P{BIG}", 21), (f"G1 X{BIG} F100", 4),
    (f"G1 X10 F{BIG}", 8), (f"M3 S{BIG}", 4), (f"N{BIG} G0 X1", 1),
])
def test_huge_numbers_are_errors_with_line_and_column(text, column):
    program = load_text("G0 X0\n" + text + "\n")
    line, col, message = only_error(program)
    assert (line, col) == (2, column) and "too large" in message
    assert isinstance(program.device_lines, list)


def test_arc_turns_are_limited_before_anything_is_expanded():
    program = load_text("G0 X-5 Y0\nG2 X-5 Y0 I5 J0 F100 P100000000\n")
    line, col, message = only_error(program)
    assert (line, col) == (2, 22) and str(MAX_TURNS) in message
    assert len(program.device_lines) == 1


def test_dwell_is_limited():
    line, col, message = only_error(load_text(f"G4 P{MAX_DWELL_S + 1}\n"))
    assert (line, col) == (1, 4) and "dwell" in message and str(MAX_DWELL_S) in message


def test_cli_normalize_of_a_huge_number_is_an_error_not_a_traceback(tmp_path):
    path = tmp_path / "m.ngc"
    path.write_text(f"M{BIG}\nG2 X0 Y0 I5 J0 F100 P{BIG}\n")
    for command in ("check", "normalize", "moves"):
        done = subprocess.run([sys.executable, "-m", "app.gcode", command, str(path)],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 1, done.stderr
        assert "Traceback" not in done.stderr + done.stdout
        assert "line 1, column 1" in done.stderr + done.stdout


# ---------------------------------------------------------------------- files (point 6)


def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "pipe.ngc"
    os.mkfifo(fifo)
    line, col, message = only_error(load(fifo))
    assert "not a regular file" in message


def test_a_device_is_refused():
    assert "not a regular file" in only_error(load("/dev/zero"))[2]


def test_a_directory_is_refused(tmp_path):
    assert "not a regular file" in only_error(load(tmp_path))[2]


def test_size_limit_is_stated(tmp_path):
    path = tmp_path / "huge.ngc"
    with path.open("wb") as file:
        file.truncate(MAX_FILE_BYTES + 1)  # sparse: no disk used
    message = only_error(load(path))[2]
    assert f"{MAX_FILE_BYTES // (1 << 20)} MiB" in message


def test_file_mode_is_irrelevant_to_the_check(tmp_path):
    path = tmp_path / "ok.ngc"
    path.write_text("G0 X1\n")
    assert stat.S_ISREG(path.stat().st_mode) and not load(path).errors


# ---------------------------------------------------------------------- silent corruption (point 7)


@pytest.mark.parametrize("ending", ["\n", "\r\n", "\r"])
def test_every_line_ending_gives_the_same_program(tmp_path, ending):
    text = ending.join(["G0 Z5", "X10 Y10", "G1 Z-1 F100", "X20"]) + ending
    path = tmp_path / "e.ngc"
    path.write_bytes(text.encode())
    for program in (load(path), load_text(text)):
        assert not program.diagnostics, program.diagnostics
        assert len(program.source_lines) == 4
        assert program.device_lines == load_text(text.replace(ending, "\n")).device_lines
        assert len(program.device_lines) == 4 and program.device_lines[-1] == "G01 X20"


def test_mixed_cr_and_lf_endings(tmp_path):
    path = tmp_path / "m.ngc"
    path.write_bytes(b"G0 Z5\rX10 Y10\nG1 Z-1 F100\r\nX20\n")
    program = load(path)
    assert len(program.source_lines) == 4 and not program.diagnostics


@pytest.mark.parametrize("text,column,words", [
    ("M3 S-1000", 4, "negative"), ("G1 X10 F-100", 8, "negative"), ("G1 X10 F0.0000001", 8, "0.001"),
])
def test_values_the_machine_would_refuse_are_errors_at_load(text, column, words):
    program = load_text("G0 X0\n" + text + "\n")
    line, col, message = only_error(program)
    assert (line, col) == (2, column) and words in message
    assert "feed 0" not in message


def test_int64_never_wraps():
    program = load_text("G1 X10 F9223372036854775.808\nM3 S99999999999999999\nG4 P99999999999999999\n")
    assert [d.line for d in program.errors] == [1, 2, 3]
    assert not any("-9223372036854775" in line for line in program.device_lines)


def test_g91_piling_up_past_the_travel_is_named():
    program = load_text("G91\n" + "G1 X10 F100\n" * 100)
    named = [d for d in program.warnings if "spans X" in d.message and "G91" in d.message]
    assert len(named) == 1 and named[0].line == 18  # the first move that takes it past 150 mm
    assert not program.errors


@pytest.mark.parametrize("block", [1, 3, 16, 1 << 14])
def test_the_first_row_too_wide_is_found_block_by_block_as_in_one_pass(block):
    from app.gcode.limits import _first_too_wide

    rng = np.random.default_rng(13)
    for _ in range(300):
        ends = np.cumsum(rng.normal(0, rng.uniform(0.1, 30), int(rng.integers(1, 120))))
        span = float(rng.uniform(0, 200))
        over = np.flatnonzero(np.maximum.accumulate(ends) - np.minimum.accumulate(ends) > span + 1e-6)
        assert _first_too_wide(ends, span, block) == (int(over[0]) if len(over) else None)


@pytest.mark.parametrize("prefix", ["", "G0 X1 (general path)\n"])
def test_g91_runaway_is_an_error_on_both_paths(prefix):
    program = load_text(prefix + "G91\n" + "G1 X100000 F100\n" * 12)
    assert any("X coordinate out of range" in d.message for d in program.errors)
    assert all(abs(v) <= 1e6 for row in program.toolpath.end for v in row)


# ---------------------------------------------------------------------- encodings, empty (point 8)


def test_empty_file_says_it_has_no_moves(tmp_path):
    path = tmp_path / "empty.ngc"
    path.write_bytes(b"")
    for program in (load(path), load_text(""), load_text("(only a comment)\n")):
        assert any("no moves" in d.message for d in program.diagnostics), program.diagnostics


def test_utf8_bom_is_skipped(tmp_path):
    path = tmp_path / "bom.ngc"
    path.write_bytes(b"\xef\xbb\xbfG0 X1\nG0 X2\n")
    for program in (load(path), load_text("\ufeffG0 X1\nG0 X2\n")):
        assert not program.diagnostics
        assert program.device_lines == load_text("G0 X1\nG0 X2\n").device_lines


@pytest.mark.parametrize("encoding", ["utf-16", "utf-16-le", "utf-16-be", "latin-1", "cp1252"])
def test_other_encodings_get_one_clear_message(tmp_path, encoding):
    path = tmp_path / "enc.ngc"
    path.write_bytes("G0 X1 (café, 10°)\nG0 X2\n".encode(encoding))
    message = only_error(load(path))[2]
    assert "UTF-8" in message and ("UTF-16" in message if "16" in encoding else "Latin-1" in message)


@pytest.mark.parametrize("text", ["O²", "o²", "O1\n#1=²", "#1=[1+٣]"])
def test_unicode_digits_are_not_numbers(text):
    # found by the long fuzz run: "O²" passed str.isdigit() and float("²") raised ValueError
    program = load_text(text)
    assert program.diagnostics and all(d.line >= 1 for d in program.diagnostics)
