"""`make run`: until the window lands, check a sample with the G-code core."""

import sys
from pathlib import Path

SAMPLES = Path(__file__).resolve().parent.parent / "resources" / "samples"


def main() -> int:
    samples = sorted(SAMPLES.glob("*.ngc"))
    print("The operator's window is coming (issue 5); checking a sample meanwhile.")
    if not samples:
        print("no samples yet in resources/samples")
        return 0
    from app.gcode.cli import main as gcode_main

    return gcode_main(["check", str(samples[0])])


if __name__ == "__main__":
    sys.exit(main())
