"""No operator-visible English typed straight into a widget: every text given to a Qt
label, button, title, tab, tooltip, placeholder, status message or message box in
``app/ui`` goes through ``self.tr()`` / ``QCoreApplication.translate()`` (so it reaches the
``.ts`` files, and the catalogue test then asks for its translation)."""

from __future__ import annotations

import ast
import re
from pathlib import Path

UI = Path(__file__).resolve().parents[2] / "app" / "ui"
TAKES_TEXT = {
    "setText", "setTitle", "setToolTip", "setStatusTip", "setWindowTitle", "setPlaceholderText",
    "setTabText", "addTab", "insertTab", "showMessage", "setHeaderLabels", "addItem", "setSuffix",
    "setPrefix", "setFormat", "setLabel", "addMenu", "addAction", "setItemText", "QLabel", "QPushButton",
    "QCheckBox", "QRadioButton", "QGroupBox", "QAction", "QDockWidget", "QTreeWidgetItem", "warning",
    "error", "info", "notify", "about", "information", "critical", "question", "getOpenFileName",
    "getSaveFileName", "setWhatsThis", "addRow", "_action", "_menu",
}
WORDS = re.compile(r"[A-Za-z]{3,}")
MARKUP = re.compile(r"<[^>]*>")
NOT_PROSE = re.compile(r"^(?:[\w.-]+\.\w+|(?:Ctrl|Alt|Shift)\+.*)$")  # a file name, a key
PASSES_TEXT_ON = {"notifier.py"}  # forwards texts it is given (its first argument is a level)
# Texts that are the same in every language: protocol words, axis names, units, names.
SAME_EVERYWHERE = {"TX", "RX", "XY", "XYZ", "LED", "mm", "X", "Y", "Z", "left", "bottom", "%p %", "Esc"}


def _literal_text(node) -> str:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.JoinedStr):
        return " ".join(v.value for v in node.values if isinstance(v, ast.Constant))
    if isinstance(node, ast.List | ast.Tuple):
        return " ".join(_literal_text(e) for e in node.elts)
    return ""


def _name(func) -> str:
    return func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")


def raw_texts(path: Path) -> list[str]:
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Call) and _name(node.func) in TAKES_TEXT:
            for arg in node.args:
                text = MARKUP.sub(" ", _literal_text(arg)).strip()
                if text and text not in SAME_EVERYWHERE and not NOT_PROSE.match(text) and WORDS.search(text):
                    found.append(f"{path.relative_to(UI.parent.parent)}:{node.lineno}: {text!r}")
    return found


def test_no_widget_text_bypasses_translation():
    paths = [p for p in sorted(UI.rglob("*.py")) if p.name not in PASSES_TEXT_ON]
    found = [hit for path in paths for hit in raw_texts(path)]
    assert found == [], "wrap these in self.tr() / QCoreApplication.translate():\n" + "\n".join(found)
