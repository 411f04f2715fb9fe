"""Every text an operator can see in the window and its dialogs, with where it is:
labels, buttons, group and tab titles, dock and window titles, menus and actions (text
and status tip), tooltips, placeholders, combo items, list headers and rows, progress
text, plot axis labels and legends, message boxes, the status bar message. The console
log and the source listing are left out: they show protocol frames and G-code."""

from __future__ import annotations

import html
import re

import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QAbstractButton,
    QComboBox,
    QDockWidget,
    QGroupBox,
    QLabel,
    QLineEdit,
    QMainWindow,
    QMenu,
    QProgressBar,
    QStatusBar,
    QTabBar,
    QTableWidget,
    QTreeView,
    QTreeWidget,
    QWidget,
)

TAGS = re.compile(r"<[^>]+>")


def plain(text: str) -> str:
    """Rich text and mnemonics ("&File", "Feeds && motion") as the operator reads them."""
    text = html.unescape(TAGS.sub(" ", text or ""))
    text = text.replace("&&", "\0").replace("&", "").replace("\0", "&")
    return " ".join(text.split())


def _name(widget) -> str:
    return f"{type(widget).__name__}({widget.objectName() or ''})"


def widget_texts(widget: QWidget) -> list[tuple[str, str]]:
    out = []
    where = _name(widget)
    if widget.toolTip():
        out.append((where + ".toolTip", widget.toolTip()))
    if widget.isWindow() and widget.windowTitle():
        out.append((where + ".windowTitle", widget.windowTitle()))
    if isinstance(widget, QLabel | QAbstractButton):
        out.append((where, widget.text()))
    elif isinstance(widget, QGroupBox):
        out.append((where, widget.title()))
    elif isinstance(widget, QLineEdit):
        out.append((where + ".placeholder", widget.placeholderText()))
    elif isinstance(widget, QComboBox):
        out += [(where, widget.itemText(i)) for i in range(widget.count())]
    elif isinstance(widget, QTabBar):
        out += [(where, widget.tabText(i)) for i in range(widget.count())]
    elif isinstance(widget, QDockWidget):
        out.append((where, widget.windowTitle()))
    elif isinstance(widget, QProgressBar) and widget.isTextVisible():
        out.append((where, widget.text()))
    elif isinstance(widget, QTreeWidget):
        header = widget.headerItem()
        out += [(where + ".header", header.text(c)) for c in range(header.columnCount())]
        for row in range(min(widget.topLevelItemCount(), 50)):
            item = widget.topLevelItem(row)
            out += [(where + ".row", item.text(c)) for c in range(item.columnCount())]
    elif isinstance(widget, QTreeView) and widget.model() is not None:  # a model's rows (Problems)
        out += _model_texts(where, widget.model())
    elif isinstance(widget, QTableWidget):
        headers = [widget.horizontalHeaderItem(c) for c in range(widget.columnCount())]
        out += [(where + ".header", h.text()) for h in headers if h is not None]
    elif isinstance(widget, QStatusBar):
        out.append((where + ".message", widget.currentMessage()))
    elif isinstance(widget, pg.PlotWidget):
        out += _plot_texts(where, widget.getPlotItem())
    elif isinstance(widget, pg.GraphicsLayoutWidget):
        for item in widget.ci.items:
            if isinstance(item, pg.PlotItem):
                out += _plot_texts(where, item)
    return out


def _model_texts(where: str, model) -> list[tuple[str, str]]:
    columns = range(model.columnCount())
    out = [(where + ".header", model.headerData(c, Qt.Orientation.Horizontal) or "") for c in columns]
    for row in range(min(model.rowCount(), 50)):
        out += [(where + ".row", model.index(row, c).data() or "") for c in columns]
    return out


def _plot_texts(where: str, plot: pg.PlotItem) -> list[tuple[str, str]]:
    out = [(where + ".axis", plot.getAxis(side).labelText) for side in ("left", "bottom")]
    legend = plot.legend
    if legend is not None:
        out += [(where + ".legend", label.text) for _, label in legend.items]
    return out


def menu_texts(menu: QMenu, where: str = "menu") -> list[tuple[str, str]]:
    out = [(where, menu.title())]
    for action in menu.actions():
        if action.menu() is not None:
            out += menu_texts(action.menu(), f"{where}/{plain(menu.title())}")
        elif not action.isSeparator():
            out += [(f"{where}/action", action.text()), (f"{where}/statusTip", action.statusTip())]
    return out


def all_texts(*roots: QWidget) -> list[tuple[str, str]]:
    """(where, plain text) of everything visible in ``roots`` and their children."""
    out = []
    for root in roots:
        for widget in [root, *root.findChildren(QWidget)]:
            out += widget_texts(widget)
        if isinstance(root, QMainWindow):
            for action in root.menuBar().actions():
                if action.menu() is not None:
                    out += menu_texts(action.menu())
    return [(where, plain(text)) for where, text in out if text and plain(text)]
