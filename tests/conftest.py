"""Suite-wide setup: headless Qt."""

import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
