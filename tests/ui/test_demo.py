"""``cnc-gui --demo``: a whole job on the simulator, a screenshot, one line, exit 0."""

import pytest

from app.ui.main import main
from tests.ui.conftest import SAMPLES


@pytest.mark.slow
def test_demo_runs_a_sample_to_the_end(qtbot, tmp_path, capsys):
    shot = tmp_path / "demo.png"
    code = main(["--demo", str(SAMPLES / "arcs_circles.ngc"), "--speed", "40", "--screenshot", str(shot)])
    out = capsys.readouterr().out.strip().splitlines()
    assert code == 0, out
    assert out[-1].startswith("demo arcs_circles.ngc on sim at 40x: completed 146 lines")
    assert shot.stat().st_size > 20_000
