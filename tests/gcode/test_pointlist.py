"""Point-list import: both formats recognised by content, placement, G-code through
the loader, each malformed case refused with its line and what was expected."""

from __future__ import annotations

import numpy as np
import pytest

from app.gcode import load_text
from app.gcode.cli import main
from app.gcode.pointlist import ImportOptions, PointListError, looks_like_points, read_points, to_gcode

PLAIN = b"""# two paths
1 2 -0.5
4,5,-0.5
6\t5\t-0.5   # tab separated

10 10 -1
12 10 -1
"""

FAB = b"""===== Fabrication Task =====
Format Version : 01
== General Information ==
Exposure Time : 1
Laser Power : 0.250000
Voxel Distance : 0.700000
Flag of 'Start from Top' : 1
== Scan Path Information ==
Number of Total Paths : 2
Path Number : 0
Number of Total Points : 3
0.000000 134.817570 810.000000
0.699612 134.817570 810.000000
1.399223 134.817570 810.000000
Path Number : 1
Number of Total Points : 2
2.098835 130.000000 810.000000
2.798446 130.000000 810.000000
"""


def test_plain_paths_are_separated_by_blank_lines():
    points = read_points(PLAIN, "p.xyz")
    assert points.format == "plain"
    assert [p.tolist() for p in points.paths] == [
        [[1, 2, -0.5], [4, 5, -0.5], [6, 5, -0.5]], [[10, 10, -1], [12, 10, -1]]]


def test_fabrication_task_header_and_paths():
    points = read_points(FAB, "task.txt")
    assert points.format == "fabrication"
    assert points.header["Voxel Distance"] == "0.700000"
    assert points.header["Flag of 'Start from Top'"] == "1"
    assert [len(p) for p in points.paths] == [3, 2]
    assert points.paths[1][0].tolist() == [2.098835, 130.0, 810.0]


def test_recognised_by_content_not_name():
    assert looks_like_points(PLAIN) and looks_like_points(FAB)
    assert not looks_like_points(b"G00 X1 Y2\nG01 X3 Y4 F100\n")
    assert not looks_like_points(b"(a comment)\nX1 Y2 Z3\n")


def test_each_path_retracts_rapids_feeds_down_and_through_its_points():
    text, placement = to_gcode(read_points(PLAIN, "p.xyz"), ImportOptions(feed=250, clearance=3))
    program = load_text(text)
    assert program.errors == []
    kinds = [(m["kind"], m["end"]) for m in program.moves]
    assert kinds[:6] == [("rapid", [0, 0, 3]), ("rapid", [1, 2, 3]), ("feed", [1, 2, -0.5]),
                         ("feed", [4, 5, -0.5]), ("feed", [6, 5, -0.5]), ("rapid", [6, 5, 3])]
    assert kinds[6:] == [("rapid", [6, 5, 3]), ("rapid", [10, 10, 3]), ("feed", [10, 10, -1]),
                         ("feed", [12, 10, -1]), ("rapid", [12, 10, 3])]
    assert {m["feed"] for m in program.moves if m["kind"] == "feed"} == {250}
    assert placement.scale == 1 and placement.offset == (0, 0)


def test_fit_scales_uniformly_into_the_travel_and_the_summary_says_so():
    points = read_points(FAB, "task.txt")
    text, placement = to_gcode(points, ImportOptions(fit=True, cut_z=-0.3))
    program = load_text(text)
    assert program.errors == [] and program.warnings == []
    ends = np.array([m["end"] for m in program.moves[1:]])  # [0] is the machine's start
    low, high = ends.min(axis=0), ends.max(axis=0)
    assert low[0] >= 5 - 1e-6 and high[0] <= 145 + 1e-6 and low[1] >= 5 - 1e-6 and high[1] <= 145 + 1e-6
    assert max(high[:2] - low[:2]) == pytest.approx(140, abs=0.002)  # the longer side fills the travel
    size = np.ptp(np.vstack(points.paths)[:, :2], axis=0)
    assert (high[1] - low[1]) / (high[0] - low[0]) == pytest.approx(size[1] / size[0], rel=1e-3)
    summary = placement.describe(points, ImportOptions(fit=True, cut_z=-0.3))
    assert f"scale {placement.scale:.6g}" in summary and "offset X" in summary and "cut Z -0.3" in summary


def test_scale_multiplies():
    _, placement = to_gcode(read_points(PLAIN), ImportOptions(scale=2.5))
    assert placement.high[:2] == (30.0, 25.0)


MALFORMED = [
    (PLAIN.replace(b"4,5,-0.5", b"4,five,-0.5"), "line 3, column 3: expected a number (y), got 'five'"),
    (PLAIN.replace(b"10 10 -1", b"10 10"), "line 6: expected three numbers 'x y z', got 2"),
    (PLAIN.replace(b"12 10 -1", b"12 10 -1 7"), "line 7: expected three numbers 'x y z', got 4"),
    (b"# nothing\n\n", "expected points 'x y z', found none"),
    (FAB.replace(b"Number of Total Points : 2", b"Number of Total Points : 5"),
     "line 18: path 1 announced 5 points, found 2 before the end of the file"),
    (FAB.replace(b"Number of Total Points : 3", b"Number of Total Points : 4"),
     "line 15: path 0 announced 4 points, found 3 before 'Path Number : 1'"),
    (FAB.replace(b"Number of Total Paths : 2\n", b""), "line 9, column 1: expected 'Number of Total Paths"),
    (FAB.replace(b"Number of Total Paths : 2", b"Number of Total Paths : two"),
     "line 9, column 25: expected a whole number after 'Number of Total Paths :', got 'two'"),
    (FAB.replace(b"== Scan Path Information ==\n", b""), "expected the line '== Scan Path Information =='"),
    (FAB.replace(b"Path Number : 1\n", b""), "line 15, column 1: expected 'Path Number : ...'"),
    (FAB.replace(b"0.699612 134.817570", b"0.699612 13x.817570"),
     "line 13, column 10: expected a number (y)"),
    (FAB.replace(b"Number of Total Paths : 2", b"Number of Total Paths : 1"),
     "line 15: expected the end of the file after 1 paths, got 'Path Number : 1'"),
]


@pytest.mark.parametrize(("raw", "message"), MALFORMED)
def test_malformed_files_are_refused_with_the_line_and_what_was_expected(raw, message):
    with pytest.raises(PointListError) as caught:
        read_points(raw, "f.txt")
    assert message in str(caught.value)
    assert str(caught.value).startswith("f.txt")


def test_points_above_the_clearance_are_refused_without_a_cut_z():
    with pytest.raises(PointListError, match="reach Z 810.*give a cut Z") as caught:
        to_gcode(read_points(FAB, "f.txt"), ImportOptions())
    assert str(caught.value).startswith("f.txt: points reach Z")  # the whole list: no "line 0"


def test_cli_import_prints_gcode_and_the_summary(tmp_path, capsys):
    path = tmp_path / "drawing.txt"
    path.write_bytes(FAB)
    assert main(["import", str(path), "--fit", "--cut-z", "-0.2", "--feed", "200", "--clearance", "4"]) == 0
    out, err = capsys.readouterr()
    assert load_text(out).errors == []
    assert "scale" in err and "offset X" in err and "2 paths, 5 points (fabrication)" in err


def test_cli_import_refuses_a_malformed_file(tmp_path, capsys):
    path = tmp_path / "bad.xyz"
    path.write_bytes(b"1 2 3\n4 5\n")
    assert main(["import", str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and "bad.xyz, line 2: expected three numbers" in err


def test_telling_a_point_list_apart_does_not_import_the_converter():
    """The window asks ``looks_like_points`` of every file it opens; the converter brings
    the features' modules (0.1 s or more of the first Open), and only an import needs it."""
    import subprocess
    import sys

    probe = ("import sys; from app.gcode.pointlist import looks_like_points\n"
             "assert looks_like_points(b'1 2 3\\n4 5 6\\n')\n"
             "assert 'app.gcode.pointlist.convert' not in sys.modules\n"
             "assert 'app.gcode.features' not in sys.modules\n"
             "from app.gcode.pointlist import to_gcode\n"
             "assert 'app.gcode.pointlist.convert' in sys.modules")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
