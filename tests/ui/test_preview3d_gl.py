"""The 3-D view drawing with OpenGL: what reaches the frame buffer.

These need a Qt platform whose windows can show an OpenGL widget (not ``offscreen``,
which ``make test`` uses). When this process has none and ``xvfb-run`` is installed,
``test_under_xvfb`` runs this file and the 3-D screenshot test again in a child
process on an Xvfb display with the xcb platform (Mesa's software renderer); without
Xvfb they skip with the reason.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from app.ui.preview.widget import DONE_COLOUR, group_colours
from tests.ui.test_preview3d_model import star_program

CHILD = "CNC_PREVIEW3D_CHILD"
ROOT = Path(__file__).resolve().parents[2]


def _gl_reason() -> str:
    from app.ui.preview3d.view import gl_problem

    return gl_problem()


def test_under_xvfb(qapp):
    reason = _gl_reason()
    if not reason:
        pytest.skip("this process can draw OpenGL: the tests below ran in it")
    if os.environ.get(CHILD):
        pytest.fail(f"the child under Xvfb has no OpenGL either: {reason}")
    if shutil.which("xvfb-run") is None:
        pytest.skip(f"no OpenGL here ({reason}) and no xvfb-run to start a display")
    env = dict(os.environ, QT_QPA_PLATFORM="xcb", **{CHILD: "1"})
    files = [__file__, *(
        str(ROOT / "tests" / "ui" / f"test_preview3d_{name}.py")
        for name in ("full", "screens"))]
    run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1600x1000x24", sys.executable, "-m", "pytest",
                          "-q", "-p", "no:cacheprovider", "-k", "not test_under_xvfb", *files],
                         cwd=ROOT, env=env, capture_output=True, text=True, timeout=280)
    tail = (run.stdout + run.stderr)[-3000:]
    assert run.returncode == 0, tail
    assert "skipped" not in run.stdout and " passed" in run.stdout, tail


def gl_widget(qtbot, make, ready):
    """``make()`` shown at 900 x 700 until ``ready(widget)`` (OpenGL started); skips where
    this process cannot show an OpenGL widget."""
    reason = _gl_reason()
    if reason:
        pytest.skip(f"no OpenGL widget here: {reason} (test_under_xvfb runs these on Xvfb)")
    widget = make()
    qtbot.addWidget(widget)
    widget.resize(900, 700)
    widget.show()
    qtbot.waitExposed(widget)
    qtbot.waitUntil(lambda: ready(widget))
    return widget


@pytest.fixture
def gl_view(qtbot):
    from app.ui.preview3d.view import Preview3D

    return gl_widget(qtbot, Preview3D, lambda view: view.gl is not None and bool(view.gl.renderer))


def _show_star(qtbot, view):
    from app.gcode import load_text
    from app.ui.preview.model import PreviewModel

    program = load_text(star_program())
    view.show_model(PreviewModel(program.toolpath, threads=1), program)
    qtbot.waitUntil(lambda: view.mesh is not None and view.gl.drawn[0] == "full")
    return program


def _frame(view) -> np.ndarray:
    """The GL widget's picture as (h, w, 3) uint8."""
    from PySide6.QtGui import QImage

    image = view.gl.grabFramebuffer().convertToFormat(QImage.Format.Format_RGB888)
    data = np.frombuffer(image.constBits(), np.uint8, image.sizeInBytes())
    rows = data.reshape(image.height(), image.bytesPerLine())[:, : image.width() * 3]
    return rows.reshape(image.height(), image.width(), 3).copy()  # the image's memory goes with it


def _count(frame: np.ndarray, hex_colour: str, tolerance: int = 12) -> int:
    rgb = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)])
    return int(np.all(np.abs(frame.astype(int) - rgb) <= tolerance, axis=2).sum())


def test_the_star_is_drawn_in_its_depth_colours_and_progress_turns_it_green(qtbot, gl_view):
    program = _show_star(qtbot, gl_view)
    gl_view.preset("isometric")
    frame = _frame(gl_view)
    colours = group_colours()
    bands = {int(g) for g in gl_view.mesh.group if g >= 2}
    assert len(bands) >= 3
    seen = {band: _count(frame, colours[band]) for band in bands}
    assert min(seen.values()) > 30, seen  # every pass is seen from the side
    assert _count(frame, DONE_COLOUR) == 0
    uploads = []
    gl_view.gl._upload_mesh = lambda: uploads.append(True)  # progress must not re-upload
    gl_view.set_done(len(program.device_lines) - 1)
    frame = _frame(gl_view)
    assert _count(frame, DONE_COLOUR) > 200 and not uploads
    assert all(_count(frame, colours[band]) == 0 for band in bands)


def test_moving_draws_a_level_of_detail_then_full_detail_again(qtbot, gl_view, monkeypatch):
    from app.gcode import load_text
    from app.ui.preview.model import PreviewModel
    from app.ui.preview3d import glview

    circles = [f"G1 Z{-0.1 * k:.1f} F100\nG2 X90 Y50 I-40 J0 F300" for k in range(1, 31)]
    program = load_text("G0 X90 Y50\n" + "\n".join(circles) + "\nM2\n")
    model = PreviewModel(program.toolpath, tolerance=0.0002, threads=1)  # about 1,000 chords a circle
    n = len(model.geometry.points)
    assert n > 25_000
    monkeypatch.setattr(glview, "MOVING_BUDGET", 5_000)
    gl_view.show_model(model, program)
    qtbot.waitUntil(lambda: gl_view.mesh is not None and gl_view.gl.levels_on_gpu > 0)
    qtbot.waitUntil(lambda: gl_view.gl.drawn == ("full", n - 1))
    seen = []
    gl_view.gl.frame_drawn.connect(lambda: seen.append(gl_view.gl.drawn))
    gl_view.gl.camera.orbit(15, 5)
    gl_view.gl.camera_moved()
    qtbot.waitUntil(lambda: bool(seen) and seen[-1] == ("full", n - 1), timeout=3000)  # once it settles
    assert seen[0][0] == "level" and 0 < seen[0][1] <= 5_000  # while it moved


def test_full_detail_in_slices_is_the_same_picture_and_progress_draws_only_what_is_new(qtbot, gl_view):
    program = _show_star(qtbot, gl_view)
    gl_view.preset("isometric")
    gl = gl_view.gl
    whole = _frame(gl_view)
    gl.direct_segments = 0  # in slices however small
    gl.full_cell_pixels = 0  # of every segment (test_preview3d_full: a level's full detail)
    gl._full.slice_segments = 7  # the first slice: 7 of the star's segments, then sized to the renderer
    slices = []
    cut = gl._full.slice
    gl._full.slice = lambda strip: slices.append(cut(strip)) or slices[-1]
    seen = []
    gl.frame_drawn.connect(lambda: seen.append(gl.drawn))
    gl.update()
    qtbot.waitUntil(lambda: bool(seen) and seen[-1][0] == "full")
    assert seen[0] == ("partial", 0) and slices[:2] == [7, 29]  # drawn between frames
    differ = np.any(_frame(gl_view) != whole, axis=2)
    assert differ.sum() < 0.0005 * differ.size  # only where the box crosses the path (a copy has no depth)
    strips = []
    draw = gl._full.overdraw
    gl._full.overdraw = lambda strip, done: draw(lambda a, b: (strips.append((a, b)), strip(a, b)), done)
    gl_view.set_done(8)
    qtbot.waitUntil(lambda: bool(strips))
    vertex = gl.done_vertex
    assert strips == [(0, vertex)]  # only the newly finished part, over the picture
    assert _count(_frame(gl_view), DONE_COLOUR) > 20
    gl_view.set_done(len(program.device_lines) - 1)
    qtbot.waitUntil(lambda: len(strips) == 2)
    assert strips[1] == (vertex, gl.done_vertex)


def test_the_measured_path_is_drawn_over_in_its_deviation_colours(qtbot, gl_view):
    from app.ui.preview3d.measured import RAMP

    _show_star(qtbot, gl_view)
    gl_view.preset("top")
    gl_view.set_done(5)
    y = np.linspace(60, 100, 50)
    measured = np.column_stack([np.full(50, 75.0), y, np.full(50, -1.0)])
    gl_view.add_measured(measured, measured + [0.5, 0, 0])  # far off: red
    qtbot.waitUntil(lambda: gl_view.gl._measured_sent[1] == 50)
    red = "#{:02x}{:02x}{:02x}".format(*(int(round(255 * c)) for c in RAMP[2]))
    assert _count(_frame(gl_view), red, tolerance=20) > 40
    gl_view.jump_to_largest()
    assert gl_view.gl.camera.half_height < 10
    np.testing.assert_allclose(gl_view.gl.camera.target, measured[0], atol=1e-4)


@pytest.mark.qt_log_ignore("QOpenGLShader::compile", "Problematic .* shader", "QOpenGLShader::link")
def test_a_shader_that_does_not_compile_leaves_the_message(qtbot, monkeypatch):
    if _gl_reason():
        pytest.skip("no OpenGL widget here (test_under_xvfb runs this on Xvfb)")
    from app.ui.preview3d import shaders
    from app.ui.preview3d.view import Preview3D

    monkeypatch.setattr(shaders, "PATH_VERTEX", "#version 330 core\nthis is not GLSL")
    view = Preview3D()
    qtbot.addWidget(view)
    with qtbot.waitSignal(view.gl_failed, timeout=5000) as failed:
        view.show()
    assert failed.args[0] and view.gl is None
    assert view.stack.currentWidget() is view.message and "cannot start" in view.message.text()


def test_coming_back_to_a_pose_shows_its_picture_at_once(qtbot, gl_view):
    program = _show_star(qtbot, gl_view)
    gl = gl_view.gl
    gl.direct_segments = 0  # in slices, as a big program is
    gl.full_cell_pixels = 0
    seen, slices = [], []
    gl.frame_drawn.connect(lambda: seen.append(gl.drawn))
    cut = gl._full.slice
    gl._full.slice = lambda draw: slices.append(cut(draw)) or slices[-1]
    for name in ("top", "isometric"):
        gl_view.preset(name)
        qtbot.waitUntil(lambda: bool(seen) and seen[-1][0] == "full")
    undone = _frame(gl_view)
    gl_view.set_done(len(program.device_lines) // 2)  # progress while away: drawn over on return
    qtbot.waitUntil(lambda: bool(seen) and seen[-1][0] == "full")
    seen.clear()
    slices.clear()
    gl_view.preset("top")
    qtbot.waitUntil(lambda: bool(seen))
    assert seen[0][0] == "full" and not slices  # no slice drawn again
    assert _count(_frame(gl_view), DONE_COLOUR) > 20 and _count(undone, DONE_COLOUR) == 0
