"""``python -m app.gcode check|normalize|moves FILE``."""

import sys

from .cli import main

if __name__ == "__main__":  # the helper process of workers.py imports this module too
    sys.exit(main())
