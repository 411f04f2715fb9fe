"""Drive the two interpreters over a whole program, line by line or run by run.

Simple lines (``bulk.Scan``) in a state the fast path handles go to ``vector.run``
in runs (a block-deleted "/" line too, unless the operator's switch is on: then a run
of them is skipped at once, with the general path's warning for each); every other line
is lexed and interpreted by the general path. After a line the general path refused,
the next ``SLOW_AFTER_ERROR`` lines also take the general path so a file full of errors
costs linear time; the general path's rows
become arrays every ``FLUSH_ROWS`` rows (a file read line by line costs no more
memory per move than the fast path). After M2/M30 nothing more
is interpreted; words after it earn one warning.
"""

from __future__ import annotations

import numpy as np

from app.i18n import msg

from . import vector
from .bulk import Scan
from .diagnostics import WARNING, Report
from .interp import finish_program, interpret_line
from .lexer import lex_line
from .ops import OpBuffer
from .state import State

SLOW_AFTER_ERROR = 64
RUN_MAX = 1 << 16
RUN_AFTER_ERROR = 256
BLOCK_DELETED = msg("block delete '/': line skipped")
FLUSH_ROWS = 1 << 14  # rows of the general path kept as tuples (~200 bytes each) before they become arrays


def _general(state: State, text: str, line_no: int, ops: OpBuffer, report: Report) -> tuple[State, bool]:
    """One line through the general lexer and interpreter; (state, refused?)."""
    lexed = lex_line(text, line_no)
    if lexed.error is not None:
        report.add(lexed.error.line, lexed.error.column, lexed.error.severity, lexed.error.message)
        return state, True
    if lexed.skip == "block delete" and state.block_delete:
        report.warning(line_no, 0, BLOCK_DELETED, "block delete")
        return state, False
    if lexed.skip == "%" or not lexed.words:
        return state, False
    return interpret_line(state, lexed.words, line_no, ops, report)


def _after_end(lines: list[str], start: int, end_line: int, report: Report) -> None:
    for i in range(start, len(lines)):
        lexed = lex_line(lines[i], i + 1)
        if lexed.words or lexed.error:
            report.warning(i + 1, 0, msg("ignored: the program ended at line {line} (M2/M30)", line=end_line))
            return


class Runner:
    """Interprets a program as its scan becomes ready: ``advance(scan, ready)`` runs
    every line before ``ready`` not yet run; ``finish()`` ends and returns the state."""

    def __init__(self, lines: list[str], ops: OpBuffer, report: Report, state: State | None = None):
        self.lines, self.ops, self.report = lines, ops, report
        self.state = state or State()
        self.i = 0  # the next line to run
        self.slow_until = 0
        self.run_len = RUN_MAX

    def advance(self, scan: Scan, ready: int) -> None:
        """Run lines ``self.i .. ready``; ``scan`` holds them (``scan.first`` <= ``self.i``)."""
        state, i, simple, first = self.state, self.i, scan.simple, scan.first
        if i >= ready:
            return
        skipped = None
        if state.block_delete and scan.deleted is not None and scan.deleted[i - first : ready - first].any():
            skipped = simple & scan.deleted  # the switch is on: these are skipped a run at a time
            simple = simple & ~scan.deleted
        complex_lines = np.flatnonzero(~simple[i - first : ready - first]) + i
        while i < ready and not state.ended:
            if simple[i - first] and i >= self.slow_until and state.fast_path_ok():
                k = int(np.searchsorted(complex_lines, i))
                end = min(int(complex_lines[k]) if k < len(complex_lines) else ready, i + self.run_len)
                state, stop = vector.run(scan, i, end, state, self.ops)
                self.run_len = min(self.run_len * 2, RUN_MAX) if stop == end else RUN_AFTER_ERROR
                if stop > i or stop == end:
                    i = stop
                    continue
            if skipped is not None and skipped[i - first]:
                i = self._skip_deleted(skipped[i - first : ready - first], i)
                continue
            state, refused = _general(state, self.lines[i], i + 1, self.ops, self.report)
            if refused:
                self.slow_until = i + 1 + SLOW_AFTER_ERROR
            elif len(self.ops.rows) >= FLUSH_ROWS:
                self.ops.flush()
            i += 1
        self.state, self.i = state, i

    def _skip_deleted(self, skipped: np.ndarray, i: int) -> int:
        """Skip the run of well-formed "/" lines that starts at line ``i`` (``skipped``
        from there on), one warning each as the general path gives; the line after it."""
        end = i + (len(skipped) if skipped.all() else int(np.argmin(skipped)))
        self.report.add_many(range(i + 1, end + 1), 0, WARNING, BLOCK_DELETED, "block delete")
        return end

    def finish(self) -> State:
        finish_program(self.state, self.ops)
        if self.state.ended:
            _after_end(self.lines, self.i, self.state.ended, self.report)
        return self.state


def run(lines: list[str], scan: Scan, ops: OpBuffer, report: Report, state: State | None = None) -> State:
    """Interpret every line; rows go to ``ops``, diagnostics to ``report``."""
    runner = Runner(lines, ops, report, state)
    runner.advance(scan, len(lines))
    return runner.finish()
