"""The operator's window (PySide6 + pyqtgraph); the only package that imports Qt widgets."""

from app.ui import _pyside_guard

_pyside_guard.apply()
