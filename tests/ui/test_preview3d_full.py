"""Full detail from a level of detail is honest: the picture it draws is the picture of
every segment, pixel for pixel but for sub-pixel shifts (run on Xvfb by
``test_preview3d_gl.test_under_xvfb`` when this process has no OpenGL widget)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from app.ui.preview3d.glview import FULL_CELL_PIXELS
from tests.ui.test_preview3d_gl import _frame, gl_widget
from tests.ui.test_preview3d_model import raster

SAME = 24  # colour channels this close are the same colour


def dense_geometry(turns: int = 30, per_turn: int = 3_000, repeats: int = 3) -> SimpleNamespace:
    """A spiral in three depth passes, each cut ``repeats`` times (spring passes), its
    chords far shorter than a pixel, with rapids between the passes."""
    t = np.linspace(0, 2 * np.pi * turns, turns * per_turn)
    radius = 5 + 40 * t / t[-1]
    flat = np.column_stack([60 + radius * np.cos(t), 60 + radius * np.sin(t)])
    chains, groups = [], []
    for depth in (1.0, 2.0, 3.0):
        for _ in range(repeats):
            chains.append(np.array([[flat[0, 0], flat[0, 1], 5.0]]))  # a rapid to the start
            groups.append(np.array([0]))
            chains.append(np.column_stack([flat, np.full(len(flat), -depth)]))
            groups.append(np.full(len(flat), 1 + int(depth)))
    points = np.concatenate(chains)
    return SimpleNamespace(points=points, group=np.concatenate(groups).astype(np.int8),
                           move=np.arange(len(points)))


def _lit(frame: np.ndarray) -> np.ndarray:
    return frame.max(axis=2) > SAME


def _unexplained(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Pixels of ``a`` whose colour ``b`` has neither there nor one pixel away."""
    h, w, _ = a.shape
    padded = np.pad(b.astype(int), ((1, 1), (1, 1), (0, 0)), constant_values=-999)
    found = np.zeros((h, w), bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            near = padded[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
            found |= np.all(np.abs(near - a.astype(int)) <= SAME, axis=2)
    return ~found


def compare(full: np.ndarray, fast: np.ndarray) -> dict:
    differ = np.any(np.abs(full.astype(int) - fast.astype(int)) > SAME, axis=2)
    lit = max(int(_lit(full).sum()), 1)
    return {"lit": lit, "differ": int(differ.sum()) / lit,
            "unexplained": int((_unexplained(full, fast) | _unexplained(fast, full)).sum()) / lit}


@pytest.fixture
def gl(qtbot):
    from app.ui.preview3d.glview import PathGLView

    return gl_widget(qtbot, PathGLView, lambda view: bool(view.renderer))


def _grab(qtbot, gl, full_cell_pixels: float) -> np.ndarray:
    gl.full_cell_pixels = full_cell_pixels
    gl._full.forget()
    gl.drawn = ("none", 0)
    gl.update()
    qtbot.waitUntil(lambda: gl.drawn[0] == "full")
    return SimpleNamespace(frame=_frame(SimpleNamespace(gl=gl)), lines=gl.full_lines)


@pytest.mark.parametrize("preset", ["isometric", "top", "front"])
def test_full_detail_from_a_level_is_the_picture_of_every_segment(qtbot, gl, preset):
    from app.ui.preview3d.mesh import PathMesh

    mesh = PathMesh.from_geometry(dense_geometry())
    mesh.build_levels()
    gl.camera.preset(preset)
    gl.set_mesh(mesh)
    gl.levels_ready()
    for done in (-1, mesh.segments // 2 + 123):  # before a job, and half-way through one
        gl.set_done_vertex(done)
        every = _grab(qtbot, gl, 0.0)
        fast = _grab(qtbot, gl, FULL_CELL_PIXELS)
        assert every.lines == mesh.segments and fast.lines < every.lines / 3
        seen = compare(every.frame, fast.frame)
        assert seen["lit"] > 3000, seen
        assert seen["differ"] <= 5e-4 and seen["unexplained"] <= 5e-5, seen  # a few pixels one off


def test_zoomed_in_only_the_chunks_on_screen_are_drawn_and_the_picture_is_the_same(qtbot, gl, monkeypatch):
    from app.ui.preview3d import glview
    from app.ui.preview3d.mesh import PathMesh

    mesh = PathMesh.from_geometry(raster(rows=400))
    mesh.build_levels()  # (the chunks' boxes come with them, off the GUI thread)
    gl.camera.preset("top")
    gl.set_mesh(mesh)
    gl.levels_ready()
    x, y, _ = gl.camera.project(mesh.points[len(mesh.points) * 3 // 4][None])[0]
    gl.camera.zoom_at(6.0, x, y)  # on a part of the path
    culled = _grab(qtbot, gl, 0.0)
    assert 0 < culled.lines < mesh.segments / 4
    monkeypatch.setattr(glview, "visible_runs", lambda boxes, project, total: [(0, total)])
    every = _grab(qtbot, gl, 0.0)
    assert every.lines == mesh.segments
    assert compare(every.frame, culled.frame)["differ"] == 0 and _lit(every.frame).sum() > 1000
