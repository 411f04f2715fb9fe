"""``cnc-gui --demo``: a whole job on the simulator, a screenshot, one line, exit 0.
Run as its own process, as an operator would (it quits its QApplication at the end)."""

import os
import subprocess
import sys

import pytest

from tests.ui.conftest import SAMPLES


@pytest.mark.slow
def test_demo_runs_a_sample_to_the_end(tmp_path):
    shot = tmp_path / "demo.png"
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_CONFIG_HOME=str(tmp_path / "config"),
               XDG_DATA_HOME=str(tmp_path / "data"))
    args = [sys.executable, "-m", "app.ui.main", "--demo", str(SAMPLES / "arcs_circles.ngc"),
            "--speed", "40", "--screenshot", str(shot)]
    done = subprocess.run(args, capture_output=True, text=True, timeout=240, env=env)
    lines = done.stdout.strip().splitlines()
    assert done.returncode == 0, done.stdout + done.stderr
    assert lines[-1].startswith("demo arcs_circles.ngc on sim at 40x: completed 146 lines")
    assert shot.stat().st_size > 20_000
