"""Messages of the expander (issue 9), the features and point lists (issue 10) and the
preflight (issue 11) in Vietnamese, their English text unchanged."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from app import i18n
from app.gcode import load_text
from app.gcode.checks import preflight
from app.gcode.features import Cutting, FeatureError, parse_contour
from app.gcode.pointlist import PointListError, read_points
from app.profile import MachineProfile


@pytest.fixture
def vietnamese():
    i18n.set_language("vi")
    yield
    i18n.set_language("en")


BAD_MACROS = [
    "#1 = [1 / 0]\nG1 X#1 F100\n", "#1 = SQRT[-1]\n", "#1 = [2 MOD 0]\n", "#1 = [1 +\n", "#1 = FOO[2]\n",
    "#1 = ATAN[1]\n", "#1 = [#<nope>]\n", "#1 = #[1.5]\n", "#0 = 1\n", "#99999 = 1\n",
    "o100 while [1]\nG1 X1\n",
    "o100 endwhile\n", "o100 sub\no100 sub\n", "o100 call\n", "o<missing> call\n", "M98 P1234\n", "M99\n",
    "WHILE [1] DO 4\nEND 4\n", "END 1\n", "DO 1\n", "GOTO 5\n", "IF [1] THEN G1 X1\n", "o100 if\n",
    "(open\n", "%x\n", "o100 while [1]\nG0 X1\no100 endwhile\n", "#1 = EXISTS[#2]\n", "o100 frob\n",
    "#1 = " + "[" * 70 + "1" + "]" * 70 + "\n",
]


@pytest.mark.parametrize("text", BAD_MACROS)
def test_every_expander_diagnostic_is_translated(text, vietnamese):
    diagnostics = load_text(text).diagnostics
    assert diagnostics, text
    for d in diagnostics:
        assert isinstance(d.message, i18n.Message), f"{d.message!r} is a plain string: build it with msg()"
        assert i18n.localize(d.message) != d.message, d.message


def test_division_by_zero_in_both_languages(vietnamese):
    error = load_text("G21\n#1 = [1 / 0]\n").errors[0]
    assert str(error) == "line 2, column 9: division by zero"
    assert error.localized() == "dòng 2, cột 9: chia cho 0"
    loop = load_text("o100 while [1]\nG1 X1 F100\no100 endwhile\n").errors[0]
    assert "more than 1,000,000 times" in str(loop)
    assert "quá 1.000.000 lần" in loop.localized()  # thousands with a point in Vietnamese


def test_feature_rules_in_vietnamese(vietnamese):
    with pytest.raises(FeatureError) as caught:
        Cutting(tool_diameter=6, depth=3, stepover=120)
    assert str(caught.value) == "stepover: must be a number above 0 and at most 100 (got 120)"
    assert caught.value.field == "stepover"
    assert i18n.localize(caught.value.rule) == "phải là một số lớn hơn 0 và không quá 100 (nhập 120)"
    with pytest.raises(FeatureError) as caught:
        parse_contour("G1 X0 Y0\nG1 X10\nG1 Y10\n", "island.nc")
    assert caught.value.localized().startswith("contour: island.nc, dòng 3: biên dạng không khép kín")


def test_point_list_errors_in_vietnamese(vietnamese):
    with pytest.raises(PointListError) as caught:
        read_points(b"1 2 3\n4 x 6\n", "pts.xyz")
    assert str(caught.value) == "pts.xyz, line 2, column 3: expected a number (y), got 'x'"
    assert caught.value.localized() == "pts.xyz, dòng 2, cột 3: cần một số (y), gặp 'x'"


def test_preflight_in_vietnamese(vietnamese):
    program = load_text("G0 X10 Y10\nG1 X140 F100\n")
    (error,) = preflight(program.ops, MachineProfile(), program.source_lines, (20.0, 0.0, 0.0))
    assert str(error.message).endswith("1 move in all")
    said = i18n.localize(error.message)
    assert said.startswith("trục X theo chiều + vượt hành trình 10,000 mm khi gốc phôi ở tọa độ máy X20,000")


def test_cli_feature_and_import_speak_vietnamese(tmp_path):
    bad = tmp_path / "bad.xyz"
    bad.write_bytes(b"1 2 3\n4 x 6\n")
    clean = {k: v for k, v in os.environ.items() if k not in ("LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG")}
    env = clean | {"LANG": "vi_VN.UTF-8"}
    run = [sys.executable, "-m", "app.gcode"]
    feature = subprocess.run([*run, "feature", "pocket-rect", "--x", "20", "--y", "20", "--width", "40",
                              "--height", "25", "--tool-diameter", "6", "--depth", "3", "--stepover", "120"],
                             capture_output=True, text=True, encoding="utf-8", env=env, check=False)
    said = "cnc-gcode feature: --stepover: phải là một số lớn hơn 0 và không quá 100 (nhập 120)"
    assert said in feature.stderr
    imported = subprocess.run([*run, "import", str(bad)], capture_output=True, text=True, encoding="utf-8",
                              env=env, check=False)
    assert "dòng 2, cột 3: cần một số (y), gặp 'x'" in imported.stderr
