"""Suite-wide setup: headless Qt, and a private home for everything the code keeps per user.

The simulator's SD card and flash (work offsets), the tool table and the window's
settings live in the user's data and config folders (platformdirs, QStandardPaths).
A test must neither read what the developer left there (a `SET WCS 55` in the window
moves every later simulated job) nor write into it, and two test processes must not
share it: each process gets fresh folders of its own before anything is imported.
"""

import atexit
import os
import shutil
import sys
import tempfile

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")


def _private_user_folders() -> None:
    root = tempfile.mkdtemp(prefix="cnc-tests-")
    atexit.register(shutil.rmtree, root, ignore_errors=True)
    for name in ("XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"):
        os.environ[name] = os.path.join(root, name.lower())
    if sys.platform == "win32":
        os.environ["APPDATA"] = os.environ["LOCALAPPDATA"] = os.path.join(root, "appdata")
    elif sys.platform == "darwin":  # platformdirs and Qt read ~/Library there
        os.environ["HOME"] = root


_private_user_folders()


def _hypothesis_without_clocks() -> None:
    """No property test passes or fails on the computer's speed: Hypothesis's deadline and
    its too-slow health check time each example, and a busy CI machine trips them on
    tests whose examples are right. A test's own ``@settings`` still sets the rest."""
    from hypothesis import HealthCheck, settings

    settings.register_profile("suite", deadline=None, suppress_health_check=[HealthCheck.too_slow])
    settings.load_profile("suite")


_hypothesis_without_clocks()

