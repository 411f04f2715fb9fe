"""``python -m app.gcode check|normalize|moves FILE``."""

from .cli import run

if __name__ == "__main__":  # the helper process of workers.py imports this module too
    run()
