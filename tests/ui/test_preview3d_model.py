"""The 3-D view's model without a GPU: mesh, levels of detail, camera, measured path,
and scene lines."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from app.gcode import load_text
from app.ui.preview.geometry import RAPID_GROUP
from app.ui.preview.model import PreviewModel
from app.ui.preview3d import scene
from app.ui.preview3d.camera import PRESETS, Camera
from app.ui.preview3d.measured import RAMP, TOLERANCE_MM, MeasuredPath, deviation_colour
from app.ui.preview3d.mesh import PathMesh


def star_program(passes: int = 3, step: float = 1.0, outer: float = 40.0, inner: float = 16.0,
                 centre=(75.0, 75.0)) -> str:
    """A five-point star cut in ``passes`` depth passes of ``step`` mm (one plunge each)."""
    points = []
    for k in range(11):
        r = outer if k % 2 == 0 else inner
        a = math.pi / 2 + k * math.pi / 5
        points.append((centre[0] + r * math.cos(a), centre[1] + r * math.sin(a)))
    lines = ["G21 G90", "G0 Z5", f"G0 X{points[0][0]:.3f} Y{points[0][1]:.3f}", "M3 S4000"]
    for p in range(1, passes + 1):
        lines.append(f"G1 Z{-p * step:.3f} F100")
        lines += [f"G1 X{x:.3f} Y{y:.3f} F300" for x, y in points[1:]]
    return "\n".join([*lines, "G0 Z5", "M5", "M2"]) + "\n"


def _model(text: str) -> PreviewModel:
    return PreviewModel(load_text(text).toolpath, threads=1)


def test_mesh_keeps_the_geometry_in_13_bytes_per_segment():
    model = _model(star_program() + "G2 X80 Y75 I2.5 J0 F200\n")
    g = model.geometry
    mesh = PathMesh.from_geometry(g)
    assert mesh.points.dtype == np.float32 and mesh.group.dtype == np.uint8
    np.testing.assert_allclose(mesh.points, g.points, atol=1e-4)
    np.testing.assert_array_equal(mesh.group, g.group)
    assert mesh.segments == len(g.points) - 1
    assert mesh.bytes_per_segment() == pytest.approx(13 * len(g.points) / (len(g.points) - 1))
    for move in range(len(model.toolpath)):
        assert mesh.vertex_of_move(move) == g.vertex_of_move(move)
    assert mesh.vertex_of_move(-1) == -1


def test_the_three_passes_are_three_depth_bands_and_rapids_stay_rapids():
    mesh = PathMesh.from_geometry(_model(star_program()).geometry)
    cut = mesh.group != RAPID_GROUP
    depths = {round(float(z), 3) for z in mesh.points[1:][cut[1:] & (mesh.points[1:, 2] < 0)][:, 2]}
    assert depths == {-1.0, -2.0, -3.0}
    bands = {int(mesh.group[i]) for i in range(1, len(mesh.points)) if mesh.points[i, 2] < 0}
    assert len(bands) >= 3  # each pass is drawn in its own colour


def _spiral(n: int, turns: float = 30, passes: int = 3) -> SimpleNamespace:
    t = np.linspace(0, 2 * np.pi * turns, n)
    z = -np.floor(np.linspace(0, passes, n, endpoint=False))
    points = np.column_stack([50 + 40 * np.cos(t), 50 + 40 * np.sin(t), z])
    return SimpleNamespace(points=points, group=np.full(n, 2, np.int8), move=np.arange(n))


def _distance_to_segments(p, a, b) -> np.ndarray:
    ab = b - a
    t = np.clip(np.sum((p - a) * ab, axis=1) / np.maximum(np.sum(ab * ab, axis=1), 1e-12), 0, 1)
    return np.linalg.norm(a + ab * t[:, None] - p, axis=1)


def raster(rows: int = 200, per_row: int = 500) -> SimpleNamespace:
    """A relief carved row by row (zigzag in X, a step in Y each row, Z waving): what a
    million-line file from an image looks like."""
    x = np.linspace(10, 110, per_row)
    chains = []
    for row in range(rows):
        y = 10 + 100 * row / rows
        xs = x if row % 2 == 0 else x[::-1]
        chains.append(np.column_stack([xs, np.full(per_row, y), -1 - 0.5 * np.sin(xs / 7) * np.cos(y / 5)]))
    points = np.concatenate(chains)
    return SimpleNamespace(points=points, group=np.full(len(points), 3, np.int8), move=np.arange(len(points)))


def test_levels_are_spans_of_the_path_in_program_order_each_near_the_path_it_stands_for():
    mesh = PathMesh.from_geometry(_spiral(60_000))
    mesh.group[30_000:30_050] = RAPID_GROUP  # a run of another colour
    mesh.build_levels()
    assert mesh.levels and [lv.cell for lv in mesh.levels] == sorted(lv.cell for lv in mesh.levels)
    counts = [len(lv.ends) for lv in mesh.levels]
    assert counts == sorted(counts, reverse=True) and counts[-1] < counts[0] <= 0.6 * mesh.segments
    for level in mesh.levels:
        starts, ends = level.starts.astype(np.int64), level.ends.astype(np.int64)
        assert np.all(np.diff(ends) > 0) and np.all(starts < ends) and starts.min() >= 0
        np.testing.assert_array_equal(level.pairs().reshape(-1, 2), np.column_stack([starts, ends]))
        for s, e in zip(starts, ends, strict=True):  # one colour per span, the path within reach
            assert np.all(mesh.group[s + 1:e + 1] == mesh.group[e])
        # (no repeats in the spiral: the spans follow the path, each vertex near its span)
        span = np.repeat(np.arange(len(ends)), ends - starts)
        inside = np.concatenate([np.arange(s + 1, e + 1) for s, e in zip(starts, ends, strict=True)])
        reach = _distance_to_segments(mesh.points[inside], mesh.points[starts[span]], mesh.points[ends[span]])
        assert reach.max() <= 2 * math.sqrt(3) * level.cell
        assert level.spans_done(-1) == 0 and level.spans_done(int(ends[-1])) == len(ends)
        assert level.spans_done(int(ends[3])) == 4 and level.spans_done(int(ends[3]) - 1) == 3


def test_levels_keep_depth_passes_apart_and_repeats_once_the_last():
    # the same square ten times at Z -1, then once at Z -2: a level keeps one square per
    # depth, not one in all, and of the repeats the last (it is on top in a full draw)
    square = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], float)
    loop = [np.column_stack([square, np.full(4, -1.0)])] * 10 + [np.column_stack([square, np.full(4, -2.0)])]
    points = np.concatenate(loop)
    n = len(points)
    geometry = SimpleNamespace(points=points, group=np.full(n, 2, np.int8), move=np.arange(n))
    mesh = PathMesh.from_geometry(geometry)
    mesh.build_levels()
    for level in mesh.levels:
        z = mesh.points[:, 2]
        kept_z = {(float(z[s]), float(z[e])) for s, e in zip(level.starts, level.ends, strict=True)}
        assert (-1.0, -1.0) in kept_z and (-2.0, -2.0) in kept_z
        flat = [e for s, e in zip(level.starts, level.ends, strict=True) if z[s] == z[e] == -1.0]
        assert len(flat) == 4 and min(flat) >= 36  # the four sides at Z -1 once: of the tenth square


def test_pick_level_fits_the_pixel_and_the_budget():
    mesh = PathMesh.from_geometry(_spiral(100_000))
    assert mesh.pick_level(1.0, 1000) is None  # not built
    mesh.build_levels()
    level = mesh.pick_level(0.5, 10**9)
    assert level.cell <= 0.5
    assert all(lv.cell > 0.5 or lv is level or lv.cell < level.cell for lv in mesh.levels)
    tight = mesh.pick_level(0.0001, 5_000)
    assert len(tight.ends) <= 5_000 or tight is mesh.levels[-1]


def test_pick_full_takes_the_coarsest_level_well_under_a_pixel_else_every_segment():
    mesh = PathMesh.from_geometry(_spiral(100_000))
    assert mesh.pick_full(1.0, 0.5) is None  # not built: every segment
    mesh.build_levels()
    cells = [lv.cell for lv in mesh.levels]
    assert mesh.pick_full(cells[0] * 1.9, 0.5) is None  # no level fine enough
    assert mesh.pick_full(cells[2] * 2.5, 0.5) is mesh.levels[2]


def test_camera_presets_look_the_way_their_names_say():
    cam = Camera()
    cam.preset("top")
    right, up, towards = cam.rotation()
    np.testing.assert_allclose([right, up, towards], np.eye(3), atol=1e-12)
    cam.preset("front")
    right, up, towards = cam.rotation()
    np.testing.assert_allclose(up, [0, 0, 1], atol=1e-12)
    np.testing.assert_allclose(towards, [0, -1, 0], atol=1e-12)  # the operator's side
    cam.preset("side")
    np.testing.assert_allclose(cam.rotation()[2], [1, 0, 0], atol=1e-12)
    cam.preset("isometric")
    np.testing.assert_allclose(cam.rotation()[2], np.array([1, -1, 1]) / math.sqrt(3), atol=1e-12)
    assert set(PRESETS) == {"top", "front", "side", "isometric"}


def test_fit_shows_the_whole_box_and_zoom_keeps_the_cursor_point():
    cam = Camera(aspect=1.6)
    low, high = np.array([10.0, 5.0, -3.0]), np.array([120.0, 90.0, 5.0])
    for name in PRESETS:
        cam.preset(name)
        cam.fit(low, high)
        corners = np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                            for z in (low[2], high[2])])
        ndc = cam.project(corners)
        assert np.abs(ndc[:, :2]).max() <= 1.0
        assert np.abs(ndc[:, :2]).max() > 0.8  # and fills the view
        assert np.abs(ndc[:, 2]).max() < 1.0  # nothing clipped in depth
    point = cam.on_screen(0.3, -0.6)
    cam.zoom_at(2.5, 0.3, -0.6)
    np.testing.assert_allclose(cam.project(point[None])[0, :2], [0.3, -0.6], atol=1e-9)
    before = cam.project(point[None])[0, :2]
    cam.pan(0.1, 0.2)
    np.testing.assert_allclose(cam.project(point[None])[0, :2], before + [0.1, 0.2], atol=1e-9)
    cam.orbit(10, 200)
    assert cam.pitch == 90.0


def test_measured_path_grows_and_finds_the_largest_deviation():
    path = MeasuredPath()
    rng = np.random.default_rng(3)
    measured = rng.uniform(0, 100, (3000, 3))
    commanded = measured + rng.normal(0, 0.02, (3000, 3))
    commanded[1234] = measured[1234] + [0.3, 0.4, 0.0]  # 0.5 mm off
    for m, c in zip(measured, commanded, strict=True):
        path.append(m, c)
    assert len(path) == 3000 and path.capacity >= 3000
    np.testing.assert_allclose(path.rows()[:, :3], measured, atol=1e-4)
    np.testing.assert_allclose(path.rows()[:, 3], np.linalg.norm(measured - commanded, axis=1), atol=1e-5)
    worst = path.largest()
    assert worst.index == 1234 and worst.distance == pytest.approx(0.5, abs=1e-5)
    np.testing.assert_allclose(worst.commanded, commanded[1234])
    path.append([0, 0, 10], [0, 0, 0], rapid=True)  # 10 mm off during a rapid: not a deviation
    assert path.largest().index == 1234 and path.rows()[-1, 3] < 0
    version = path.version
    path.clear()
    assert len(path) == 0 and path.largest() is None and path.version > version


def test_deviation_colours_run_green_yellow_red():
    np.testing.assert_allclose(deviation_colour(0.0), RAMP[0])
    np.testing.assert_allclose(deviation_colour(TOLERANCE_MM / 2), RAMP[1])
    np.testing.assert_allclose(deviation_colour(TOLERANCE_MM), RAMP[2])
    np.testing.assert_allclose(deviation_colour(5.0), RAMP[2])
    assert deviation_colour([0.0, 0.1]).shape == (2, 3)


def test_scene_lines():
    box = scene.box_lines([-1, -2, -3], [4, 5, 6])
    assert box.shape == (24, 6)
    np.testing.assert_allclose(box[:, :3].min(axis=0), [-1, -2, -3])
    np.testing.assert_allclose(box[:, :3].max(axis=0), [4, 5, 6])
    lengths = np.linalg.norm(box[0::2, :3] - box[1::2, :3], axis=1)
    assert sorted(set(np.round(lengths, 4))) == [5.0, 7.0, 9.0]  # edges only, no diagonals
    tool = scene.tool_lines([10, 20, -1], 6.0)
    ring = tool[:-2, :3]
    np.testing.assert_allclose(np.linalg.norm(ring[:, :2] - [10, 20], axis=1), 3.0, atol=1e-5)
    assert np.all(ring[:, 2] == -1) and tool[-1, 2] > tool[-2, 2]
    assert scene.axes_lines(10).shape == (6, 6)


def test_program_tool_and_its_diameter():
    assert scene.program_tool(["G0 X1", "(T9 is not a word here)", "M6 T3", "T4"]) == 3
    assert scene.program_tool(["G1 X1 ; T5 in a comment"]) is None
    tools = {2: SimpleNamespace(diameter=6.0), 5: SimpleNamespace(diameter=1.5)}
    assert scene.tool_diameter(tools, 5) == (1.5, 5)
    assert scene.tool_diameter(tools, 7) == (6.0, 2)  # not in the table: its first tool
    assert scene.tool_diameter({}, 7) == (scene.DEFAULT_DIAMETER, None)


def test_the_program_tool_is_found_without_splitting_the_whole_file():
    from app.gcode.source import Lines

    body = b"G1 X1 Y1 F100\n" * (3 * scene.SCAN_LINES)
    lines = Lines(data=b"G21\n(T9 in a comment)\nM6 T7\n" + body)
    assert scene.program_tool(lines) == 7
    late = Lines(data=body + b"M6 T4\n")
    assert scene.program_tool(late) is None  # past the lines looked at
    assert lines._list is None and late._list is None  # the file was not split into a list


def test_visible_runs_keep_every_segment_on_screen_and_leave_out_the_rest():
    from app.ui.preview3d.chunks import visible_runs

    mesh = PathMesh.from_geometry(raster())
    mesh.build_levels()
    cam = Camera(aspect=1.6)
    cam.preset("top")
    cam.fit(*mesh.bounds())
    assert visible_runs(mesh.boxes, cam.project, mesh.segments) == [(0, mesh.segments)]  # all in view
    x, y, _ = cam.project(mesh.points[35_000][None])[0]
    cam.zoom_at(8.0, x, y)  # a part of the path
    runs = visible_runs(mesh.boxes, cam.project, mesh.segments)
    drawn = np.zeros(mesh.segments + 1, bool)
    for first, last in runs:
        drawn[first + 1:last + 1] = True  # the strip's segments first+1..last
    ndc = cam.project(mesh.points)
    inside = np.all(np.abs(ndc[:, :2]) <= 1, axis=1)
    on_screen = np.flatnonzero(inside[1:] | inside[:-1]) + 1  # segments with an end in view
    assert len(on_screen) and drawn[on_screen].all()
    assert drawn.sum() < mesh.segments / 4
    level = mesh.levels[0]
    spans = visible_runs(level.boxes, cam.project, len(level.ends))
    kept = np.zeros(len(level.ends), bool)
    for first, last in spans:
        kept[first:last] = True
    seen = inside[level.starts] | inside[level.ends]
    assert seen.any() and kept[seen].all() and kept.sum() < len(kept) / 4
