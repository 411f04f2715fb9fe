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

import threading
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from app.profile import MachineProfile

from . import bulk, checks, normalize, runner
from .diagnostics import ERROR, WARNING, Diagnostic, Report
from .limits import program_checks
from .moves import moves_of
from .ops import OpBuffer, Ops
from .reading import SourceError, clean_bytes, clean_text, read_source, text_problem
from .render import render
from .source import Lines
from .toolpath import Toolpath, build


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

    def __repr__(self) -> str:
        return (f"Program({self.name!r}, {len(self.lines)} lines, {len(self.toolpath)} moves, "
                f"{len(self.errors)} errors, {len(self.warnings)} warnings)")

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
            self._render = render(self.ops, self.plan.count, self.plan.chords, tol, rpm)
        return self._render

    @property
    def device_lines(self) -> list[str]:
        """The program in the machine's dialect, one string per line."""
        return self._rendered()[0]

    @cached_property
    def line_map(self) -> np.ndarray:
        """Device index -> 1-based source line (known without rendering the lines)."""
        return np.repeat(self.ops.line, self.plan.count)

    @property
    def device_count(self) -> int:
        """Number of device lines, known without rendering them."""
        return self.plan.total

    @property
    def pauses(self) -> list[tuple[int, str]]:
        """(device index to pause before, message) for M0, M1 and tool changes."""
        return self._rendered()[2]

    @cached_property
    def moves(self) -> list[dict]:
        """The interpreted motion in the ``cnc-gcode moves`` JSON format."""
        return moves_of(self.ops)


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


def _interpret(lines: Lines, data: list[bytes], name: str, profile: MachineProfile) -> Program:
    """Interpret ``lines``; ``data`` holds their bytes, handed over (emptied) to free them early."""
    raw = data.pop()
    n = len(lines)  # reuse the chunks Lines already counted; otherwise scan makes its own
    report = Report()
    buffer = OpBuffer()
    interpreter = runner.Runner(lines, buffer, report)
    for scan, ready in bulk.scan_stream(raw, n, lines.chunks or None):  # interpret as lines come
        interpreter.advance(scan, ready)
    del raw, scan
    interpreter.finish()
    ops = buffer.finish()
    del buffer
    ops.starts()  # computed once, before two threads read it
    checking = _in_thread(checks.run, ops, profile, lines, report)  # numpy lets both run at once
    the_plan = normalize.plan(ops, profile.motion.arc_tolerance_mm)
    toolpath = build(ops, the_plan.first, profile)
    checking.join()
    program_checks(toolpath, profile, report)
    return Program(name, lines, report.finish(), ops, toolpath, profile, the_plan)


class _in_thread(threading.Thread):
    """``fn(*args)`` on a thread; ``join()`` re-raises what it raised."""

    def __init__(self, fn, *args):
        super().__init__(name="gcode-checks", daemon=True)
        self._call, self._error = (fn, args), None
        self.start()

    def run(self) -> None:
        fn, args = self._call
        try:
            fn(*args)
        except BaseException as exc:  # handed to the joining thread
            self._error = exc

    def join(self, timeout: float | None = None) -> None:
        super().join(timeout)
        if self._error is not None:
            raise self._error


def load_text(text: str, name: str = "<text>", profile: MachineProfile | None = None) -> Program:
    """Interpret G-code ``text``; errors and warnings are in the result, never raised."""
    profile = profile or MachineProfile()
    if "\x00" in text:
        return _empty(name, "not a text file (it contains NUL bytes)", profile)
    text = clean_text(text)
    data = [text.encode("utf-8", "replace")]  # a \r is a space to the fast path
    return _interpret(Lines(_split(text)), data, name, profile)


def load(path: str | Path, profile: MachineProfile | None = None) -> Program:
    """Read and interpret a G-code file; unreadable or non-UTF-8 files give an error."""
    path = Path(path)
    profile = profile or MachineProfile()
    try:
        raw = clean_bytes(read_source(path))
    except SourceError as exc:
        return _empty(str(path), str(exc), profile)
    problem = text_problem(raw)
    if problem:
        return _empty(str(path), problem, profile)
    lines = Lines(data=raw)  # split on first use, not here
    data = [raw]  # valid UTF-8: the bytes the fast path reads
    del raw
    return _interpret(lines, data, str(path), profile)
