"""Hostile option values (issue 19): ``inf``, ``nan``, 1e12, 0.00001, counts in the
millions, depths of 1e6, a corner radius at the limit. Whatever ``cnc-gcode feature`` and
``cnc-gcode import`` are given, they answer with their own error naming the option (or
its file) and its range, never a traceback or a run of minutes, and what they accept
the loader reads without an error."""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.gcode import load_text
from app.gcode.features import FeatureError
from app.gcode.features.cli import KIND_OPTIONS, _parser, build
from app.gcode.features.fanuc import write_fanuc
from app.gcode.features.generate import program_moves
from app.gcode.features.plain import write_plain
from app.gcode.features.ranges import RANGES
from app.gcode.pointlist import ImportOptions, PointListError, read_points, to_gcode
from app.gcode.pointlist.cli import main as import_main
from app.profile import MachineProfile

HOSTILE = ["inf", "-inf", "nan", "1e12", "-1e12", "0.00001", "1e6", "0", "-3", "5000000", "1e-9", "3.5"]
SANE = {"x": "20", "y": "20", "x1": "20", "y1": "20", "x2": "60", "y2": "35", "width": "30", "height": "20",
        "diameter": "24", "count": "4", "pitch": "8", "corner-radius": "2", "angle": "10", "start-angle": "0",
        "tool-diameter": "4", "depth": "2", "stepdown": "1", "stepover": "50", "finish-xy": "0.2",
        "finish-z": "0.1", "clearance": "5", "feed": "300", "plunge-feed": "100", "rpm": "3000", "tool": "1",
        "peck": "0.5", "dwell": "0.5", "stock": "4"}
COMMON = ["tool-diameter", "depth", "stepdown", "stepover", "finish-xy", "finish-z", "clearance", "feed",
          "plunge-feed", "rpm", "tool"]
KINDS = [k for k in KIND_OPTIONS if k != "profile"]
SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def _argv(kind: str, changes: dict[str, str]) -> list[str]:
    names = [n.rstrip("?") for n in KIND_OPTIONS[kind]] + COMMON
    if kind.startswith("holes"):
        names += ["peck", "dwell"]
    argv = [kind]
    for name in names:
        argv += [f"--{name}", changes.get(name, SANE[name])]
    return argv


def _run(argv: list[str], dialect: str | None = None) -> str | None:
    """The program text, or None when refused with the feature's own error."""
    try:
        args = _parser(MachineProfile()).parse_args(argv)
    except SystemExit:  # argparse: a whole number was expected (count, tool)
        return None
    try:
        moves = program_moves([build(args)], MachineProfile())
    except FeatureError as exc:
        assert exc.field.replace("_", "-") in argv[0] + " ".join(argv) or exc.field in ("x", "y", "z")
        return None
    return write_fanuc(moves, dialect) if dialect else write_plain(moves)


@SETTINGS
@given(st.sampled_from(KINDS), st.dictionaries(st.sampled_from(sorted(SANE)), st.sampled_from(HOSTILE),
                                               max_size=3), st.sampled_from([None, "fanuc21", "fanuc31"]))
def test_hostile_feature_options_are_refused_or_load_cleanly(kind, changes, dialect):
    text = _run(_argv(kind, changes), dialect)
    if text is not None:
        program = load_text(text)
        assert not program.errors, (changes, program.errors[:3])


@pytest.mark.parametrize(("kind", "option", "value", "words"), [
    ("pocket-rect", "width", "inf", "--width"),
    ("pocket-rect", "height", "nan", "--height"),
    ("pocket-rect", "width", "1e12", "--width"),
    ("pocket-rect", "tool-diameter", "0.00001", "from 0.1"),
    ("pocket-rect", "stepover", "0.00001", "rings"),
    ("pocket-rect", "stepdown", "0.00001", "from 0.01"),
    ("pocket-rect", "depth", "1e6", "at most 100000"),
    ("pocket-rect", "feed", "1e-9", "from 0.001"),
    ("pocket-rect", "rpm", "1e12", "--rpm"),
    ("holes-row", "count", "5000000", "from 1 to 10000"),
    ("holes-row", "dwell", "1000000000", "from 0 to 3600"),
    ("holes-row", "peck", "0.00001", "moves"),
    ("face", "stepover", "0.001", "--stepover"),
])
def test_each_hostile_value_names_its_option_and_range(kind, option, value, words, capsys):
    from app.gcode.cli import main

    assert main(["feature", *_argv(kind, {option: value})]) == 2
    err = capsys.readouterr().err
    assert f"--{option}:" in err and words in err and "Traceback" not in err


def test_a_corner_radius_at_the_limit_is_a_stadium_pocket():
    text = _run(_argv("pocket-rect", {"width": "30", "height": "20", "corner-radius": "10"}))
    assert text is not None and not load_text(text).errors


@pytest.mark.parametrize("path", ["/dev/zero", "/dev/null", "/tmp"])
def test_contour_and_point_files_pass_the_loaders_file_checks(path, capsys):
    from app.gcode.cli import main

    assert main(["feature", "profile", "--contour", path, "--side", "inside", "--tool-diameter", "3",
                 "--depth", "2"]) == 2
    assert "regular file" in capsys.readouterr().err
    assert import_main([path]) == 1
    assert "regular file" in capsys.readouterr().err


def test_a_fifo_is_refused_without_waiting(tmp_path, capsys):
    import os

    fifo = tmp_path / "points.fifo"
    os.mkfifo(fifo)
    assert import_main([str(fifo)]) == 1
    assert "regular file" in capsys.readouterr().err


POINTS = read_points(b"0 0 -1\n10 0 -1\n10 5 -1\n", "p.txt")
IMPORT_VALUES = [math.inf, -math.inf, math.nan, 1e12, 1e-9, 0.0, -1.0, 1e20, 3.0]


@SETTINGS
@given(st.booleans(), st.sampled_from(IMPORT_VALUES), st.one_of(st.none(), st.sampled_from(IMPORT_VALUES)),
       st.sampled_from(IMPORT_VALUES + [300.0]), st.sampled_from(IMPORT_VALUES + [5.0]))
def test_hostile_import_options_are_refused_or_load_cleanly(fit, scale, cut_z, feed, clearance):
    try:
        options = ImportOptions(fit, scale, cut_z, feed, clearance)
        text, _ = to_gcode(POINTS, options, MachineProfile())
    except FeatureError as exc:
        low, high, _ = RANGES[exc.field]
        assert f"{high:g}" in str(exc)
        return
    except PointListError:
        return
    program = load_text(text)
    assert not program.errors, program.errors[:3]


def test_a_point_at_1e20_is_refused_not_written_with_its_sign_flipped():
    with pytest.raises(PointListError, match="too large"):
        read_points(b"0 0 0\n1e20 0 0\n", "far.txt")
    with pytest.raises(PointListError, match="beyond"):
        to_gcode(read_points(b"0 0 -1\n1e8 0 -1\n", "far.txt"), ImportOptions(scale=100.0))
