"""`make run`: the operator's window on the built-in simulator (real time), with a
sample made by Inkscape open. With no display (Linux without DISPLAY or
WAYLAND_DISPLAY, and QT_QPA_PLATFORM not set) it says so and runs the demo instead:
the same sample on the simulator at 50x, a screenshot, and a one-line summary."""

import os
import sys
import tempfile
from pathlib import Path

SAMPLES = Path(__file__).resolve().parent.parent / "resources" / "samples"
SAMPLE = SAMPLES / "potrace_logo.ngc"


def has_display() -> bool:
    if os.environ.get("QT_QPA_PLATFORM"):
        return True
    if not sys.platform.startswith("linux"):
        return True
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def main() -> int:
    sample = SAMPLE if SAMPLE.exists() else next(iter(sorted(SAMPLES.glob("*.ngc"))), None)
    from app.ui.main import main as gui_main

    if has_display():
        args = ["--connect", "sim://"]
        return gui_main(args + ([str(sample)] if sample else []))
    shot = Path(tempfile.gettempdir()) / "cnc-demo.png"
    print("No display found (DISPLAY / WAYLAND_DISPLAY unset): running the demo headless instead.")
    os.environ["QT_QPA_PLATFORM"] = "offscreen"
    if sample is None:
        print("no sample in resources/samples")
        return 1
    return gui_main(["--demo", str(sample), "--speed", "50", "--screenshot", str(shot)])


if __name__ == "__main__":
    sys.exit(main())
