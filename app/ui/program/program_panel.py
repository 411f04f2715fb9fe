"""The program panel: summary, source listing with line numbers (the executing line
highlighted), and the problems list (double-click jumps to the line)."""

from __future__ import annotations

import numpy as np
from PySide6.QtCore import QEvent, Qt, Signal
from PySide6.QtGui import QAction, QFontDatabase
from PySide6.QtWidgets import (
    QAbstractItemView,
    QHeaderView,
    QLabel,
    QMenu,
    QPushButton,
    QTableView,
    QTabWidget,
    QTreeView,
    QVBoxLayout,
    QWidget,
)

from app.ui.missing_tool import missing_tools
from app.ui.numbers import fill
from app.ui.program.problems_model import ProblemsModel
from app.ui.program.source_model import SourceModel
from app.ui.program.summary import describe

CELL_PADDING = 16  # pixels around a cell's text (the item view's margins and focus frame)


class ProgramPanel(QWidget):
    line_activated = Signal(int)  # 1-based source line chosen by the operator
    start_here_requested = Signal(int)  # 1-based source line: "Start here" (right-click)
    tool_table_requested = Signal(int)  # a tool the program needs and the tool table lacks

    def __init__(self, parent=None):
        super().__init__(parent)
        self.summary = QLabel()
        self.summary.setWordWrap(True)
        self.summary.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.source_model = SourceModel(self)
        self.source = _source_view(self.source_model)
        self.source.doubleClicked.connect(lambda index: self.line_activated.emit(index.row() + 1))
        self.source.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        self.source.customContextMenuRequested.connect(self._source_menu)
        self.start_here_action = QAction(self)  # enabled by the window's state table
        self.start_here_action.triggered.connect(lambda: self.start_here_requested.emit(self._menu_line))
        self._menu_line = 0
        self.context = QLabel()  # where an expanded program is: subprogram and loop pass
        self.context.hide()
        self.problems_model = ProblemsModel(self)
        self.problems = QTreeView()  # every finding, each row made when it scrolls into view
        self.problems.setRootIsDecorated(False)
        self.problems.setUniformRowHeights(True)
        self.problems.setModel(self.problems_model)
        self.problems.activated.connect(self._problem_activated)
        self.missing_tool = 0  # the first tool the problems say the tool table lacks
        self.tool_button = QPushButton()  # offers the tool table editor on that tool
        self.tool_button.clicked.connect(lambda: self.tool_table_requested.emit(self.missing_tool))
        self.tool_button.hide()
        self.problems_page = QWidget()
        page = QVBoxLayout(self.problems_page)
        page.setContentsMargins(0, 0, 0, 0)
        page.addWidget(self.tool_button)
        page.addWidget(self.problems, 1)
        self.tabs = QTabWidget()
        self.tabs.addTab(self.source, "")
        self.tabs.addTab(self.problems_page, "")
        layout = QVBoxLayout(self)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.addWidget(self.summary)
        layout.addWidget(self.tabs, 1)
        layout.addWidget(self.context)
        self.program = None
        self._shown = None  # (program, name) on show
        self.retranslate_ui()

    def retranslate_ui(self) -> None:
        self.problems_model.set_headers([self.tr("Line"), self.tr("Col"), "", self.tr("Message")])
        self.tabs.setTabText(0, self.tr("Source"))
        self.start_here_action.setText(self.tr("Start here"))
        if self._shown is None:
            empty = self.tr("No program open. File ▸ Open… or drop a G-code file on the window.")
            self.summary.setText(empty)
            self.tabs.setTabText(1, self.tr("Problems"))
        else:
            self.show_program(*self._shown, keep_tab=True)

    def changeEvent(self, event) -> None:  # noqa: N802 (Qt override)
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate_ui()
        super().changeEvent(event)

    def show_program(self, program, name: str = "", keep_tab: bool = False) -> None:
        """Show ``program``; ``keep_tab``: only re-say it (another language), same listing."""
        errors = list(_diagnostics(program, "errors"))
        warnings = list(_diagnostics(program, "warnings"))
        self.program = program
        if not keep_tab:
            expanded = getattr(getattr(program, "ops", None), "source", None) is not None
            moves = program.moves_per_line() if expanded else None
            self.source_model.set_lines(program.lines, [d.line for d in errors], moves,  # read on scroll
                                        (lambda line: _device_lines_of(program, line)) if expanded else None)
            if expanded:
                header = self.source.horizontalHeader()
                header.setSectionResizeMode(0, QHeaderView.ResizeMode.Stretch)
                header.setSectionResizeMode(1, QHeaderView.ResizeMode.ResizeToContents)
            self.context.hide()
        self._shown = (program, name)
        self.summary.setText(describe(program, name))
        self._fill_problems(errors, warnings, keep_tab)

    def clear(self) -> None:
        self.program = None
        self.context.hide()
        self._shown = None
        self.source_model.set_lines([])
        self.problems_model.set_problems([], {})
        self._offer_tool_table([])
        self.summary.setText(self.tr("No program open."))

    def _fill_problems(self, errors, warnings, keep_tab: bool = False) -> None:
        rows = [("error", d) for d in errors] + [("warning", d) for d in warnings]
        said = {"error": self.tr("error"), "warning": self.tr("warning")}
        self.problems_model.set_problems(rows, said)
        self._fit_columns()
        counts = fill(self.tr("%1, %2"), self.tr("%n error(s)", "", len(errors)),
                      self.tr("%n warning(s)", "", len(warnings)))
        self.tabs.setTabText(1, fill(self.tr("Problems (%1)"), counts))
        self._offer_tool_table(errors)
        if errors and not keep_tab:
            self.tabs.setCurrentWidget(self.problems_page)

    def _fit_columns(self) -> None:
        """Line, column and kind as wide as their widest text or their title: worked out
        from the texts (``ProblemsModel.widest``), not by the view, which would ask the
        model for every row."""
        widest = self.problems_model.widest()
        metrics, header = self.problems.fontMetrics(), self.problems.header()
        for column, text in enumerate(widest):
            width = metrics.horizontalAdvance(text) + CELL_PADDING
            self.problems.setColumnWidth(column, max(width, header.sectionSizeFromContents(column).width()))

    def _offer_tool_table(self, errors) -> None:
        """The button to the tool table editor when an error says a tool is not in it."""
        missing = missing_tools(errors)
        self.missing_tool = missing[0] if missing else 0
        if missing:
            numbers = ", ".join(f"T{n}" for n in missing)
            text = self.tr("Tool %1 is not in the tool table: edit the tool table…", "", len(missing))
            self.tool_button.setText(fill(text, numbers))
        self.tool_button.setVisible(bool(missing))

    def _source_menu(self, pos) -> None:
        index = self.source.indexAt(pos)
        if not index.isValid():
            return
        menu = QMenu(self)
        self._menu_line = index.row() + 1
        menu.addAction(self.start_here_action)
        menu.popup(self.source.viewport().mapToGlobal(pos))

    def _problem_activated(self, index) -> None:
        line = self.problems_model.line_of(index.row())
        if line:
            self.go_to_line(line)
            self.line_activated.emit(line)

    def go_to_line(self, line: int) -> None:
        index = self.source_model.index(line - 1, 0)
        self.source.setCurrentIndex(index)
        self.source.scrollTo(index, QAbstractItemView.ScrollHint.PositionAtCenter)
        self.tabs.setCurrentWidget(self.source)

    def show_device_line(self, program, index: int) -> None:
        """Follow machine line ``index`` of ``program``: highlight the main program's line
        that made it and, inside a subprogram or loop, say which one and which pass."""
        self.set_current_line(int(program.line_map[index]))
        name, iteration = program.context_at(index) if hasattr(program, "context_at") else ("", 0)
        if not name and not iteration:
            self.context.hide()
            return
        parts = [self.tr("in subprogram %1").replace("%1", name)] if name else []
        if iteration:
            parts.append(self.tr("loop pass %1").replace("%1", f"{iteration:,}"))
        self.context.setText(", ".join(parts))
        self.context.show()

    def set_current_line(self, line: int, follow: bool = True) -> None:
        """Highlight the executing 1-based source line and keep it in view."""
        if line == self.source_model.current_line:
            return
        self.source_model.set_current_line(line)
        if follow and line > 0:
            index = self.source_model.index(line - 1, 0)
            self.source.scrollTo(index, QAbstractItemView.ScrollHint.PositionAtCenter)


def _source_view(model: SourceModel) -> QTableView:
    view = QTableView()
    view.setModel(model)
    view.setFont(QFontDatabase.systemFont(QFontDatabase.SystemFont.FixedFont))
    view.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
    view.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
    view.setShowGrid(False)
    view.setWordWrap(False)
    view.horizontalHeader().hide()
    view.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
    rows = view.verticalHeader()
    rows.hide()
    rows.setSectionResizeMode(QHeaderView.ResizeMode.Fixed)
    rows.setDefaultSectionSize(view.fontMetrics().height() + 2)
    return view


def _device_lines_of(program, line: int, limit: int = 12) -> list[str]:
    """The first ``limit`` machine lines made by 1-based ``line`` of the main program."""
    indices = np.flatnonzero(np.asarray(program.line_map) == line)[:limit]
    device = program.device_lines
    return [device[i] for i in indices.tolist()]


def _diagnostics(program, kind: str):
    return getattr(program, kind, ()) or ()

