"""The Qt-free core's messages: English strings that keep their template, shown in the
operator's language by ``localize``; ``cnc-gcode check`` follows LANG."""

from __future__ import annotations

import os
import pickle
import subprocess
import sys
from pathlib import Path

import pytest

from app import i18n
from app.gcode import load_text


@pytest.fixture
def vietnamese():
    i18n.set_language("vi")
    yield
    i18n.set_language("en")


def test_a_message_is_its_english_text():
    message = i18n.msg("unknown word {letter}", letter="Q")
    assert message == "unknown word Q" and isinstance(message, str)
    assert pickle.loads(pickle.dumps(message)).args == {"letter": "Q"}  # the helper process pickles it
    i18n.set_language("en")
    assert i18n.localize(message) == "unknown word Q"


def test_localize_in_vietnamese_with_decimal_comma(vietnamese):
    beyond = i18n.msg("{axis}{sign} beyond travel ({value:.3f} {rel} {limit:g})",
                      axis="X", sign="+", value=200.0, rel=">", limit=150.0)
    assert i18n.localize(beyond) == "vượt hành trình trục X theo chiều + (200,000 > 150)"
    assert i18n.localize("not connected") == "chưa kết nối"  # a plain constant, looked up whole
    assert i18n.localize("no such text anywhere") == "no such text anywhere"


def test_program_diagnostics_in_vietnamese(vietnamese):
    program = load_text("G0 X10 F100\nG1 E5 F100\n")  # (a program stops at its first error)
    arc = load_text("G0 X10 F100\nG2 X1 Y1\n")
    said = [d.localized() for d in program.errors + arc.errors]
    assert said == ["dòng 2, cột 4: chưa hỗ trợ từ lệnh E", "dòng 2, cột 1: cung tròn thiếu cả R, I, J và K"]
    assert [str(d) for d in program.errors][0] == "line 2, column 4: E words are not supported"


def test_a_bad_translation_never_hides_the_message(vietnamese, monkeypatch):
    monkeypatch.setattr(i18n, "gettext", lambda text: "{missing}")
    assert i18n.localize(i18n.msg("word {letter} has no number", letter="X")) == "word X has no number"


def _check(tmp_path, **env) -> subprocess.CompletedProcess:
    path = tmp_path / "bad.ngc"
    path.write_text("G0 X10 F100\nG1 X200\nG1 E5 F100\n")  # (a program stops at its first error)
    clean = {k: v for k, v in os.environ.items() if k not in ("LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG")}
    return subprocess.run([sys.executable, "-m", "app.gcode", "check", str(path)], env=clean | env,
                          capture_output=True, text=True, encoding="utf-8")


def test_cli_check_speaks_vietnamese_with_lang(tmp_path):
    result = _check(tmp_path, LANG="vi_VN.UTF-8")
    assert result.returncode == 1
    assert "lỗi: dòng 3, cột 4: chưa hỗ trợ từ lệnh E" in result.stdout
    assert "cảnh báo: dòng 2, cột 4: vượt hành trình trục X theo chiều + (200,000 > 150)" in result.stdout
    assert "quãng cắt: 190,0 mm" in result.stdout


def test_cli_check_stays_english_otherwise(tmp_path):
    result = _check(tmp_path, LANG="C.UTF-8")
    assert "error: line 3, column 4: E words are not supported" in result.stdout
    assert "cut length: 190.0 mm" in result.stdout
    assert "lỗi: dòng 3, cột 4" in _check(tmp_path, LANG="en_US.UTF-8", LC_MESSAGES="vi_VN.UTF-8").stdout


CASES = sorted((Path(__file__).resolve().parents[1] / "oracle" / "cases").glob("*.ngc"))
MORE = ["G0 X10\nG1 X200 F100\n", "G1 X1\n", "G4\n", "G0 A5\n", "G0 X1 X2\n", "M3 S100\nM4\nM8\nM6 T2\nM0\n",
        "/G0 X1\nM2\nG0 X5\n", "G1 X1 F100 (open\n", "G17 G18\n", "%\nG0 X1\n%x\n", "G0 X#1\n",
        "G1 X1 F100 I5\n", "T7 M6\nG43 H9\n", "G10 L11 P1 R2\n", "G86 X1 Y1 Z-1 R1 F100\n", "M72\n",
        "G5 X1 Y1 F100\n", "G92\n", "G41 D3\n", "G0 X1 @5\n", "G1 X1 F100 L2\n"]


@pytest.mark.parametrize("text", [p.read_text() for p in CASES] + MORE, ids=[p.stem for p in CASES] + MORE)
def test_every_diagnostic_is_a_translated_message(text, vietnamese):
    for d in load_text(text).diagnostics:
        assert isinstance(d.message, i18n.Message), f"{d.message!r} is a plain string: build it with msg()"
        assert i18n.localize(d.message) != d.message or not any(c.isalpha() for c in d.message), d.message


def test_tool_table_problems_in_vietnamese(vietnamese, tmp_path):
    from app.gcode.tools import ToolError, check_tool, load_tools

    with pytest.raises(ToolError) as caught:
        check_tool(2, -4.0, 0.0)
    assert str(caught.value) == "tool 2: diameter -4 mm is outside 0..100 mm"
    assert i18n.localize(caught.value.args[0]) == "dao 2: đường kính -4 mm nằm ngoài phạm vi 0..100 mm"
    path = tmp_path / "tools.json"
    path.write_text('{"version": 1, "tools": [{"number": 1}, {"number": 1}]}')
    problem = load_tools(path).problem
    assert problem.endswith("the tool table is damaged (tool 1 is listed twice); the table is empty")
    said = i18n.localize(problem)
    assert said.endswith("bảng dao bị hỏng (dao 1 có hai lần trong bảng); bảng dao để trống")
