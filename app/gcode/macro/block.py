"""One source line compiled once into a ``Block`` the walker runs as often as needed.

Kinds: ``WORDS`` (G-code words whose values are functions, and assignments applied
after the line is read), ``SKIP`` (empty, ``%``, block delete with the switch on),
``PLAIN`` (a line of a long run of simple lines, which the fast path reads: ``plain.py``;
one block shared by the run), ``OWORD`` (a LinuxCNC o-word statement: ``keyword``,
o-name, optional value functions), and the
Fanuc macro B statements ``PROGRAM`` (``O1234``), ``IF_GOTO``, ``IF_THEN``, ``GOTO``,
``WHILE`` (``WHILE [c] DO m``), ``DO`` (``DO m``) and ``END`` (``END m``). A Fanuc
``N`` number is the block's ``label``. ``compile_line`` raises ``MacroError`` with
the line and column of anything it cannot read.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from app.i18n import msg

from .batch import compile_rows, fast_row_code, row_maker, simple_shape
from .errors import MacroError
from .expr import Reader, compile_code, compile_codes, compile_locals, constant
from .stores import compile_stores
from .text import squeeze

WORDS, SKIP, OWORD, PROGRAM, IF_GOTO, IF_THEN, GOTO, WHILE, DO, END, PLAIN = range(11)
O_KEYWORDS = ("sub", "endsub", "call", "return", "if", "elseif", "else", "endif", "while",
              "endwhile", "do", "repeat", "endrepeat", "break", "continue")
WITH_VALUE = {"if", "elseif", "while", "repeat"}  # keywords that need one [value]
MAY_VALUE = {"return", "endsub"}  # keywords that may carry one [value]
LETTERS = set("abcdefghijklmnpqrstuvwxyz@^")  # @ ^: LinuxCNC's polar radius and angle
_COMMENT = re.compile(r"\(([^()]*)\)")
_ABORT = re.compile(r"(?i)\(\s*abort\s*,([^)]*)\)")
_CALLS = {("M", 98.0), ("M", 99.0), ("G", 65.0)}  # a word's letter ('o' is a statement)


@dataclass(slots=True)
class Word:
    """A G-code word: letter (upper case), 1-based column, value code, bare #param?"""

    letter: str
    column: int
    code: str
    bare: bool  # a lone parameter: a vacant one drops the word (Fanuc)


@dataclass(slots=True, eq=False)
class Block:
    """A compiled line (see the module docstring)."""

    line: int
    kind: int
    words: list[Word] = field(default_factory=list)
    sets: list[tuple] = field(default_factory=list)  # (target: int, name or code, value code, column)
    label: int | None = None
    keyword: str = ""
    oname: str = ""
    onumber: object = None  # o[expr] call: the number's code, then its compiled function
    args: list = field(default_factory=list)  # codes, then compiled functions ``fn(S)``
    number: int = 0  # O program number, GOTO label, DO/END loop number
    column: int = 0
    skip: str = ""
    values: object = None  # fn(S) -> (word values..., set values..., computed set targets...)
    targets: list = field(default_factory=list)  # per set: a number, a name, or (index into values,)
    simple: bool = False  # only G X Y Z I J F words, each once: may go to the fast path
    row: object = None  # for a simple block: values -> a batch row (batch.row_maker)
    fast: object = None  # for a simple block without assignments: scope -> a batch row, or None
    fast_code: str | None = None  # the code of ``fast`` (runs.py joins those of a run)
    reads_machine: bool = False  # reads #5000 and up, a computed number or a predefined #<_name>
    assigns: list = field(default_factory=list)  # (target, index of its value)
    store: object = None  # fn(scope, values) applying ``assigns`` (frame.compile_stores)
    vacant: bool = False  # Fanuc: a parameter may be vacant
    run: object = None  # the walker's handler for this block (walker.bind)
    call: Word | None = None  # Fanuc: the M98/M99/G65 word of the line (a constant)
    call_only: bool = False  # Fanuc: the line is only that call and its P/L/arguments
    context: str = ""  # LinuxCNC call: the trace's name of the subroutine it runs
    plan: tuple | None = None  # Fanuc G65 line: where its P, L and arguments are (fanuc.g65_plan)
    deleted: bool = False  # the line starts with "/" (block delete)
    abort: str | None = None  # the text of an (ABORT, text) comment: the walk stops there
    comment: str = ""  # Fanuc: the text of the line's first comment (a #3000 alarm's message)
    called: dict = field(default_factory=dict)  # o-word call: caller's file id -> (unit, start, file id)
    specialized: bool = False  # a call: its handler was made for the one program it calls (leaf.direct)
    end: int = 0  # PLAIN: the index past the chunk's last line (plain.py)

    def finish(self) -> Block:
        """Compile the codes of the line into functions (done once)."""
        codes = [w.code for w in self.words] + [value for _, value, _ in self.sets]
        self.targets = []
        for target, _, _ in self.sets:
            if isinstance(target, str) and target.startswith("_index("):  # a computed number
                self.targets.append((len(codes),))
                codes.append(target)
            else:
                self.targets.append(target)
        self.values = _lazy(self, "values", compile_codes, codes) if codes else None
        self.simple = self.kind == WORDS and simple_shape([w.letter for w in self.words])
        if self.simple:
            letters = [w.letter for w in self.words]
            self.row = row_maker(letters, self.vacant, self.line)
            if not self.sets:
                self.fast_code = fast_row_code(letters, [w.code for w in self.words], self.vacant, self.line)
                self.fast = _lazy(self, "fast", compile_rows, [self.fast_code]) if self.fast_code else None
        if self.vacant and self.kind == WORDS:  # Fanuc: a call line read without building words
            self.call = next((w for w in self.words if (w.letter, constant(w.code)) in _CALLS), None)
            self.call_only = self.call is not None and (
                self.call.letter == "G" or all(w.letter in "MPL" for w in self.words))
        self.reads_machine = any("S.num(" in code or "S.system(" in code for code in codes)
        n = len(self.words)
        self.assigns = [(target, n + i) for i, target in enumerate(self.targets)]
        if self.assigns:
            self.store = compile_stores(self.assigns, self.vacant, self.comment)
        if self.kind == OWORD and self.keyword == "call":  # all arguments in one function
            self.values = compile_locals(self.args)
            self.context = f"o{self.oname}" if self.oname.isdigit() else f"o<{self.oname}>"
        self.args = [compile_code(a) for a in self.args]
        if self.onumber is not None:
            self.onumber = compile_code(self.onumber)
            self.context = "o[]"
        return self


def _lazy(owner, attr: str, compile_, source):
    """A function that compiles ``source`` on its first call, puts the result in
    ``owner.attr`` and runs it: a line inside a run of moves, or never reached, is never
    compiled (a long program compiles what it runs)."""
    def first_call(*args):
        fn = compile_(source)
        setattr(owner, attr, fn)
        return fn(*args)

    return first_call


def _integer(reader: Reader, what: str) -> int:
    at = reader.pos
    if not reader.peek().isdigit():
        raise reader.error(msg("{what} needs a whole number", what=what))
    v = reader.number()
    if v != int(v):
        raise reader.error(msg("{what} needs a whole number", what=what), at)
    return int(v)


def _oname(reader: Reader, block: Block) -> str:
    reader.expect("o", "")
    if reader.peek() == "<":
        reader.pos += 1
        return reader.name()
    if reader.peek() == "[":  # o[expression]: a number computed when the statement runs
        block.onumber = reader.value()
        return "[]"
    return str(_integer(reader, msg("an o-word")))


def _oword(reader: Reader, block: Block) -> Block:
    block.kind, block.column = OWORD, reader.sq.column(reader.pos)
    block.oname = _oname(reader, block)
    block.keyword = next((k for k in sorted(O_KEYWORDS, key=len, reverse=True)
                          if reader.text.startswith(k, reader.pos)), "")
    if not block.keyword:
        rest = reader.text[reader.pos:]
        if not rest and block.oname.isdigit():  # a Fanuc program number line
            block.kind, block.number = PROGRAM, int(block.oname)
            return block
        raise reader.error(msg("unknown o-word statement {rest!r}", rest=rest.upper()) if rest
                           else msg("o-word without a keyword"))
    reader.pos += len(block.keyword)
    while reader.peek() == "[":
        block.args.append(reader.value())
    if block.keyword in WITH_VALUE and len(block.args) != 1:
        raise reader.error(msg("'{keyword}' needs one [value]", keyword=block.keyword))
    if block.keyword in MAY_VALUE and len(block.args) > 1:
        raise reader.error(msg("'{keyword}' takes at most one [value]", keyword=block.keyword))
    if block.keyword not in WITH_VALUE | MAY_VALUE | {"call"} and block.args:
        raise reader.error(msg("'{keyword}' takes no value", keyword=block.keyword))
    if block.keyword == "call" and len(block.args) > 30:
        raise reader.error(msg("a call takes at most 30 arguments"))
    if block.onumber is not None and block.keyword != "call":
        raise reader.error(msg("only a call may compute its o-word number (o[...] call)"), block.column)
    if not reader.at_end():
        raise reader.error(msg("unexpected {rest!r} after the o-word statement",
                               rest=reader.text[reader.pos:].upper()))
    return block


def _assignment(reader: Reader) -> tuple:
    column = reader.sq.column(reader.pos)
    target = reader.target()
    reader.expect("=", msg("after the parameter to set"))
    value = reader.expression() if reader.fanuc else reader.value()
    return target, value, column


def _words(reader: Reader, block: Block) -> Block:
    while not reader.at_end():
        c = reader.peek()
        if c == "#":
            block.sets.append(_assignment(reader))
        elif c in LETTERS:
            column = reader.sq.column(reader.pos)
            reader.pos += 1
            bare = reader.peek() == "#"
            block.words.append(Word(c.upper(), column, reader.value(), bare))
        else:
            raise reader.error(msg("unexpected character {char!r}", char=c))
    return block


def _fanuc(reader: Reader, block: Block) -> Block | None:
    """A Fanuc macro statement at ``reader.pos``, or None when the line holds none."""
    text, pos = reader.text, reader.pos
    block.column = reader.sq.column(pos)
    if text.startswith("if[", pos):
        reader.pos += 2
        block.args.append(reader.value())
        if text.startswith("goto", reader.pos):
            reader.pos += 4
            block.kind, block.args = IF_GOTO, [*block.args, reader.value()]
        elif text.startswith("then", reader.pos):
            reader.pos += 4
            block.kind = IF_THEN
            _words(reader, block)
            if block.words or not block.sets:
                raise reader.error(msg("IF [..] THEN takes assignments only (#i = value)"))
            return block
        else:
            raise reader.error(msg("IF [..] needs GOTO n or THEN #i = value"))
    elif text.startswith("goto", pos):
        reader.pos += 4
        block.kind, block.args = GOTO, [reader.value()]
    elif text.startswith("while[", pos):
        reader.pos += 5
        block.args.append(reader.value())
        reader.expect("d", "(WHILE [..] DO m)")
        reader.expect("o", "(WHILE [..] DO m)")
        block.kind, block.number = WHILE, _integer(reader, "DO")
    elif text.startswith("do", pos) and text[pos + 2:pos + 3].isdigit():
        reader.pos += 2
        block.kind, block.number = DO, _integer(reader, "DO")
    elif text.startswith("end", pos) and text[pos + 3:pos + 4].isdigit():
        reader.pos += 3
        block.kind, block.number = END, _integer(reader, "END")
    else:
        return None
    if not reader.at_end():
        raise reader.error(msg("unexpected {rest!r} at the end of the statement",
                               rest=reader.text[reader.pos:].upper()))
    return block


MAX_LINE = 255  # characters of a line (rs274ngc refuses longer ones: "Command too long")


def compile_line(line: str, line_no: int, fanuc: bool) -> Block:
    """The ``Block`` of one source line (``fanuc``: the dialect's assignment rule)."""
    if len(line) > MAX_LINE:
        raise MacroError(msg("the line is {length:,} characters long; the limit is {limit} (as LinuxCNC's)",
                             length=len(line), limit=MAX_LINE), line_no)
    block = _read_line(line, line_no, fanuc)
    block.vacant = fanuc
    if "(" in line:
        aborted = _ABORT.search(line)
        block.abort = aborted.group(1) if aborted else None
    if fanuc and "(" in line:
        found = _COMMENT.search(line)
        block.comment = found.group(1).strip() if found else ""
    try:
        return block.finish()
    except (SyntaxError, RecursionError, MemoryError):  # Python's own limits on one expression
        raise MacroError(msg("the line's expressions are too complex (too many operations)"),
                         line_no) from None


def _read_line(line: str, line_no: int, fanuc: bool) -> Block:
    sq = squeeze(line, line_no)
    block = Block(line_no, WORDS)
    text = sq.text
    if not text:
        block.kind = SKIP
        return block
    if text[0] == "%":
        if len(text) > 1:
            raise MacroError(msg("unexpected text after '%'"), line_no, sq.column(1))

        block.kind, block.skip = SKIP, "%"
        return block
    reader = Reader(sq, line_no, fanuc)
    if text[0] == "/":  # block delete: the rest is read; ``Unit`` skips it when the switch is on
        block.deleted, reader.pos = True, 1
    if text.startswith("n", reader.pos) and text[reader.pos + 1:reader.pos + 2].isdigit():
        reader.pos += 1
        block.label = _integer(reader, "N")
    if reader.peek() == "o":
        return _oword(reader, block)
    if fanuc and _fanuc(reader, block) is not None:
        return block
    return _words(reader, block)
