"""The 3-D view around its GL widget, where OpenGL cannot start: the fallback to the
2-D view with the reason, and what works without a GPU (legend, deviation text)."""

from __future__ import annotations

import numpy as np

from app.gcode.ops import RAPID
from app.ui.preview.model import PreviewModel
from app.ui.preview3d.view import Preview3D
from tests.ui.test_preview3d_model import star_program


def _seq_before(program, model, rapid: bool) -> int:
    """The first device line after which the move executed next is (not) a rapid."""
    kind = program.toolpath.kind
    return next(s for s in range(len(program.device_lines) - 1)
                if (int(kind[model.move_of_device_line(s + 1)]) == RAPID) == rapid)


def test_without_opengl_the_view_says_why_and_makes_no_gl_object(qtbot):
    asked = []

    def probe():
        asked.append(True)
        return "no OpenGL context could be created on this display"

    view = Preview3D(probe=probe)
    qtbot.addWidget(view)
    failures = []
    view.gl_failed.connect(failures.append)
    view.show()
    qtbot.waitExposed(view)
    assert asked and view.gl is None
    assert failures == ["no OpenGL context could be created on this display"]
    assert "no OpenGL context" in view.message.text() and "2-D view" in view.message.text()
    assert view.stack.currentWidget() is view.message
    assert not any(button.isEnabled() for button in view.buttons.values())
    view.hide()
    view.show()  # asked once: the answer does not change
    assert len(asked) == 1


def test_the_window_falls_back_to_the_2d_view(make_window, qtbot):
    window = make_window()
    window.preview3d.probe = lambda: "OpenGL 2.1 found, 3.3 needed"
    assert window.views.currentWidget() is window.preview
    window.views.setCurrentWidget(window.preview3d)
    qtbot.waitUntil(lambda: window.views.currentWidget() is window.preview)
    assert "3.3 needed" in window.preview3d.message.text()
    assert window.views.tabText(1) == "3-D view"


def test_without_gl_progress_and_the_largest_deviation_still_work(qtbot):
    from app.gcode import load_text

    view = Preview3D(probe=lambda: "none here")
    qtbot.addWidget(view)
    program = load_text(star_program())
    view.show_model(PreviewModel(program.toolpath, threads=1), program)
    view.set_done(10)  # no mesh, no GL: nothing to draw, nothing raised
    assert "Z -0" in view.legend.text() and "rapid" in view.legend.text()
    view.jump_to_largest()
    assert view.deviation_label.text() == "no cut measured yet"
    feed_seq, rapid_seq = _seq_before(program, view.model, False), _seq_before(program, view.model, True)
    measured = np.array([[1.0, 2.0, -1.0], [1.0, 2.2, -1.0]])
    view.set_done(rapid_seq)
    view.add_measured(measured + [0, 5, 0], measured - [0, 5, 0])  # 10 mm off in a rapid
    view.jump_to_largest()
    assert view.deviation_label.text() == "no cut measured yet"
    view.set_done(feed_seq)
    view.add_measured(measured, np.array([[1.0, 2.0, -1.0], [1.0, 2.0, -1.0]]))
    view.jump_to_largest()
    assert view.deviation_label.text() == "largest deviation 0.200 mm at X 1.000 Y 2.200 Z -1.000"
    assert np.allclose(view.mark_at, (1.0, 2.2, -1.0))
