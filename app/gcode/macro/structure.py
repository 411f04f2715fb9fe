"""A source file compiled into blocks, with every jump target found before running.

``Unit(name, lines, fanuc, block_delete)`` compiles each line once (``block.py``; a
line starting with ``/`` is skipped when ``block_delete``, the operator's switch, is on) and records what
the walker needs: ``jump[i]`` (where a LinuxCNC ``if``/``elseif`` goes when false,
where ``else``/``elseif`` go after a taken branch, where a loop exits),
``back[i]`` (the head a loop end or ``continue`` returns to), ``subs`` (o-name ->
index of its ``sub``), and for Fanuc the programs in the file (``O`` number ->
first index), the ``N`` labels of each program and the ``WHILE``/``DO``-``END``
pairs. Lines that do not compile are kept in ``errors`` (all of them, so one load
lists every problem) and become ``SKIP`` blocks that stop the run if reached.
Unbalanced structures are errors naming the line and column.
"""

from __future__ import annotations

import bisect
import re

from app.i18n import msg

from .block import DO, END, OWORD, PLAIN, PROGRAM, SKIP, WHILE, Block, compile_line
from .errors import MacroError
from .plain import chunks, labels, outside

MAX_LINES = 50_000  # lines the expander compiles, every file together (about 2 s and 250 MB): plain
# lines in chunks (plain.py) do not count


def too_many_lines() -> MacroError:
    return MacroError(msg("the expander compiles at most {limit:,} lines of a program and its subprogram "
                          "files (lines of plain words do not count); this line is past the limit",
                          limit=MAX_LINES))


_FANUC = re.compile(
    r"(?im)^[ \t]*(?:n[ \t]*\d+[ \t]*)?(?:o[ \t]*\d+[ \t]*(?:\([^\n]*\))?[ \t]*$|if[ \t]*\[|goto"
    r"|while[ \t]*\[|(?:do|end)[ \t]*\d)|m[ \t]*0*9[ \t]*[89](?![\d.])|g[ \t]*0*6[ \t]*5(?![\d.])")


def is_fanuc(text: str) -> bool:
    """True when ``text`` is written in Fanuc macro B rather than LinuxCNC o-words: it has
    a bare ``O`` number line, ``IF [``, ``GOTO``, ``WHILE [``, ``DO``/``END`` or
    ``M98``/``M99``/``G65``."""
    return _FANUC.search(re.sub(r"\([^()\n]*\)", "", text)) is not None


LOOP_HEADS = {"while", "do"}  # break/continue work in these (not in repeat, as rs274ngc)


def _past_limit(found: list[tuple[int, int]], count: int, limit: int) -> int | None:
    """The index of the first line to compile past ``limit`` (0: no limit), the lines of
    the chunks ``found`` left out, or None."""
    if not limit:
        return None
    start = 0
    for a, b in [*found, (count, count)]:
        if a - start > limit:
            return start + limit
        limit -= a - start
        start = b
    return None


class Unit:
    """One compiled source file (see the module docstring)."""

    def __init__(self, name: str, lines, fanuc: bool | None, block_delete: bool = False,
                 compile_limit: int = 0, chunked: tuple | None = None):
        """``fanuc``: the dialect, or None to tell it from the lines (``is_fanuc``);
        ``chunked``: ``plain.chunks(lines)`` when the caller has it already."""
        found, self.scan = chunked or chunks(lines)
        if fanuc is None:
            fanuc = is_fanuc(outside(lines, found))  # a simple line is of either dialect
        self.name, self.fanuc, self.block_delete, self.lines = name, fanuc, block_delete, lines
        self.blocks: list[Block] = []
        self.starts: list[int] = []  # the index of each distinct block (a chunk's first line)
        self.errors: list[MacroError] = []
        self.bad: set[int] = set()
        self.plain_label_of = labels(lines, found) if fanuc else {}
        self.plain_labels = sorted(self.plain_label_of)  # chunk lines with an N label
        self.compiled = 0  # lines compiled (the lines of chunks are not)
        self.jump: dict[int, int] = {}
        self.back: dict[int, int] = {}
        self.subs: dict[str, int] = {}
        self.programs: dict[int, int] = {}  # Fanuc O number -> index of its O line
        self.program_of: list[int] = []  # block index -> index of its program's first block
        self.labels: dict[tuple[int, int], int] = {}  # (program start, N) -> index
        self.bound = False  # the walker has given each block its handler
        self.leaves: dict = {}  # block index -> its leaf subprogram's body or None (leaf.py)
        self.loops: set[int] = set()  # heads of loops run by a compiled handler (loop.py)
        past = _past_limit(found, len(lines), compile_limit)
        if past is not None:  # refused before compiling anything: all of it would cost seconds
            self.errors.append(too_many_lines().at(past + 1, name))
            self.blocks, self.program_of = [Block(0, SKIP)] * len(lines), [0] * len(lines)
            self.structure_ok = False
            return
        for start, end in [*found, (len(lines), len(lines))]:
            for i in range(len(self.blocks), start):
                self._compile(i, lines[i])
            if end > start:
                self.starts.append(start)
                self.blocks.extend([Block(start + 1, PLAIN, end=end)] * (end - start))
        compiled = len(self.errors)
        self._structure()
        self.structure_ok = len(self.errors) == compiled  # jumps are only safe when balanced

    def _compile(self, i: int, text: str) -> None:
        """Line ``i``'s block (a ``SKIP`` block and an error when it does not compile)."""
        self.starts.append(i)
        self.compiled += 1
        try:
            block = compile_line(text, i + 1, self.fanuc)
            if block.deleted and self.block_delete:  # the operator's switch is on: skipped
                block = Block(i + 1, SKIP, skip="block delete")
            self.blocks.append(block)
        except MacroError as exc:
            self.errors.append(exc.at(i + 1, self.name))
            self.bad.add(i)
            self.blocks.append(Block(i + 1, SKIP))

    def fail(self, message: str, block: Block) -> None:
        self.errors.append(MacroError(message, block.line, block.column, self.name))

    def _structure(self) -> None:
        if self.fanuc:
            self._programs()
            self._fanuc_loops()
            for b in map(self.blocks.__getitem__, self.starts):
                if b.kind == OWORD:  # Fanuc O numbers and M98/M99 beside LinuxCNC o-words
                    self.fail(msg("o{name} {keyword}: a LinuxCNC o-word statement in a program of Fanuc "
                                  "O numbers (O0001 ... M99, M98 P): one style per program",
                                  name=b.oname, keyword=b.keyword), b)
        else:
            self._owords()

    # --- Fanuc -----------------------------------------------------------------------
    def _programs(self) -> None:
        start = 0
        for i in self.starts:
            b = self.blocks[i]
            if b.kind == PROGRAM:
                start = i
                if b.number in self.programs:
                    self.fail(msg("program O{number} is defined twice", number=b.number), b)
                self.programs.setdefault(b.number, i)
            if b.kind == PLAIN:
                self.program_of.extend([start] * (b.end - i))
                labelled = self.plain_labels
                for k in labelled[bisect.bisect_left(labelled, i):bisect.bisect_left(labelled, b.end)]:
                    self.labels.setdefault((start, self.plain_label_of[k]), k)
                continue
            self.program_of.append(start)
            if b.label is not None:
                self.labels.setdefault((start, b.label), i)

    def _fanuc_loops(self) -> None:
        open_loops: list[tuple[int, int]] = []  # (DO number, index)
        program = 0
        for i in self.starts:
            b = self.blocks[i]
            if self.program_of[i] != program:
                self._unclosed_do(open_loops)
                open_loops, program = [], self.program_of[i]
            if b.kind in (WHILE, DO):
                if not 1 <= b.number <= 3:
                    self.fail(msg("DO {number}: the loop number must be 1, 2 or 3", number=b.number), b)
                if any(n == b.number for n, _ in open_loops):
                    self.fail(msg("DO {number} inside another loop DO {number}", number=b.number), b)
                open_loops.append((b.number, i))
            elif b.kind == END:
                if not open_loops or open_loops[-1][0] != b.number:
                    self.fail(msg("END {number} without its DO {number} (the open loop is DO {open})",
                                  number=b.number, open=open_loops[-1][0]) if open_loops
                              else msg("END {number} without its DO {number}", number=b.number), b)
                    continue
                _, head = open_loops.pop()
                self.jump[head], self.back[i] = i + 1, head
        self._unclosed_do(open_loops)

    def _unclosed_do(self, open_loops) -> None:
        for number, i in open_loops:
            self.fail(msg("DO {number} has no END {number}", number=number), self.blocks[i])

    # --- LinuxCNC o-words --------------------------------------------------------------
    def _owords(self) -> None:
        stack: list[tuple[str, str, int, list[int]]] = []  # (keyword, o-name, index, branches)
        for i in self.starts:
            b = self.blocks[i]
            if b.kind != OWORD:
                continue
            handler = getattr(self, "_o_" + b.keyword, None)
            if handler is not None:
                handler(stack, i, b)
        for keyword, _, i, _ in stack:
            self.fail(msg("'{keyword}' is never closed", keyword=keyword), self.blocks[i])

    def _open(self, stack, i, b) -> None:
        stack.append((b.keyword, b.oname, i, [i]))

    def _close(self, stack, i, b, opener: str, closer: str) -> tuple | None:
        if not stack or stack[-1][0] != opener or stack[-1][1] != b.oname:
            said = dict(name=b.oname, closer=closer, opener=opener)
            self.fail(msg("o{name} {closer} without o{name} {opener} (open: o{top} {keyword})",
                          top=stack[-1][1], keyword=stack[-1][0], **said) if stack
                      else msg("o{name} {closer} without o{name} {opener}", **said), b)
            return None
        return stack.pop()

    def _o_sub(self, stack, i, b) -> None:
        if any(k == "sub" for k, *_ in stack):
            self.fail(msg("o{name} sub inside another sub", name=b.oname), b)
        if b.oname in self.subs:
            self.fail(msg("o{name} sub is defined twice", name=b.oname), b)
        self.subs.setdefault(b.oname, i)
        self._open(stack, i, b)

    def _o_endsub(self, stack, i, b) -> None:
        opened = self._close(stack, i, b, "sub", "endsub")
        if opened:
            self.jump[opened[2]] = i + 1

    def _o_if(self, stack, i, b) -> None:
        self._open(stack, i, b)

    def _o_elseif(self, stack, i, b) -> None:
        if not stack or stack[-1][0] != "if" or stack[-1][1] != b.oname:
            self.fail(msg("o{name} {keyword} without o{name} if", name=b.oname, keyword=b.keyword), b)

            return
        stack[-1][3].append(i)

    _o_else = _o_elseif

    def _o_endif(self, stack, i, b) -> None:
        opened = self._close(stack, i, b, "if", "endif")
        if not opened:
            return
        branches = opened[3]
        for here, nxt in zip(branches, branches[1:] + [i], strict=True):
            self.jump[here] = nxt  # a false test goes to the next branch
        for here in branches[1:]:
            self.back[here] = i + 1  # the end of a taken branch goes past endif

    def _o_while(self, stack, i, b) -> None:
        if stack and stack[-1][0] == "do" and stack[-1][1] == b.oname:
            _, _, head, _ = stack.pop()
            self.back[i] = head + 1  # do ... while [c]: true goes back into the body
            self.jump[head] = i + 1
            b.keyword = "do-while"  # the walker's handler for the end of a do loop
            return
        self._open(stack, i, b)

    def _o_endwhile(self, stack, i, b) -> None:
        opened = self._close(stack, i, b, "while", "endwhile")
        if opened:
            self.jump[opened[2]], self.back[i] = i + 1, opened[2]

    _o_do = _o_if

    def _o_repeat(self, stack, i, b) -> None:
        self._open(stack, i, b)

    def _o_endrepeat(self, stack, i, b) -> None:
        opened = self._close(stack, i, b, "repeat", "endrepeat")
        if opened:
            self.jump[opened[2]], self.back[i] = i + 1, opened[2]

    def _o_break(self, stack, i, b) -> None:
        self._loop_exit(stack, i, b)

    _o_continue = _o_break

    def _loop_exit(self, stack, i, b) -> None:
        loop = next((s for s in reversed(stack) if s[0] in LOOP_HEADS and s[1] == b.oname), None)
        if loop is None:
            self.fail(msg("o{name} {keyword} outside a loop o{name}", name=b.oname, keyword=b.keyword), b)
            return
        self.back[i] = loop[2]  # resolved by the walker: the loop head's exit or test

    def _o_return(self, stack, i, b) -> None:
        """Inside any subroutine definition; its o-word may name another (an ``if`` around
        it), as rs274ngc allows: it leaves the subroutine it is in."""
        if not any(k == "sub" for k, *_ in stack):
            self.fail(msg("o{name} return outside a subroutine definition", name=b.oname), b)

