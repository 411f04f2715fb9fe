"""``python -m app.gcode check|normalize|moves FILE``."""

import sys

from .cli import main

sys.exit(main())
