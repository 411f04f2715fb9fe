"""The operator's window (PySide6 + pyqtgraph)."""
