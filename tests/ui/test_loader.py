"""The loader's first picture: what it draws covers the program as the finer model does,
and what the window reads when the program arrives is ready (worked out off the GUI
thread)."""

import numpy as np
import pytest

from app.ui.loader import load_program
from app.ui.preview.model import PreviewModel
from app.ui.program.summary import describe, device_count
from tests.ui.conftest import SAMPLE_FILES

VIEW = (900, 700)


def _drawn(model: PreviewModel, pixel_of=None):
    """Every group's (x, y) point pairs in a view fitted to the program."""
    (x0, x1), (y0, y1) = model.fitted_range()
    pixel = max((x1 - x0) / VIEW[0], (y1 - y0) / VIEW[1])
    return model.frame((x0, x1, y0, y1), pixel), pixel


@pytest.mark.parametrize("path", SAMPLE_FILES, ids=lambda p: p.name)
def test_the_first_picture_covers_what_the_fine_model_draws(path):
    first = load_program(path, 0.01, VIEW)
    fine = PreviewModel(first.program.toolpath, 0.01)
    coarse, pixel = _drawn(first.preview)
    full, _ = _drawn(fine)
    assert first.preview.tolerance <= pixel / 2 + 1e-12  # chords within half a pixel
    for group, ((cx, cy), (fx, fy)) in enumerate(zip(coarse, full, strict=True)):
        assert bool(len(cx)) == bool(len(fx)), f"group {group} drawn in one picture only"
        if len(fx):  # the same extent, to the coarse chords' tolerance
            tol = first.preview.tolerance + 1e-4
            assert (cx.min(), cx.max(), cy.min(), cy.max()) == pytest.approx(
                (fx.min(), fx.max(), fy.min(), fy.max()), abs=tol)
    moves = [np.unique(m.geometry.move[1:]) for m in (first.preview, fine)]
    np.testing.assert_array_equal(*moves)  # every move has its segments in both


def test_the_summary_s_facts_are_ready_when_the_program_arrives():
    first = load_program(SAMPLE_FILES[0], 0.01, VIEW)
    cached = vars(first.program.toolpath)
    assert "bounds" in cached and "_length_by_kind" in cached  # not left to the GUI thread
    assert device_count(first.program) == first.program.device_count == len(first.program.line_map)
    first = load_program(SAMPLE_FILES[0], 0.01, VIEW)
    describe(first.program, "name")
    assert "line_map" not in vars(first.program)  # the summary counts the plan's device lines
