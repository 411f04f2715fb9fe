"""The operator's window (PySide6 + pyqtgraph); the only package that imports Qt widgets."""
