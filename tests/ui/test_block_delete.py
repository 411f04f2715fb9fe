"""The block delete switch in the window (issue 19): off by default, so lines starting
with "/" run; turned on, the open program is loaded again without them."""

from tests.ui.conftest import open_and_wait


def test_the_block_delete_switch_reloads_the_program_without_slash_lines(qtbot, window, tmp_path):
    path = tmp_path / "slash.ngc"
    path.write_text("G21 G90 F100\nG1 X1\n/G1 X2\nG1 X3\nM2\n")
    loaded = open_and_wait(qtbot, window, path)
    switch = window.actions_by_name["block_delete"]
    assert not switch.isChecked()
    assert [m["end"][0] for m in loaded.program.moves] == [1.0, 2.0, 3.0]
    with qtbot.waitSignal(window.loader.loaded, timeout=20_000) as blocker:
        switch.trigger()
    assert switch.isChecked()
    assert [m["end"][0] for m in blocker.args[0].program.moves] == [1.0, 3.0]
