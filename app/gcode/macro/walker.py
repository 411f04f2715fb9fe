"""The walk: run compiled blocks with explicit call frames, emit plain blocks.

``Walker.run()`` starts at the first block of the main file and follows the control
flow of both dialects: each block has its handler (``lines.py`` for word lines,
``fanuc.py`` and ``owords.py`` for statements); plain moves are collected in the
``Batch``, other words go to ``interpret_line`` through ``emit``. Rows get, beside their own line, the
file they came from, the main program's line that caused them, the subprogram and
the loop iteration (``Trace``). Limits: a loop jumped back to more than
``LOOP_LIMIT`` times, calls nested deeper than ``DEPTH_LIMIT``, more than
``MOVE_LIMIT`` rows, or more work than ``WORK_LIMIT`` (blocks, moves and reads of the
machine's state, counted): an error naming the line. An error of the expander stops
the walk at once (rs274ngc stops too); a block the interpreter refuses is reported and
the walk goes on, so that the lines after it are checked too (issue 20), until a block
is refused a second time (a loop repeating an error: issue 19), which stops it at
once (``Batch.refused_again``). Errors are reported with their file, and the rows
before them stay, except after the move limit (``TooLarge``: none are kept).
"""

from __future__ import annotations

from app.gcode import modal_state, tooling
from app.gcode.diagnostics import ERROR, Report
from app.gcode.interp import finish_program, interpret_line
from app.gcode.lexer import Word
from app.gcode.ops import OpBuffer
from app.i18n import msg

from . import block as bk
from . import fanuc_system, predefined
from .batch import MAX_ROWS, Batch
from .calls import Library
from .errors import MacroError, Stopped, TooLarge
from .frame import DEPTH_LIMIT, Frame, Scope
from .leaf import Locals
from .trace import FileReport, Trace

LOOP_LIMIT = 1_000_000
# The budget of one expansion, counted in work done (never in wall-clock time, so that a
# result does not depend on the machine's load), in units of about 0.35 us of CPU: a
# block run costs 1, a move made ``ROW_COST``, a read of the machine's state (#5000 and
# up, ``#<_x>``) ``SYNC_COST``, or ``PUBLISH_COST`` when the state changed since the last
# read, a block the general interpreter reads one at a time (not a plain G0-G3 move of
# the batch) ``LINE_COST``. About 3 s of CPU on a busy 2-core machine and at most 1 GB
# (``MOVE_LIMIT`` rows); the 1 M-move expansions of ``bench_macro`` spend 3.3 M
# (``bench_hostile`` prints what the hostile programs take).
MOVE_LIMIT = 2_000_000
ROW_COST, SYNC_COST, PUBLISH_COST, LINE_COST = 1, 2, 55, 50
WORK_LIMIT = 7_500_000


FAULTS = (ArithmeticError, LookupError, TypeError, ValueError, OSError, RecursionError)


def fault(exc: Exception) -> MacroError:
    """A fault of the expander itself (one of ``FAULTS``): the operator gets the line,
    never a traceback."""
    return MacroError(msg("the expander failed on this line ({error}); the program cannot "
                          "be previewed", error=f"{type(exc).__name__}: {exc}"[:200]))


class Walker:
    """Expands one program (see the module docstring)."""

    def __init__(self, library: Library, state, ops: OpBuffer, report: Report, params):
        self.library, self.state, self.ops, self.report = library, state, ops, report
        self.fast_ok = state.fast_path_ok()  # the state changes only in flush() and emit()
        main = library.units[0]
        self.fanuc = main.fanuc
        self.scope = Scope(params, self.fanuc)
        self.scope.sync = self._sync
        self.frames: list[Frame] = []
        self.trace = Trace([main.name])
        self.reports = [FileReport(report, "")]
        self.blocks_run = 0
        self.syncs = self.publishes = 0
        self.interpreted = 0  # blocks through ``emit`` (the batch counts its own)
        self._published: tuple = (None, ())  # (state, (rows, call depth)) of the last sync
        self.batch = Batch()
        self.batch_limit = MAX_ROWS  # blocks collected before the batch is interpreted
        self.leaf_locals = Locals()  # the frame a leaf call's rows read (leaf.py)
        self._names: dict[str, int] = {"": 0}
        self._wheres: dict[tuple, int] = {}  # (file id, calling line, name) -> where id
        first = next((i for i, b in enumerate(main.blocks) if b.kind != bk.SKIP), 0)
        self._push(Frame(main, 0, {}, "", 0, main.program_of[first] if self.fanuc else 0))

    # --- frames ------------------------------------------------------------------------
    def _push(self, frame: Frame) -> None:
        frames = self.frames
        if len(frames) >= DEPTH_LIMIT + 1:
            raise MacroError(msg("calls nested deeper than {depth} levels", depth=DEPTH_LIMIT))
        if frames:
            frame.iteration = frame.iteration or frames[-1].iteration  # the caller's loop pass
            frame.wid = self.where_id(frame.file_id, frame.name)
        else:
            frame.wid = self._where(frame.file_id, 0, frame.name)
        frames.append(frame)
        self.scope.frame = frame

    def where_id(self, file_id: int, name: str) -> int:
        """The batch's where id of rows of subprogram ``name`` of file ``file_id`` called
        now (from the main program's line running)."""
        main = self.frames[0]
        key = (file_id, main.unit.blocks[main.pc - 1].line, name)
        wid = self._wheres.get(key)
        if wid is None:
            wid = self._wheres[key] = self._where(*key)
        return wid

    def _where(self, file_id: int, call_line: int, name: str) -> int:
        """The id of a frame's where (file id, calling line or 0, subprogram id, report)."""
        if name not in self._names:
            self._names[name] = len(self.trace.names)
            self.trace.names.append(name)
        while len(self.reports) <= file_id:
            unit = self.library.units[len(self.reports)]
            self.trace.files.append(unit.name)
            self.reports.append(FileReport(self.report, unit.name))
        return self.batch.where_id((file_id, call_line, self._names[name], self.reports[file_id]))

    def _pop(self) -> Frame:
        frame = self.frames.pop()
        self.scope.frame = self.frames[-1] if self.frames else None
        if self.frames:
            self._returned(frame)
        return frame

    def _sync(self) -> None:
        """Before a macro reads #5000 and up (Fanuc: #4000 and up) or a predefined
        ``#<_name>``: the rows so far interpreted, and the parameters the interpreter
        derives (tool, position; Fanuc's system variables or LinuxCNC's predefined
        named parameters) written."""
        self.syncs += 1
        self._spend()
        self.flush()
        key = (len(self.trace.file), len(self.frames))
        if self.state is self._published[0] and key == self._published[1]:
            return  # nothing changed since the last sync: the parameters already say it
        self._published = (self.state, key)  # the state is held: its identity stays unique
        self.publishes += 1
        tooling.publish(self.state)
        if self.fanuc:
            fanuc_system.publish(self.state)
        else:
            predefined.publish(self.state, len(self.frames) - 1)

    def _returned(self, frame: Frame) -> None:
        """A call level ended: what its M73 saved comes back (``modal_state``). Only an
        M73 (interpreted by ``emit``, never batched) sets ``saved``: without one the
        batch goes on across the return."""
        saved = self.state.saved
        if saved is None or not saved.get("auto"):
            return
        self.flush()
        before = len(self.ops.rows)
        line = frame.unit.blocks[max(0, min(frame.pc, len(frame.unit.blocks)) - 1)].line
        self._published = (None, ())  # the state is changed in place
        if modal_state.restore_on_return(self.state, line, self.ops):
            self.fast_ok = self.state.fast_path_ok()
            main = self.frames[0]
            self._trace_rows(frame, main.unit.blocks[max(0, main.pc - 1)].line, before)

    def _finish_program(self) -> None:
        """No M2/M30 ended the program: what cutter compensation holds back is written."""
        if self.state.ended:
            return
        before = len(self.ops.rows)
        finish_program(self.state, self.ops)
        rows = self.ops.rows[before:]
        self.trace.repeat(len(rows), 0, 0, 0, [int(row[0]) for row in rows])

    # --- the loop --------------------------------------------------------------------
    def work_done(self) -> int:
        """The budget spent so far (``bench_hostile`` prints it)."""
        return WORK_LIMIT - self.work_left()

    def run(self) -> None:
        """Walk to the end of the main program or the first error (reported)."""
        frames = self.frames
        try:
            while frames:
                f = frames[-1]
                if f.pc >= len(f.unit.blocks):
                    self._end_of_file(f)
                    continue
                self._run_frame(f, frames)
            self.flush()
            self._finish_program()
        except Stopped:
            pass  # reported by the interpreter; the rows before it stay
        except TooLarge as exc:
            self.report.add(exc.line, exc.column, ERROR, exc.message, file=exc.file)
            self._drop_rows()
        except MacroError as exc:
            self.report.add(exc.line, exc.column, ERROR, exc.message, file=exc.file)
            try:
                self.flush()  # the blocks before the error stay, as rs274ngc's output does
            except TooLarge:
                self._drop_rows()

    def _drop_rows(self) -> None:
        """A refused program of millions of rows: none are kept."""
        self.batch = Batch()
        self.ops.clear()
        self.trace = Trace(self.trace.files, self.trace.names)

    def work_left(self) -> int:
        """What is left of ``WORK_LIMIT`` (the blocks of a ``_run_frame`` in progress not counted)."""
        lines = self.interpreted + self.batch.interpreted
        return (WORK_LIMIT - self.blocks_run - ROW_COST * len(self.trace.file) - SYNC_COST * self.syncs
                - PUBLISH_COST * self.publishes - LINE_COST * lines)

    def _over_budget(self) -> MacroError:
        return MacroError(msg("the program does more work than the limit of {limit:,} (a block run "
                              "counts 1, a move {row}, a read of the machine's state {sync} or {publish}, "
                              "a block that is not a plain move {line}): a loop that never ends?",
                              limit=WORK_LIMIT, row=ROW_COST, sync=SYNC_COST, publish=PUBLISH_COST,
                              line=LINE_COST))

    def _spend(self) -> None:
        """Refuse the program once the budget is spent (checked where work is done besides
        running blocks, which ``_run_frame`` counts)."""
        if self.work_left() < 0:
            raise self._over_budget()

    def _run_frame(self, f: Frame, frames: list[Frame]) -> None:
        """Run blocks of frame ``f``, then of the frame it calls or returns to, until
        the walk ends or a frame reaches the end of its file (``run`` handles that)."""
        left = self.work_left()  # rows and reads only lower it: checked again when passed
        ran, b = 0, None
        try:
            while True:
                blocks = f.unit.blocks
                if not f.unit.bound:
                    bind(f.unit)
                n = len(blocks)
                while frames and frames[-1] is f and f.pc < n:
                    b = blocks[f.pc]
                    ran += 1
                    if ran > left:
                        left = self.work_left()
                        if ran > left:
                            raise self._over_budget()
                    b.run(self, f, b)
                if not frames or frames[-1].pc >= len(frames[-1].unit.blocks):
                    return
                f = frames[-1]
        except MacroError as exc:
            raise exc.at(b.line if b is not None else 0, f.unit.name if f.file_id else "") from None
        except FAULTS as exc:
            raise fault(exc).at(b.line if b is not None else 0, f.unit.name if f.file_id else "") from None
        finally:
            self.blocks_run += ran

    def _end_of_file(self, f: Frame) -> None:
        if len(self.frames) == 1:
            self.frames.pop()
        elif self.fanuc:
            fanuc.leave(self, f, None)
        else:
            raise MacroError(msg("the file ended inside a subroutine"), len(f.unit.blocks))

    def loop_back(self, f: Frame, head: int) -> None:
        count = f.counts.get(head, 0) + 1
        if count > LOOP_LIMIT:
            raise MacroError(msg("a loop ran more than {limit:,} times (it starts at line {line})",
                                 limit=LOOP_LIMIT, line=f.unit.blocks[head].line))
        f.counts[head] = count
        f.iteration = count + 1  # passes are counted from 1

    def loop_pass(self, f: Frame, head: int) -> None:
        """A loop's test passed: the rows that follow are of pass ``count + 1``."""
        f.iteration = f.counts.get(head, 0) + 1

    def loop_test(self, f: Frame, passed: bool) -> None:
        """The test of the loop whose head is ``f.pc`` (WHILE, o-word while): into the
        body, or past the loop's end."""
        if passed:
            self.loop_pass(f, f.pc)
            f.pc += 1
        else:
            self.loop_done(f, f.pc)
            f.pc = f.unit.jump[f.pc]

    def loop_done(self, f: Frame, head: int) -> None:
        f.counts.pop(head, None)
        f.iteration = 0

    def test(self, fn) -> bool:
        v = fn(self.scope)
        return v is not None and v != 0.0

    def _call_line(self, f: Frame, b: bk.Block | None) -> int:
        """The main program's line that ``b`` of frame ``f`` runs for."""
        main = self.frames[0]
        return b.line if f is main else main.unit.blocks[main.pc - 1].line

    def flush(self) -> None:
        """Interpret the collected plain blocks."""
        if len(self.batch):
            self.state = self.batch.flush(self.state, self.ops, self.trace)
            self.fast_ok = self.state.fast_path_ok()
            self.check_moves()

    def emit(self, f: Frame, b: bk.Block, words: list[Word]) -> None:
        self.interpreted += 1
        self._spend()
        self.flush()
        ops = self.ops
        before = len(ops.rows)
        self.state, refused = interpret_line(self.state, words, b.line, ops, self.reports[f.file_id])
        self.fast_ok = self.state.fast_path_ok()
        self._trace_rows(f, self._call_line(f, b), before, b.line)
        if refused:
            self.batch.refused_again(f.file_id, b.line, self.reports[f.file_id])
        if self.state.ended:
            if f is self.frames[0]:
                self._after_end(f)
            self.frames.clear()

    def check_moves(self, line: int = 0) -> None:
        """Refuse the program once it has made more than ``MOVE_LIMIT`` rows."""
        if len(self.trace.file) > MOVE_LIMIT:
            raise TooLarge(msg("the expansion makes more than {limit:,} moves", limit=MOVE_LIMIT), line)

    def _trace_rows(self, f: Frame, call_line: int, before: int, line: int = 0) -> None:
        """The rows added since row ``before`` come from frame ``f`` at ``call_line``."""
        rows = self.ops.rows[before:]
        if rows:
            main = f is self.frames[0]  # the main program: each row's own line (a held move's too)
            lines = [int(row[0]) for row in rows] if main else call_line
            self.trace.repeat(len(rows), f.file_id, self._names[f.name], f.iteration, lines)
            self.check_moves(line)

    def _after_end(self, f: Frame) -> None:
        """One warning for the first block after M2/M30 (Fanuc: before the next program;
        LinuxCNC: subroutine definitions are not "after" anything)."""
        i, blocks = f.pc, f.unit.blocks
        while i < len(blocks):
            b = blocks[i]
            if b.kind == bk.PROGRAM:
                return
            if b.kind == bk.OWORD and b.keyword == "sub":
                i = f.unit.jump[i]
                continue
            i += 1
            if b.kind == bk.PLAIN and not f.unit.lines[i - 1].strip():
                continue  # an empty line of a chunk of plain lines
            if b.kind != bk.SKIP or i - 1 in f.unit.bad:
                ended = self.state.ended
                self.report.warning(b.line, 0, msg("ignored: the program ended at line {line} (M2/M30)",
                                                   line=ended))
                return


from . import fanuc  # noqa: E402  (the statement handlers use Walker's helpers)
from .lines import bind  # noqa: E402
