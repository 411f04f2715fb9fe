"""The suite never reads or writes the developer's own folders (tests/conftest.py)."""

import os
from pathlib import Path


def test_per_user_files_live_in_the_suite_s_private_folders():
    from app.gcode.tools import default_path
    from backend_sim.simulator import default_sd_dir

    root = Path(os.environ["XDG_DATA_HOME"]).parent
    assert root.name.startswith("cnc-tests-")
    for path in (default_sd_dir(), default_path()):
        assert root in path.parents, path
