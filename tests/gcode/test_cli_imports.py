"""What a one-shot ``cnc-gcode check`` of a plain program imports: each module left out
below was measured as start-up or load time for nothing (their docstrings give the
figures), and an innocent import at the top of a module brings it back unseen."""

import subprocess
import sys
from pathlib import Path

SAMPLE = Path(__file__).resolve().parents[2] / "resources" / "samples" / "potrace_logo.ngc"
NOT_FOR_A_PLAIN_CHECK = (
    "json",  # only for ``cnc-gcode moves`` and the settings files
    "app.gcode.macro",  # the expander: only for a program that needs it
    "app.gcode.features",  # the feature generators
    "app.gcode.pointlist.convert",  # the point-list importer
    "numpy.ma",  # np.union1d / np.unique used to bring it (6 ms)
    "multiprocessing",  # the window's helper process; a one-shot load forks instead
    "concurrent.futures",
)

PROBE = """
import sys
from app.gcode import cli
status = cli.main(["check", sys.argv[1]])
print(status, *[name for name in sys.argv[2:] if name in sys.modules])
"""


def test_a_plain_check_imports_only_what_it_uses():
    done = subprocess.run([sys.executable, "-c", PROBE, str(SAMPLE), *NOT_FOR_A_PLAIN_CHECK],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    status, *imported = done.stdout.splitlines()[-1].split()
    assert status == "0" and imported == []
