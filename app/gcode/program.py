"""Loading a program: text -> interpreted rows -> diagnostics, device lines, Toolpath.

``load(path)`` and ``load_text(text, name)`` never raise for bad input: unreadable,
non-regular, oversized, non-UTF-8 or binary files give a ``Program`` with one error
(``reading.py``); a UTF-8 byte-order mark is skipped, CR-only line ends read as LF; a file with errors loads
as far as it can (refused lines change nothing), so every error is listed at once.
Lines are physical lines split at ``\\n`` (a ``\\r`` before it is dropped).
``source_lines`` (of a file), ``device_lines``, ``pauses`` and ``moves`` are computed
on first use; the number of device lines, ``line_map`` and the device index of each
move (``toolpath.device_index``) are known at once.
"""

from __future__ import annotations

import contextlib
import threading
from dataclasses import dataclass, field
from functools import cached_property, partial
from pathlib import Path

import numpy as np

from app.i18n import msg
from app.profile import MachineProfile

from . import bulk, checks, expanding, normalize, runner, sniff
from . import start as job_start
from .diagnostics import ERROR, WARNING, Diagnostic, Report
from .estimate import Estimate, estimate
from .estimate_lines import EventLines
from .heap import give_back_free_memory
from .limits import program_checks
from .moves import moves_of
from .offsets import ACTIVE_SYSTEM, system_param
from .ops import CappedBuffer, Enough, OpBuffer, Ops
from .percent import abort_line, abort_message, percent_lines, report_tail
from .reading import BOM, SourceError, clean_bytes, clean_text, read_source, text_problem
from .render import render
from .source import Lines
from .start import StartInfo
from .state import State
from .threads import each_on
from .toolpath import Toolpath, build, build_in_place, closable, timed_before_closing

TRIM_BYTES = 8 << 20  # after the scan of a file this big, free heap pages go back to the system
LATER_CHECKS_ROWS = 200_000  # a program this long may leave its checks for after its first picture
FOLD_BYTES = 1 << 20  # a program this big is read on the fast path before it is known to be plain
ORIGIN = (0.0, 0.0, 0.0)  # where rs274 reads a program from; ``from_start`` gives the machine's


@dataclass(repr=False)
class Program:
    """A loaded G-code program (see the module docstring)."""

    name: str
    lines: Lines
    diagnostics: list[Diagnostic]
    ops: Ops
    toolpath: Toolpath
    profile: MachineProfile
    plan: normalize.Plan
    _render: tuple | None = field(default=None, repr=False)
    envelope: checks.Envelope | None = field(default=None, repr=False)  # for checks.preflight
    start: StartInfo = field(default_factory=StartInfo)  # where the job starts (start.py)
    _again: object = field(default=None, repr=False)  # origin -> the program read from there
    _planning: _in_thread | None = field(default=None, repr=False)  # ``planned`` under way (``plan_ahead``)
    _checks: object = field(default=None, repr=False)  # the checks left for later (``later_checks``)

    def from_start(self, position) -> Program:
        """The program as a job from ``position`` (work mm, as the machine reports it):
        itself, or read again from there when a move is relative to where the machine
        stands (``start.relative``: G91 first moves, arcs or cycles from the start)."""
        if self._again is None or not self.start.needs_reading_from(position):
            return self
        return self._again(tuple(float(v) for v in position))

    def __repr__(self) -> str:
        return (f"Program({self.name!r}, {len(self.lines)} lines, {len(self.toolpath)} moves, "
                f"{len(self.errors)} errors, {len(self.warnings)} warnings)")

    @property
    def checks_pending(self) -> bool:
        """True while the checks a load left for later (``load(later_checks=True)``) have
        not run: ``diagnostics`` lacks their warnings, and ``envelope`` is None."""
        return self._checks is not None

    def finish_checks(self) -> None:
        """Run the checks the load left for later (the travel, feed 0 and spindle speed
        warnings): they join ``diagnostics``, in line order, and ``envelope`` is set.
        Nothing when none are left; one thread at a time. Should they raise, they stay
        pending (the program is not known to stay in the travel)."""
        pending = self._checks
        if pending is not None:
            self.envelope, self.diagnostics = pending()
            self._checks = None

    @property
    def source_lines(self) -> list[str]:
        """The program's lines as read (split on first use)."""
        return self.lines.as_list()

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == ERROR]

    @property
    def warnings(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity == WARNING]

    def _rendered(self) -> tuple:
        if self._render is None:
            tol = self.profile.motion.arc_tolerance_mm
            rpm = self.profile.spindle.no_load_rpm
            free = self.start.free_rows(self.ops)
            self._render = render(self.ops, self.plan.count, self.plan.chords, tol, rpm, free)
        return self._render

    @property
    def device_lines(self) -> list[str]:
        """The program in the machine's dialect, one string per line."""
        return self._rendered()[0]

    @cached_property
    def line_map(self) -> np.ndarray:
        """Device index -> 1-based line of the main program (known without rendering)."""
        return np.repeat(self.ops.main_lines(), self.plan.count)

    @property
    def device_count(self) -> int:
        """Number of device lines, known without rendering them."""
        return self.plan.total

    @property
    def pauses(self) -> list[tuple[int, str]]:
        """(device index of the stop line, message) for M0, M1 and tool changes."""
        return self._rendered()[2]

    def context_at(self, device_index: int) -> tuple[str, int]:
        """(subprogram, loop pass) that device line ``device_index`` comes from: ``("", 0)``
        for the main program outside loops (and for every line of a plain program)."""
        source = self.ops.source
        if source is None or not len(self.ops):
            return "", 0
        row = int(np.searchsorted(self.plan.first, device_index, "right")) - 1
        row = min(max(row, 0), len(self.ops) - 1)
        return source.names[int(source.context[row])], int(source.iteration[row])

    def moves_per_line(self) -> np.ndarray:
        """Number of moves each 1-based line of the main program produced (index 0 unused)."""
        return np.bincount(self.toolpath.source_line, minlength=len(self.lines) + 1)

    @cached_property
    def planned(self) -> Estimate:
        """The machine planner's time (``estimate.py``; about 0.5 s for a million lines, so
        in the background; the device lines need not be rendered). From then on the
        toolpath's ``time``, and with it ``estimated_time`` and the progress per line, are
        the planner's figures. Waits for the thread of a load with ``plan_ahead``."""
        planning, self._planning = self._planning, None
        est = planning.join() if planning is not None else _estimate(self.toolpath, self.ops, self.plan,
                                                                      self.profile)
        self.toolpath.time = est.row_seconds
        return est

    @property
    def planned_if_ready(self) -> Estimate | None:
        """``planned`` once something has computed it (or its thread has finished), else
        None (never computes it, never waits)."""
        if self._planning is not None and not self._planning.is_alive():
            return self.planned
        return self.__dict__.get("planned")

    @cached_property
    def moves(self) -> list[dict]:
        """The interpreted motion in the ``cnc-gcode moves`` JSON format."""
        return moves_of(self.ops)


def _estimate(toolpath: Toolpath, ops: Ops, the_plan: normalize.Plan, profile: MachineProfile,
              spare: threading.Event | None = None) -> Estimate:
    """The planner's estimate; ``spare``: a second thread works on its blocks too once it is
    set (a one-shot check: the checks beside it have finished and left a core idle). The
    window's runs on one thread, beside its redraws."""
    return estimate(toolpath, EventLines(ops, the_plan), profile, plan=the_plan,
                    threads=1 if spare is None else 2, second=spare)


def _checked(ops: Ops, profile: MachineProfile, lines: Lines, report: Report,
             toolpath: Toolpath) -> checks.Envelope:
    """``checks.run``, then the toolpath's bounds (for a caller that reads them at once:
    worked out beside the planner's estimate, which takes longer)."""
    envelope = checks.run(ops, profile, lines, report)
    toolpath.bounds  # noqa: B018 (a cached property)
    return envelope


def _later_checks(ops: Ops, profile: MachineProfile, lines: Lines, report: Report):
    """``Program._checks``: (envelope, every diagnostic) once ``checks.run`` has added its
    warnings to the load's ``report``."""
    envelope = checks.run(ops, profile, lines, report)
    return envelope, report.finish()


def _origin(path: Path, read: bytes, raw: bytes) -> tuple[str, int] | None:
    """(path, offset) of ``raw`` (``clean_bytes`` of ``read``, the file's bytes) in the
    file when it is the file's bytes from there on: as read, or without its byte-order
    mark; None when line ends were changed."""
    if raw is read:
        return str(path), 0
    if len(read) - len(raw) == len(BOM) and read.startswith(BOM) and memoryview(read)[len(BOM):] == raw:
        return str(path), len(BOM)  # (CR-only line ends made LF keep the length)
    return None


def _split(text: str) -> list[str]:
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if "\r" in text:
        lines = [line[:-1] if line.endswith("\r") else line for line in lines]
    return lines


def _empty(name: str, message: str, profile: MachineProfile) -> Program:
    program = load_text("", name, profile)
    program.diagnostics = [Diagnostic(1, 0, ERROR, message)]
    return program


def _start_state(profile: MachineProfile, tools: dict | None, block_delete: bool = False,
                 systems=None, origin=ORIGIN) -> State:
    """The interpreter's state before the first line: LinuxCNC's, in G54, with the tool table
    and the operator's block delete switch, at ``origin`` (work mm).

    ``systems``: the machine's work systems, ``(active, {system: (x, y, z)})`` with
    systems 1-6 for G54-G59 in machine mm; the program then starts in the active one,
    and each other system's offset is its difference from the active one (the frame's
    zero is the active system's work zero), so a program's G55 moves where the
    machine's G55 is."""
    start = State(pos=[float(v) for v in origin], tools=dict(tools or {}),
                  arc_tolerance=profile.motion.arc_tolerance_mm, block_delete=block_delete)
    active = 1
    if systems is not None:
        active, rows = systems
        for system, row in rows.items():
            for axis in range(3):
                start.params.set(system_param(system, axis), row[axis] - rows[active][axis])
        start.offsets.system = active
    start.params.set(ACTIVE_SYSTEM, active)  # G54 unless the machine has another, as LinuxCNC starts
    return start


def _plain(lines: Lines, data: list[bytes], start: State, report: Report, stop: int,
           buffer: OpBuffer | None = None, unsure: bool = False) -> tuple[Ops, int]:
    """The fast path over the lines before index ``stop``; ``data`` holds the bytes,
    handed over (emptied) to free them early. (ops, line of M2/M30 or 0). ``unsure``: the
    program may need the expander: each window of the scan says whether it shows it does
    not (``Scan.plain``), else ``sniff.needs_expander`` of the whole file decides, once,
    before a line of that window is interpreted; ``sniff.NeedsExpander`` when it does."""
    raw = data.pop()
    n = len(lines)  # reuse the chunks Lines already counted; otherwise scan makes its own
    buffer = OpBuffer(reserve=n) if buffer is None else buffer  # about a row a line
    interpreter = runner.Runner(lines, buffer, report, start)
    stream = bulk.scan_stream(raw, n, lines.chunks or None, origin=lines.origin)
    with contextlib.closing(stream):  # (a forked child stops at once)
        for scan, ready in stream:  # interpret as lines come
            if unsure and not scan.plain:
                if sniff.needs_expander(raw):
                    raise sniff.NeedsExpander
                unsure = False
            interpreter.advance(scan, min(ready, stop))
    del raw, scan
    ended = interpreter.finish().ended
    return buffer.finish(), ended


def _fast(lines: Lines, data: list[bytes], state_at, origin, stop: int,
          unsure: bool) -> tuple[Ops, int, StartInfo, Report]:
    """``_interpret``'s fast path: (ops, line of M2/M30 or 0, where the job starts, report);
    ``state_at(origin)``: the start state; ``unsure`` as for ``_plain`` (``sniff.NeedsExpander``
    then leaves ``data`` as it was)."""
    report, start = Report(), state_at(origin)
    aborted, text = abort_line(data[0], partial(lines.line_of, data[0]))  # the expander stops at an
    if aborted and aborted <= stop:  # ABORT when its flow reaches it; here it ends the program
        stop = aborted - 1
        report.error(aborted, 0, abort_message(text))
    where = job_start.probe(_plain_reader(data[0], lines, stop, state_at), origin)  # before the bytes
    # are handed over
    big = len(data[0]) >= TRIM_BYTES
    raw = data[0]
    try:
        ops, ended = _plain(lines, data, start, report, stop, unsure=unsure)
    except sniff.NeedsExpander:
        data[:] = [raw]
        raise
    del raw
    if big:
        give_back_free_memory()  # the scan's many chunk-sized temporaries
    return ops, ended, where, report


def _line_end(raw: bytes, count: int) -> int:
    """Offset just past the ``count``-th newline of ``raw`` (its length if fewer)."""
    pos = -1
    for _ in range(count):
        pos = raw.find(b"\n", pos + 1)
        if pos < 0:
            return len(raw)
    return pos + 1


def _plain_reader(raw: bytes, lines: Lines, stop: int, state_at):
    """``start.Reader`` of a plain program: its first lines read from a given origin;
    ``stop`` as for the whole program, ``state_at(origin)`` its start state."""

    def read(origin, limit: int) -> tuple[Ops, bool]:
        report = Report()
        cut = _line_end(raw, min(limit, stop))
        buffer = CappedBuffer(cap=limit)  # a line may make many rows (chords of a spline)
        try:
            ops, _ = _plain(Lines(data=raw[:cut]), [raw[:cut]], state_at(origin), report, min(limit, stop),
                            buffer)
        except Enough:
            return buffer.finish(), False
        return ops, cut >= len(raw) or report.has_errors()  # nothing after an error runs

    return read


def _interpret(lines: Lines, data: list[bytes], name: str, profile: MachineProfile,
               tools: dict | None = None, folder: Path | None = None, block_delete: bool = False,
               systems=None, origin=ORIGIN, plan_ahead: bool = False, later_checks: bool = False) -> Program:
    """Interpret ``lines`` from ``origin`` (work mm): the expander when the bytes in
    ``data`` need it, else the fast path; ``plan_ahead``: the planner's estimate starts on
    a thread as soon as the toolpath is there (``Program.planned`` then waits for it), and
    the checks wait for the toolpath and run beside it (less memory at the peak; without
    it they run beside the plan and the toolpath: the window's load returns sooner);
    ``later_checks`` as for ``load``.
    A program of ``FOLD_BYTES`` or more is not sniffed first: its scan tells on the way
    (``_plain``), and it starts again on the expander's path if it needs it."""
    settings = (block_delete, systems)
    state_at = partial(_start_state, profile, tools, *settings)
    line_of = partial(lines.line_of, data[0])  # from the chunk table: no count of every newline
    percent = percent_lines(data[0], line_of)
    closing = percent[1]
    whole = closing - 1 if closing else len(lines)  # nothing after the closing % runs
    unsure = len(data[0]) >= FOLD_BYTES
    expand = not unsure and sniff.needs_expander(data[0])
    if not expand:
        try:
            ops, ended, where, report = _fast(lines, data, state_at, origin, whole, unsure)
        except sniff.NeedsExpander:
            expand = True
    if expand:
        data.clear()
        ops, ended, where, report = expanding.interpret(lines, name, folder, whole, state_at, origin)
    report_tail(lines, percent, ended, report)
    ops.origin = tuple(float(v) for v in origin)
    ops.starts()  # computed once, before the threads read it
    later = later_checks and len(ops) >= LATER_CHECKS_ROWS
    early = None if plan_ahead or later else _in_thread(checks.run, ops, profile, lines, report)  # the
    # window's small programs: beside the plan and the toolpath (numpy lets them run at once)
    normalizing = _in_thread(normalize.plan, ops, profile.motion.arc_tolerance_mm, 1 if plan_ahead else 2,
                             name="gcode-normalize")  # (check's thread works out the moves' timing meanwhile)
    timing = each_on(2, normalizing.done) if plan_ahead else None  # a second thread once the plan is done
    closing = closable(ops)
    if closing is not None:  # the moves closed up in the rows' own columns, once the plan and the
        # checks have read them as they are: no copy of the positions (check's estimate reads
        # the moves' timing first: worked out here, while this thread would wait for the plan)
        timed = timed_before_closing(ops, closing, profile, timing) if plan_ahead else None
        the_plan = normalizing.join()
        envelope = early.join() if early is not None else None
        toolpath = build_in_place(ops, closing, the_plan.first, profile, timed)
    else:
        toolpath = build(ops, lambda: normalizing.join().first, profile, timing)
        the_plan = normalizing.join()
        envelope = early.join() if early is not None else None
        ops.hand_over(toolpath)  # the moves' positions kept once, by the Toolpath
    planning = None
    if plan_ahead:  # cnc-gcode check: the checks, on the toolpath, beside the planner's estimate
        checking = _in_thread(_checked, ops, profile, lines, report, toolpath)
        planning = _in_thread(_estimate, toolpath, ops, the_plan, profile, checking.done,  # (then a
                              name="gcode-plan")  # core for the estimate's second thread)
        envelope = checking.join()
    program_checks(toolpath, profile, report)
    ops.forget_starts()  # the Toolpath has the moves' starts

    def again(position) -> Program:
        return _interpret(lines, [lines.encoded()], name, profile, tools, folder, *settings, position)

    return Program(name, lines, report.finish(), ops, toolpath, profile, the_plan, envelope=envelope,
                   start=where, _again=again, _planning=planning,
                   _checks=partial(_later_checks, ops, profile, lines, report) if later else None)


class _in_thread(threading.Thread):
    """``fn(*args)`` on a thread; ``join()`` returns its value or re-raises what it raised;
    ``done`` is set when it has ended, either way (a core is free then)."""

    def __init__(self, fn, *args, name: str = "gcode-checks"):
        super().__init__(name=name, daemon=True)
        self._call, self._error, self._value = (fn, args), None, None
        self.done = threading.Event()
        self.start()

    def run(self) -> None:
        fn, args = self._call
        try:
            self._value = fn(*args)
        except BaseException as exc:  # handed to the joining thread
            self._error = exc
        finally:
            self.done.set()

    def join(self, timeout: float | None = None):
        super().join(timeout)
        if self._error is not None:
            raise self._error
        return self._value


def load_text(text: str, name: str = "<text>", profile: MachineProfile | None = None,
              tools: dict | None = None, folder: Path | None = None, block_delete: bool = False,
              systems=None) -> Program:
    """Interpret G-code ``text``; errors and warnings are in the result, never raised.
    ``tools`` is the tool table (``tools.Tool`` by number) for T, G43 H and G41 D;
    ``folder`` is where its subprogram files are looked for (none when ``None``);
    ``block_delete``: the operator's switch (on: lines starting with ``/`` are skipped;
    off, the default as on LinuxCNC and Fanuc controls: they run); ``systems`` the
    machine's work systems (``_start_state``)."""
    profile = profile or MachineProfile()
    if "\x00" in text:
        return _empty(name, msg("not a text file (it contains NUL bytes)"), profile)
    text = clean_text(text)
    data = [text.encode("utf-8", "replace")]  # a \r is a space to the fast path
    return _interpret(Lines(_split(text)), data, name, profile, tools, folder, block_delete, systems)


def load(path: str | Path, profile: MachineProfile | None = None, tools: dict | None = None,
         block_delete: bool = False, systems=None, plan_ahead: bool = False,
         later_checks: bool = False) -> Program:
    """Read and interpret a G-code file; unreadable or non-UTF-8 files give an error.
    ``tools``, ``block_delete`` and ``systems`` as for ``load_text``; subprogram files are
    looked for in the file's folder. ``plan_ahead``: start the planner's estimate on a
    thread at once, beside the last checks (for a caller that will ask for it at once,
    such as ``cnc-gcode check``; the window asks only after its first picture).
    ``later_checks``: a program of LATER_CHECKS_ROWS rows or more is returned before its
    travel, feed and spindle speed checks, which ``Program.finish_checks`` then runs (the
    window: after the first picture, which does not need them)."""
    path = Path(path)
    profile = profile or MachineProfile()
    try:
        read = read_source(path)
    except SourceError as exc:
        return _empty(str(path), exc.args[0], profile)
    raw = clean_bytes(read)
    origin = _origin(path, read, raw)
    del read  # (a copy without its byte-order mark: the file's bytes go at once)
    problem = text_problem(raw)
    if problem:
        return _empty(str(path), problem, profile)
    lines = Lines(data=raw, origin=origin)  # split on first use, not here
    data = [raw]  # valid UTF-8: the bytes the fast path reads
    del raw
    return _interpret(lines, data, str(path), profile, tools, path.parent, block_delete, systems,
                      plan_ahead=plan_ahead, later_checks=later_checks)
