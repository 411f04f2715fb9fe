"""The walk: run compiled blocks with explicit call frames, emit plain blocks.

``Walker.run()`` starts at the first block of the main file and follows the control
flow of both dialects (handlers per block kind); every ``WORDS`` block that is left
is evaluated (all values first, then the line's assignments, as LinuxCNC does) and
handed to ``interpret_line`` as plain words. Rows get, beside their own line, the
file they came from, the main program's line that caused them, the subprogram and
the loop iteration (``Trace``). Limits: a loop jumped back to more than
``LOOP_LIMIT`` times, calls nested deeper than ``DEPTH_LIMIT``, more than
``MOVE_LIMIT`` rows or ``BLOCK_LIMIT`` blocks run: an error naming the line. The
first error stops the walk (rs274ngc stops too); it is reported with its file.
"""

from __future__ import annotations

import contextlib

from app.gcode import modal_state, tooling
from app.gcode.diagnostics import ERROR, Report
from app.gcode.interp import finish_program, interpret_line
from app.gcode.lexer import Word
from app.gcode.ops import OpBuffer
from app.i18n import msg

from . import block as bk
from .batch import MAX_ROWS, Batch
from .calls import Library
from .errors import MacroError
from .frame import Frame, Scope
from .trace import FileReport, Trace

LOOP_LIMIT = 1_000_000
DEPTH_LIMIT = 64
MOVE_LIMIT = 20_000_000
BLOCK_LIMIT = 50_000_000


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
        self.batch = Batch()
        self.pending_call = None
        self._names: dict[str, int] = {"": 0}
        self._wheres: dict[tuple, tuple] = {}  # (file id, calling line, name) -> (where, its id)
        first = next((i for i, b in enumerate(main.blocks) if b.kind != bk.SKIP), 0)
        self._push(Frame(main, 0, {}, "", 0, main.program_of[first] if self.fanuc else 0))

    # --- frames ------------------------------------------------------------------------
    def _push(self, frame: Frame) -> None:
        frames = self.frames
        if len(frames) >= DEPTH_LIMIT + 1:
            raise MacroError(msg("calls nested deeper than {depth} levels", depth=DEPTH_LIMIT))
        if frames:
            frame.iteration = frame.iteration or frames[-1].iteration  # the caller's loop pass
            main = frames[0]
            call_line = main.unit.blocks[main.pc - 1].line  # the main program's line running
        else:
            call_line = 0
        frames.append(frame)
        self.scope.frame = frame
        key = (frame.file_id, call_line, frame.name)
        known = self._wheres.get(key)
        if known is None:
            known = self._wheres[key] = self._where(*key)
        frame.where, frame.wid = known

    def _where(self, file_id: int, call_line: int, name: str) -> tuple[tuple, int]:
        """A frame's ``where`` (file id, calling line or 0, subprogram id, report) and its id."""
        if name not in self._names:
            self._names[name] = len(self.trace.names)
            self.trace.names.append(name)
        while len(self.reports) <= file_id:
            unit = self.library.units[len(self.reports)]
            self.trace.files.append(unit.name)
            self.reports.append(FileReport(self.report, unit.name))
        where = (file_id, call_line, self._names[name], self.reports[file_id])
        return where, self.batch.where_id(where)

    def _pop(self) -> Frame:
        frame = self.frames.pop()
        self.scope.frame = self.frames[-1] if self.frames else None
        if self.frames:
            self._returned(frame)
        return frame

    def _sync(self) -> None:
        """Before a macro reads #5000 and up: the rows so far interpreted, and the
        parameters the interpreter derives (tool, position) written."""
        self.flush()
        tooling.publish(self.state)

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
        except MacroError as exc:
            self.report.add(exc.line, exc.column, ERROR, exc.message, file=exc.file)
            with contextlib.suppress(MacroError):  # the move limit, reported already
                self.flush()  # the blocks before the error stay, as rs274ngc's output does

    def _run_frame(self, f: Frame, frames: list[Frame]) -> None:
        """Run blocks of frame ``f``, then of the frame it calls or returns to, until
        the walk ends or a frame reaches the end of its file (``run`` handles that)."""
        left = BLOCK_LIMIT - self.blocks_run
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
                        too_many = msg("the program runs more than {limit:,} blocks", limit=BLOCK_LIMIT)
                        raise MacroError(too_many, b.line)
                    b.run(self, f, b)
                if not frames or frames[-1].pc >= len(frames[-1].unit.blocks):
                    return
                f = frames[-1]
        except MacroError as exc:
            raise exc.at(b.line if b is not None else 0, f.unit.name if f.file_id else "") from None
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

    # --- plain blocks ------------------------------------------------------------------
    def words(self, f: Frame, b: bk.Block) -> None:
        scope = self.scope
        values = b.values(scope) if b.values is not None else ()
        f.pc += 1
        if not b.words or b.call_only:
            pass
        elif b.simple and self.fast_ok and self.batch.add(b, values, f.iteration, f.wid):
            if len(self.batch) >= MAX_ROWS:
                self.flush()
        else:
            self._general(f, b, values, len(b.words))
        if b.assigns:
            self.assign(b, values)
        if b.call_only:
            call = b.call
            by_letter = {w.letter: v for w, v in zip(b.words, values, strict=False) if v is not None}
            self._fanuc_call(f, b, call.letter, by_letter.pop(call.letter), call.column, by_letter)
        elif self.pending_call is not None:
            self._pending_call(f)

    def _pending_call(self, f: Frame) -> None:
        """Run the call ``_general`` found among a line's computed words."""
        block, call, words = self.pending_call
        self.pending_call = None
        by_letter = {w.letter: w.value for w in words}
        self._fanuc_call(f, block, call.letter, call.value, call.column, by_letter)

    def simple_words(self, f: Frame, b: bk.Block) -> None:
        """``words`` for a block of G0-G3 X Y Z I J F words: straight into the batch."""
        f.pc += 1
        batch = self.batch
        if b.fast is not None and self.fast_ok:  # no assignments, a constant G0-G3 or none
            batch.extend(b.fast(self.scope, f.wid, f.iteration))
            batch.append(b)
            if len(batch.blocks) >= MAX_ROWS:
                self.flush()
            return
        values = b.values(self.scope)
        made = b.row(values, f.wid, f.iteration) if self.fast_ok else None
        if made is None:
            self._general(f, b, values, len(b.words))
        else:
            batch.extend(made)
            batch.append(b)
            if len(batch.blocks) >= MAX_ROWS:
                self.flush()
        if b.assigns:
            self.assign(b, values)
        if self.pending_call is not None:  # a computed G65 (G#1 with #1 = 65)
            self._pending_call(f)

    def call_words(self, f: Frame, b: bk.Block) -> None:
        """``words`` for a Fanuc line that is only a call (``b.call_only``)."""
        values = b.values(self.scope)
        f.pc += 1
        if b.assigns:
            self.assign(b, values)
        call = b.call
        by_letter = {w.letter: v for w, v in zip(b.words, values, strict=False) if v is not None}
        fanuc.call(self, f, b, call.letter, by_letter.pop(call.letter), call.column, by_letter)

    def g65_words(self, f: Frame, b: bk.Block) -> None:
        """``call_words`` for a ``G65`` line planned by ``fanuc.g65_plan``."""
        values = b.values(self.scope)
        f.pc += 1
        fanuc.g65(self, f, b, values)

    def return_only(self, f: Frame, b: bk.Block) -> None:
        """``call_words`` for a line that is only ``M99`` (no P, L, nor assignments)."""
        f.pc += 1
        if len(self.frames) == 1:
            raise MacroError(msg("M99 outside a subprogram (the main program ends with M30)"))
        fanuc.leave(self, f, None)

    def assignments(self, f: Frame, b: bk.Block) -> None:
        """``words`` for a line of assignments only."""
        values = b.values(self.scope)
        f.pc += 1
        b.store(self.scope, values)

    def assign(self, b: bk.Block, values) -> None:
        """Apply the line's assignments (their values were read with the line)."""
        b.store(self.scope, values)

    def _general(self, f: Frame, b: bk.Block, values, n: int) -> None:
        words = []
        for w, v in zip(b.words, values, strict=False):
            if v is None:
                if w.bare:
                    continue  # Fanuc: a word whose parameter is vacant is left out
                v = 0.0
            words.append(Word(w.letter, v, w.column))
        call = self._call_word(words) if self.fanuc else None
        if call is None:
            if words:
                self.emit(f, b, words)
            return
        if call.letter == "M":  # motion on an M98/M99 line runs first
            rest = [w for w in words if w is not call and w.letter not in "PL"]
            if rest:
                self.emit(f, b, rest)
        self.pending_call = (b, call, [w for w in words if w is not call])

    def _call_line(self, f: Frame, b: bk.Block | None) -> int:
        """The main program's line that ``b`` of frame ``f`` runs for."""
        main = self.frames[0]
        return b.line if f is main else main.unit.blocks[main.pc - 1].line

    def flush(self) -> None:
        """Interpret the collected plain blocks."""
        if len(self.batch):
            self.state = self.batch.flush(self.state, self.ops, self.trace)
            self.fast_ok = self.state.fast_path_ok()
            if len(self.trace.file) > MOVE_LIMIT:
                raise MacroError(msg("the expansion makes more than {limit:,} moves", limit=MOVE_LIMIT))

    def emit(self, f: Frame, b: bk.Block, words: list[Word]) -> None:
        self.flush()
        ops = self.ops
        before = len(ops.rows)
        self.state, _ = interpret_line(self.state, words, b.line, ops, self.reports[f.file_id])
        self.fast_ok = self.state.fast_path_ok()
        self._trace_rows(f, self._call_line(f, b), before, b.line)
        if self.state.ended:
            if f is self.frames[0]:
                self._after_end(f)
            self.frames.clear()

    def _trace_rows(self, f: Frame, call_line: int, before: int, line: int = 0) -> None:
        """The rows added since row ``before`` come from frame ``f`` at ``call_line``."""
        rows = self.ops.rows[before:]
        if rows:
            main = f is self.frames[0]  # the main program: each row's own line (a held move's too)
            lines = [int(row[0]) for row in rows] if main else call_line
            self.trace.repeat(len(rows), f.file_id, self._names[f.name], f.iteration, lines)
            if len(self.trace.file) > MOVE_LIMIT:
                raise MacroError(msg("the expansion makes more than {limit:,} moves", limit=MOVE_LIMIT), line)

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
            if b.kind != bk.SKIP or i - 1 in f.unit.bad:
                ended = self.state.ended
                self.report.warning(b.line, 0, msg("ignored: the program ended at line {line} (M2/M30)",
                                                   line=ended))
                return

    def skip(self, f: Frame, b: bk.Block) -> None:
        if f.pc in f.unit.bad:
            self.frames.clear()  # its error is reported already; the walk stops as rs274ngc does
            return
        if b.skip == "block delete":
            self.reports[f.file_id].warning(b.line, 0, msg("block delete '/': line skipped"), "block delete")

        f.pc += 1

    def _call_word(self, words: list[Word]) -> Word | None:
        """The M98/M99/G65 word of a Fanuc line whose values were computed, if any."""
        for w in words:
            if (w.letter == "M" and w.value in (98.0, 99.0)) or (w.letter == "G" and w.value == 65.0):
                return w
        return None

    def _fanuc_call(self, f: Frame, b: bk.Block, letter: str, code: float, column: int, by_letter) -> None:
        fanuc.call(self, f, b, letter, code, column, by_letter)


from . import fanuc  # noqa: E402  (the statement handlers use Walker's helpers)
from .owords import handler as oword_handler  # noqa: E402
from .runs import run_handler, runs  # noqa: E402

HANDLERS = [None] * 10  # by block kind
for _kind, _handler in {
    bk.WORDS: Walker.words, bk.SKIP: Walker.skip, bk.OWORD: None, bk.PROGRAM: fanuc.program,
    bk.IF_GOTO: fanuc.if_goto, bk.IF_THEN: fanuc.if_then, bk.GOTO: fanuc.goto,
    bk.WHILE: fanuc.while_do, bk.DO: fanuc.do, bk.END: fanuc.end,
}.items():
    HANDLERS[_kind] = _handler


def _handler(b: bk.Block):
    if b.kind == bk.OWORD:
        return oword_handler(b)
    if b.kind == bk.WORDS and not b.words and b.values is not None:
        return Walker.assignments
    if b.kind == bk.WORDS and b.simple and not b.call_only:
        return Walker.simple_words
    if b.kind == bk.WORDS and b.call_only and b.words:
        bare_m99 = len(b.words) == 1 and b.words[0] is b.call and b.call.letter == "M" and not b.assigns
        if bare_m99 and bk.constant(b.call.code) == 99.0:
            return Walker.return_only
        b.plan = fanuc.g65_plan(b) if b.call.letter == "G" else None
        return Walker.call_words if b.plan is None else Walker.g65_words
    return HANDLERS[b.kind]


def bind(unit) -> None:
    """Give every block of ``unit`` the handler that runs it (once per unit); a block
    that starts a straight run of moves runs the whole run (``runs.py``)."""
    for b in unit.blocks:
        b.run = _handler(b)
    for i, (members, span) in runs(unit).items():
        unit.blocks[i].run = run_handler(members, span, unit.blocks[i].run)
    unit.bound = True
