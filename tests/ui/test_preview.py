"""The preview: plotted extents equal the program's bounds, level of detail stays
within its budget, the finished part and the highlighted move."""

import numpy as np
import pytest

from app.gcode import load, load_text
from app.ui.preview.lod import CHUNK, LodSegments
from app.ui.preview.model import PreviewModel
from app.ui.preview.widget import DONE_COLOUR, PreviewWidget
from app.ui.program.summary import bounds_array
from tests.ui.conftest import SAMPLE_FILES


@pytest.fixture
def preview(qtbot):
    widget = PreviewWidget()
    qtbot.addWidget(widget)
    widget.resize(800, 600)
    widget.show()
    qtbot.waitExposed(widget)
    return widget


@pytest.mark.parametrize("path", SAMPLE_FILES, ids=lambda p: p.name)
def test_plotted_extents_equal_program_bounds(preview, path):
    program = load(path)
    preview.show_program(program.toolpath)
    (xmin, ymin, _), (xmax, ymax, _) = bounds_array(program.toolpath.bounds)  # exact, arcs' bulges too
    # Chords are drawn within the tolerance (0.01 mm) inside their arcs: the plotted
    # extents equal the bounds to that tolerance, and never pass them (but for the
    # float32 the preview draws with: 1e-5 mm at 150 mm).
    px0, px1, py0, py1 = preview.plotted_bounds()
    assert (px0, px1, py0, py1) == pytest.approx((xmin, xmax, ymin, ymax), abs=0.01)
    eps = 1e-4
    assert px0 >= xmin - eps and px1 <= xmax + eps and py0 >= ymin - eps and py1 <= ymax + eps
    (x0, x1), (y0, y1) = preview.view.viewRange()
    assert x0 <= xmin and x1 >= xmax and y0 <= ymin and y1 >= ymax


def test_rapids_dashed_and_cuts_coloured_by_depth(preview):
    program = load(next(p for p in SAMPLE_FILES if "star_passes" in p.name))
    preview.show_program(program.toolpath)
    assert preview.group_pens[0].style() != preview.group_pens[2].style()  # rapids dashed
    drawn = [i for i, (x, _) in enumerate(preview.group_data[2:]) if len(x)]
    assert len(drawn) >= 3  # four passes at -0.75 .. -3 fall in several depth bands


def test_arcs_are_smooth(preview):
    program = load_text("G21 G90\nG0 X10 Y0\nG1 Z-1 F100\nG2 X10 Y0 I-10 J0 F300\n")
    model = PreviewModel(program.toolpath, tolerance=0.01)
    circle = model.geometry.move_vertices(2)
    radius = np.hypot(circle[:, 0], circle[:, 1])
    assert len(circle) > 60 and np.allclose(radius, 10.0, atol=1e-9)


def _green_pixels(image) -> int:
    """Pixels of the finished colour in a QImage."""
    from PySide6.QtGui import QColor

    rgba = image.convertToFormat(image.Format.Format_RGBA8888)
    pixels = np.frombuffer(rgba.constBits(), np.uint8).reshape(rgba.height(), rgba.bytesPerLine())
    pixels = pixels[:, : rgba.width() * 4].reshape(rgba.height(), rgba.width(), 4)
    done = QColor(DONE_COLOUR)
    return int(np.count_nonzero((pixels[..., 0] == done.red()) & (pixels[..., 1] == done.green())
                                & (pixels[..., 2] == done.blue())))


def test_done_part_and_highlight(preview):
    program = load(SAMPLE_FILES[0])
    preview.show_program(program.toolpath)
    assert preview.done_layer.segments == 0 and _green_pixels(preview.grab().toImage()) == 0
    preview.set_done(len(program.device_lines) - 1)
    assert preview.done_layer.segments > 0
    assert _green_pixels(preview.grab().toImage()) > 500  # painted on screen, not only counted
    preview.highlight_move(5)
    assert len(preview.highlight_item.getData()[0]) >= 2


def test_the_finished_part_follows_a_pan_and_a_new_run(preview):
    program = load(next(p for p in SAMPLE_FILES if "star_passes" in p.name))
    preview.show_program(program.toolpath)
    preview.set_done(len(program.line_map) // 2)
    before = _green_pixels(preview.done_layer.image)
    preview.zoom(2)
    preview._refill_now()  # as the coalesced refill after a range change does
    x, _ = preview.model.done_frame(*preview._view_and_pixel(), preview._done_move)
    assert preview.done_layer.segments == len(x) // 2
    assert _green_pixels(preview.done_layer.image) > before  # the same part, drawn twice as big
    preview.set_done(-1)  # a new run
    assert preview.done_layer.segments == 0 and _green_pixels(preview.done_layer.image) == 0


def test_zoom_and_fit(preview):
    program = load(SAMPLE_FILES[0])
    preview.show_program(program.toolpath)
    before = preview.view.viewRange()
    preview.zoom(4)
    after = preview.view.viewRange()
    assert after[0][1] - after[0][0] < (before[0][1] - before[0][0]) / 3
    preview.fit()
    assert preview.view.viewRange()[0] == pytest.approx(before[0])


def _zigzag(n):
    """A path that passes over the same few millimetres ``n`` times."""
    t = np.arange(n + 1, dtype=float)
    x = np.where(t % 2 == 0, 0.0, 100.0) + (t % 7) * 0.001
    y = (t % 50) * 0.5
    seg = np.column_stack([x[:-1], y[:-1], x[1:], y[1:]])
    return LodSegments(seg, np.arange(n))


def test_level_of_detail_bounds_what_is_drawn():
    lod = _zigzag(200_000)
    view = (-10, 110, -10, 40)
    x, _ = lod.visible(view, pixel=0.2, budget=20_000)
    assert 0 < len(x) // 2 <= 20_000
    x_full, _ = lod.visible(view, pixel=1e-6, budget=10**9)
    assert len(x_full) // 2 == 200_000
    upto = lod.visible(view, pixel=0.2, budget=20_000, upto=999)
    assert len(upto[0]) // 2 <= 1000


def test_level_of_detail_keeps_extremes():
    lod = _zigzag(50_000)
    for index in range(len(lod.cells)):
        level = lod.level(index)
        xs = level.seg[:, [0, 2]]
        assert xs.min() == pytest.approx(0.0) and xs.max() == pytest.approx(100.006, abs=1e-4)
        assert len(level.boxes) == -(-len(level.move) // CHUNK)


def test_finished_part_grows_by_painting_only_what_is_new(preview):
    program = load(next(p for p in SAMPLE_FILES if "star_passes" in p.name))
    preview.show_program(program.toolpath)
    model, layer = preview.model, preview.done_layer
    total, pixels = 0, 0
    for seq in range(0, len(program.line_map), 7):
        preview.set_done(seq)
        assert layer.segments >= total  # never shrinks while the job advances
        total = layer.segments
    grown = _green_pixels(layer.image)
    preview.set_done(len(program.line_map) - 1)
    x, _ = model.recent_segments(-1, len(program.toolpath.kind) - 1)
    assert layer.segments == len(x) // 2  # every cut segment painted exactly once
    assert _green_pixels(layer.image) >= grown > pixels


def test_a_level_built_from_a_finer_level_equals_one_built_from_the_segments():
    program = load(next(p for p in SAMPLE_FILES if "potrace" in p.name))
    model = PreviewModel(program.toolpath)
    for group in model.groups:
        if not len(group):
            continue
        fresh = LodSegments(*group._raw)
        for index in range(3, len(group.cells)):
            direct = fresh.level(index)  # nothing finer built: from the segments
            fresh._levels.pop(index)
            group.level(index - 1)
            chained = group.level(index)  # from the level before
            np.testing.assert_array_equal(chained.move, direct.move)
            np.testing.assert_array_equal(chained.seg, direct.seg)


def test_without_waiting_the_nearest_built_level_is_drawn():
    program = load(next(p for p in SAMPLE_FILES if "potrace" in p.name))
    model = PreviewModel(program.toolpath)
    group = max(model.groups, key=len)
    view = (-1e3, 1e3, -1e3, 1e3)
    group.level(5)
    x, _ = group.visible(view, pixel=group.cells[2], budget=10**9, wait=False)
    assert set(group._levels) == {5}  # nothing built
    assert len(x) // 2 == len(group.level(5).move)
    assert len(group.visible(view, pixel=group.cells[2], budget=10**9)[0]) // 2 == len(group.level(2).move)


def test_a_finer_model_keeps_the_view_and_the_finished_part(preview):
    program = load(next(p for p in SAMPLE_FILES if "arcs" in p.name))
    preview.show_model(PreviewModel(program.toolpath, tolerance=0.2))
    preview.zoom(3)
    preview.set_done(len(program.line_map) // 2)
    view, coarse = preview.view.viewRange(), preview.done_layer.segments
    preview.replace_model(PreviewModel(program.toolpath, tolerance=0.01))
    assert preview.view.viewRange() == view
    assert preview.done_layer.segments > coarse  # the same finished part, in finer chords


@pytest.mark.parametrize("path", SAMPLE_FILES, ids=lambda p: p.name)
def test_the_screen_tolerance_is_never_coarser_than_half_a_pixel(path):
    from app.ui.preview.model import FIT_MARGIN, screen_tolerance

    toolpath = load(path).toolpath
    (xmin, ymin, _), (xmax, ymax, _) = bounds_array(toolpath.bounds)  # exact, arcs' bulges too
    pad = 2 * max(xmax - xmin, ymax - ymin, 1.0) * FIT_MARGIN  # a view fitted to the exact bounds
    for size in ((900, 700), (300, 200), (200, 300), (4000, 3000)):
        pixel = max((xmax - xmin + pad) / size[0], (ymax - ymin + pad) / size[1])
        assert 0.01 <= screen_tolerance(toolpath, size, 0.01) <= max(pixel / 2, 0.01)
    circle = load_text("G0 X10 Y0\nG2 X10 Y0 I-10 J0 F300\n").toolpath  # its ends are one point
    assert screen_tolerance(circle, (900, 700), 0.01) == 0.01


def test_each_group_holds_its_segments_in_program_order():
    from app.ui.preview.lod import group_segments

    program = load(next(p for p in SAMPLE_FILES if "star_passes" in p.name))
    g = PreviewModel(program.toolpath).geometry
    parts = group_segments(g.points, g.move, g.group, g.group_count)
    assert len(parts) == g.group_count and sum(len(m) for _, m in parts) == len(g.points) - 1
    for which, (seg, move) in enumerate(parts):
        ends = [i for i in range(1, len(g.points)) if g.group[i] == which]
        expected = [[*g.points[i - 1, :2], *g.points[i, :2]] for i in ends]
        np.testing.assert_allclose(seg, np.reshape(expected, (-1, 4)), rtol=1e-6)
        np.testing.assert_array_equal(move, g.move[ends])


def test_a_program_is_on_the_screen_when_show_model_returns(preview):
    program = load(next(p for p in SAMPLE_FILES if "star_passes" in p.name))
    painted = []
    preview.path_layer.painted.connect(lambda: painted.append(preview.path_layer.segments))
    preview.show_program(program.toolpath)
    assert painted and painted[-1] == sum(len(x) // 2 for x, _ in preview.group_data) > 0


def test_one_spot_drilled_over_and_over_is_one_segment_on_either_sort(monkeypatch):
    from app.ui.preview import lod

    same = np.tile([[0.0, 0.0, 1.0, 1.0]], (100_001, 1))
    same[-1] = [5.0, 5.0, 6.0, 6.0]
    for bits in (64, 0):  # the packed value sort; the argsort
        monkeypatch.setattr(lod, "PACKED_BITS", bits)
        level = LodSegments(same, np.arange(len(same))).level(3)
        np.testing.assert_array_equal(level.move, [0, len(same) - 1])


@pytest.mark.parametrize("bits", [64, 0], ids=["packed value sort", "argsort"])
def test_a_level_keeps_the_first_segment_of_every_pair_of_cells(bits, monkeypatch):
    """np.unique's first occurrences of the (start cell, end cell) keys, and the extremes:
    on a walk that crosses itself, in steps so small that most segments repeat the pair of
    the one before, and comes back to cells it left long ago; the keys (and their
    indices) packed for one value sort where they fit, else sorted by an argsort."""
    from app.ui.preview import lod

    monkeypatch.setattr(lod, "PACKED_BITS", bits)
    rng = np.random.default_rng(7)
    steps = rng.normal(0, 0.002, size=(220_001, 2))
    steps[::997] += rng.normal(0, 5, size=(len(steps[::997]), 2))  # jumps back over the path
    walk = np.cumsum(steps, axis=0)
    seg = np.column_stack([walk[:-1], walk[1:]]).astype(np.float32)
    segments, packed = LodSegments(seg, np.arange(len(seg))), []
    for index in (1, 3, 5, 7):
        key, bound = lod._pair_keys(seg, segments.cells[index])
        assert key.min() >= 0 and key.max() < bound
        packed.append(bound << (len(seg) - 1).bit_length() <= 1 << bits)
        expected = np.zeros(len(seg), bool)
        expected[np.unique(key, return_index=True)[1]] = True
        for column in range(4):
            expected[np.argmin(seg[:, column])] = expected[np.argmax(seg[:, column])] = True
        level = segments.level(index)
        assert np.count_nonzero(key[1:] == key[:-1]) > len(seg) // 2  # runs of the same pair
        np.testing.assert_array_equal(level.move, np.flatnonzero(expected))
    assert packed == ([False, True, True, True] if bits else [False] * 4)  # the finest: too many keys
