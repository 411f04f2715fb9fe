"""A load that leaves its checks for later (the window's big programs): none of their
warnings before ``finish_checks``, then exactly what a whole load gives."""

from app.gcode import load
from app.gcode import program as program_module

SOURCE = ("G21 G90\nG0 X10 Y10\nG1 X200 F100\nG1 Y-20\nG1 X10\nM3 S90000\nG0 X145 Y70\n"
          "G3 X145 Y90 I0 J10\nM2\n")  # past X+ and Y-, a spindle speed past the top, an arc's bulge


def _said(program) -> list[str]:
    return [f"{d.severity} {d}" for d in program.diagnostics]


def test_the_later_checks_give_what_a_whole_load_gives(tmp_path, monkeypatch):
    path = tmp_path / "far.ngc"
    path.write_text(SOURCE)
    whole = load(path)
    monkeypatch.setattr(program_module, "LATER_CHECKS_ROWS", 1)
    later = load(path, later_checks=True)
    assert later.checks_pending and later.envelope is None
    left = {"X+ beyond travel", "Y- beyond travel", "spindle's maximum", "line 8"}
    assert all(any(part in text for text in _said(whole)) for part in left)
    assert not any(part in text for part in left for text in _said(later))
    later.finish_checks()
    assert not later.checks_pending
    assert _said(later) == _said(whole)
    assert later.envelope.found == whole.envelope.found
    later.finish_checks()  # nothing is left: nothing changes
    assert _said(later) == _said(whole)


def test_a_program_shorter_than_the_threshold_is_checked_at_once(tmp_path):
    path = tmp_path / "far.ngc"
    path.write_text(SOURCE)
    program = load(path, later_checks=True)
    assert not program.checks_pending
    assert _said(program) == _said(load(path))
