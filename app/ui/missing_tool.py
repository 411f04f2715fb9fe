"""A program that asks for a tool the tool table lacks (issue 19): the tool table editor
offered from the message.

A LinuxCNC-dialect program keeps rs274's rule: ``T``, ``G43 H`` and ``G41 D`` name tools
of the table, else the line is refused with "Requested tool N not found in the tool
table" (``app.gcode.tooling``). The program panel's Problems page shows a button for the
first such tool; it opens the tool table editor on that tool's row (added when missing),
and once the table is saved the open program is loaded again with it.
"""

from __future__ import annotations

from PySide6.QtCore import QObject

from app.ui.settings.tools_dialog import open_tool_table

MISSING_TOOL = "Requested tool {number} not found in the tool table"  # the core's template


def missing_tools(diagnostics) -> list[int]:
    """The tool numbers the ``diagnostics`` say the tool table lacks, in order, once each."""
    numbers: list[int] = []
    for d in diagnostics:
        message = getattr(d, "message", None)
        if getattr(message, "template", None) == MISSING_TOOL:
            number = int(message.args["number"])
            if number not in numbers:
                numbers.append(number)
    return numbers


class MissingTool(QObject):
    """Opens the tool table editor on a missing tool; reloads the program after OK."""

    def __init__(self, window) -> None:
        super().__init__(window)
        self.w = window
        self.dialog = None
        window.program_panel.tool_table_requested.connect(self.edit)

    def edit(self, number: int) -> None:
        """The tool table editor with tool ``number`` focused; the open program is read
        again with the table once it is saved."""
        self.dialog = open_tool_table(self.w, focus=number, then=self._reload)

    def _reload(self) -> None:
        loaded = self.w.loaded
        if loaded is not None:
            self.w.open_file(loaded.path)
