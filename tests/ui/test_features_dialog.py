"""The feature dialog and the point-list import step, driven as an operator would."""

from __future__ import annotations

import pytest

from app.profile import MachineProfile

PAPER = "G00 X40 Y40\nG01 X35 Y55\nG02 X45 Y65 R10\nG03 X70 Y65 R30\nG02 X80 Y55 R10\nG01 Y50\n" \
        "G01 X75 Y40\nG01 X60 Y37\nG01 X40 Y40\n"


@pytest.fixture
def opened():
    return []


@pytest.fixture
def dialog(qtbot, tmp_path, opened):
    from app.ui.features.dialog import FeatureDialog

    dlg = FeatureDialog(MachineProfile(), opened.append, tmp_path / "generated")
    qtbot.addWidget(dlg)
    dlg.show()
    with qtbot.waitSignal(dlg.preview_updated):
        pass
    return dlg


def _spin(form, name):
    return form.editors[name][0]


def test_changing_a_parameter_updates_the_preview(qtbot, dialog):
    before = dialog.preview.model.bounds()
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        _spin(dialog.current_form(), "width").setValue(60)
    after = dialog.preview.model.bounds()
    assert after[1] - after[0] == pytest.approx(before[1] - before[0] + 20, abs=0.01)
    assert "Estimated time" in dialog.estimate.text()
    assert dialog.open_button.isEnabled()


def test_a_bad_value_shows_its_message_beside_its_field(qtbot, dialog):
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        _spin(dialog.cutting, "tool_diameter").setValue(30)
    message = dialog.cutting.errors["tool_diameter"].text()
    assert "must be narrower than the pocket (25 mm)" in message
    assert dialog.current_form().errors["width"].text() == ""
    assert not dialog.open_button.isEnabled()
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        _spin(dialog.cutting, "tool_diameter").setValue(6)
    assert dialog.cutting.errors["tool_diameter"].text() == ""


def test_outside_the_travel_is_named_with_axis_and_direction(qtbot, dialog):
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        _spin(dialog.current_form(), "x").setValue(140)
    assert "X+ beyond travel" in dialog.current_form().errors["x"].text()


def test_a_job_of_several_features_with_one_tool_change_opens_as_a_program(qtbot, dialog, opened):
    dialog.add_feature("holes-row")
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        _spin(dialog.cutting, "tool").setValue(2)
    dialog.add_feature("pocket-circle")
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        _spin(dialog.cutting, "tool").setValue(2)
    assert dialog.list.count() == 3
    dialog.move_feature(-1)  # the round pocket before the holes: still one change, 1 -> 2
    assert [e["kind"] for e in dialog.job] == ["pocket-rect", "pocket-circle", "holes-row"]
    dialog.open_as_program()
    assert len(opened) == 1
    text = opened[0].read_text()
    assert text.count("M06 T2") == 1
    assert dialog.program.errors == []


def test_profile_from_a_contour_file(qtbot, dialog, tmp_path):
    contour = tmp_path / "island.nc"
    contour.write_text(PAPER)
    dialog.add_feature("profile")
    form = dialog.current_form()
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        form.set_values({"contour": str(contour)})
        form.changed.emit()
    assert dialog.problem.text() == ""
    assert dialog.program.errors == []


def test_file_open_of_a_point_list_shows_the_options_step(qtbot, window, tmp_path):
    points = tmp_path / "drawing.txt"
    points.write_text("0 0 1\n10 0 1\n10 5 1\n\n20 20 1\n30 25 1\n")
    window.open_file(points)
    dialog = window.import_dialog
    qtbot.waitUntil(lambda: dialog.convert_button.isEnabled(), timeout=10000)
    assert "scale" in dialog.summary.text() and "offset X" in dialog.summary.text()
    with qtbot.waitSignal(dialog.preview_updated, timeout=5000):
        dialog.fit.setChecked(False)
    assert "scale 1," in dialog.summary.text()
    with qtbot.waitSignal(window.loader.loaded, timeout=20000) as blocker:
        dialog.convert()
    loaded = blocker.args[0]
    assert loaded.path.name == "drawing.nc" and loaded.program.errors == []
    assert len(loaded.program.toolpath) == 11  # up, and per path: over, down, 2 or 1 feeds, up twice


def test_a_malformed_point_list_says_where_and_cannot_be_converted(qtbot, window, tmp_path):
    bad = tmp_path / "task.txt"
    bad.write_text("===== Fabrication Task =====\n== Scan Path Information ==\nNumber of Total Paths : 1\n"
                   "Path Number : 0\nNumber of Total Points : 3\n1 2 3\n4 5 6\n")
    window.open_file(bad)
    dialog = window.import_dialog
    qtbot.waitUntil(lambda: dialog.problem.text() != "", timeout=10000)
    assert "line 7: path 0 announced 3 points, found 2" in dialog.problem.text()
    assert not dialog.convert_button.isEnabled()


def test_screenshot_of_the_papers_island(qtbot, dialog, tmp_path):
    from PySide6.QtGui import QImage

    from tests.ui.feature_screens import island_shot

    path = island_shot(dialog, tmp_path)
    assert dialog.problem.text() == "" and dialog.program.errors == []
    image = QImage(str(path))
    assert image.width() >= 1000 and image.height() >= 600
    colours = {image.pixel(x, y) for x in range(0, image.width(), 37) for y in range(0, image.height(), 37)}
    assert len(colours) > 20


@pytest.mark.parametrize("dialect", ["plain", "fanuc21", "fanuc31"])
def test_save_as_in_each_dialect(dialog, tmp_path, dialect):
    dialog.refresh()
    dialog.dialect.setCurrentIndex(dialog.dialect.findData(dialect))
    target = tmp_path / f"{dialect}.nc"
    dialog.save_to(target)
    text = target.read_text()
    assert ("O1001" in text) == (dialect != "plain")
    assert ("WHILE" in text) == (dialect == "fanuc31")


def test_file_new_from_features_opens_its_job_in_the_window(qtbot, window):
    window.actions_by_name["features"].trigger()
    dialog = window.feature_dialog
    qtbot.waitUntil(lambda: dialog.program is not None, timeout=5000)
    with qtbot.waitSignal(window.loader.loaded, timeout=20000) as blocker:
        dialog.open_as_program()
    loaded = blocker.args[0]
    assert loaded.path.name == "features.nc" and loaded.program.errors == []
    assert loaded.program.toolpath.bounds[0][2] == pytest.approx(-3.0)
