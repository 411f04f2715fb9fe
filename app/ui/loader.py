"""Loads a G-code file off the GUI thread: parse, normalise, toolpath, and the
preview's drawing model, then hands the result back with a queued signal.

What the first picture needs comes first: the toolpath and a preview model drawn with
the tolerance of the screen (half a pixel of the view the preview will fit; arcs need
far fewer chords than at 0.01 mm) with its level of detail for that view, while a
second thread works out what the window's summary reads (the exact bounds); ``loaded``
is emitted then, and the window paints the picture before it does anything else. The
rest waits until the window says it has shown the program (``shown()``, or
SHOW_WAIT_S), so it does not compete with the first picture for the interpreter: first
the travel, feed and spindle speed checks a big program left for later
(``load(later_checks=True)``: a tenth of a second or two for a million moves, and the
picture does not need them), then ``checked`` (its warnings are in the program now);
the model at the real tolerance with every level of detail, for zooming in (``refined``,
when the first one was coarser), then the device lines, for Start and Save to SD
(``prepared``). The rest runs niced, on this thread alone, and in pieces (chords
65,536 arcs at a time, device-line texts in slices), so a redraw never waits long for
the GIL behind one numpy call.

Anything that is not G-code ends in ``failed`` with a sentence for the operator: a
missing or unreadable file, a binary file, or text in which nothing could be run.
"""

from __future__ import annotations

import contextlib
import dataclasses
import os
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.gcode import workers
from app.i18n import localize
from app.ui.numbers import fill
from app.ui.preview.model import PreviewModel, screen_tolerance

SNIFF_BYTES = 4096
SHOW_WAIT_S = 3.0
BACKGROUND_NICE = 10
DEFAULT_VIEW = (900, 700)  # pixels, when the window did not say


@dataclass(frozen=True)
class LoadedProgram:
    path: Path
    program: object
    preview: PreviewModel
    load_s: float  # parse + normalise + toolpath
    model_s: float  # preview model


@dataclass(frozen=True)
class ReadAgain:
    """A program read again from the machine's position (``Program.from_start``) for the
    request ``token``: ``job`` (its device lines rendered), or ``error`` (a sentence)."""

    token: object
    program: object
    job: object = None
    error: str = ""


class ProgramLoader(QObject):
    loaded = Signal(object)  # LoadedProgram
    failed = Signal(str, str)  # path, message
    checked = Signal(object)  # LoadedProgram whose checks, left for after the picture, have run
    refined = Signal(object)  # LoadedProgram with the preview at the real tolerance, all levels built
    prepared = Signal(object)  # LoadedProgram whose device lines are rendered (Start is instant)
    read_again = Signal(object)  # ReadAgain: ``read_from``'s answer

    def __init__(self, parent=None, tolerance: float = 0.01):
        super().__init__(parent)
        self.tolerance = tolerance
        self.tools: dict = {}  # the tool table (app.gcode.tools), as the window last saved it
        self.block_delete = False  # the operator's switch: lines starting with "/" are skipped
        self.systems = None  # the machine's work systems (app/ui/dro.py), None until read
        self.busy = False
        self.view_size: tuple[float, float] | None = None  # the preview's, in pixels
        self._shown = threading.Event()
        workers.warm_up()  # the second core is ready before the first big file is opened

    def load(self, path: str | Path, wait: bool = False) -> None:
        """Load on a thread (``wait``: and join it; the rest then does not wait for ``shown``)."""
        self.busy = True
        self._shown.clear()
        args = (Path(path), self.view_size, not wait)
        thread = threading.Thread(target=self._run, args=args, name="gcode-load", daemon=True)
        thread.start()
        if wait:
            thread.join()

    def read_from(self, program, position, token) -> None:
        """``program.from_start(position)`` and its device lines on a thread of their own,
        the answer by ``read_again`` (a queued signal): the window stays responsive while a
        big relative-start program is read again from where the machine stands."""
        args = (program, tuple(float(v) for v in position), token)
        threading.Thread(target=self._read_again, args=args, name="gcode-read-again", daemon=True).start()

    def _read_again(self, program, position, token) -> None:
        try:
            job = program.from_start(position)
            job.device_lines  # noqa: B018 (rendered here, not on the GUI thread)
        except Exception as exc:  # a bug must not leave the operator waiting forever
            said = QCoreApplication.translate("Loader", "the program could not be read from the machine's "
                                                        "position: %1")
            self.read_again.emit(ReadAgain(token, program, error=fill(said, f"{type(exc).__name__}: {exc}")))
            return
        self.read_again.emit(ReadAgain(token, program, job))

    def shown(self) -> None:
        """The window has drawn the loaded program: the rest of the work may start."""
        self._shown.set()

    def _run(self, path: Path, view_size, defer: bool) -> None:
        try:
            result = load_program(path, self.tolerance, view_size, self.tools, self.block_delete,
                                  self.systems)
        except LoadError as exc:
            self.busy = False
            self.failed.emit(str(path), str(exc))
            return
        except Exception as exc:  # a bug must not leave the operator waiting forever
            self.busy = False
            self._failed(path, exc)
            return
        self.busy = False
        self.loaded.emit(result)
        if defer:
            self._shown.wait(SHOW_WAIT_S)
        if result.program.checks_pending:
            try:
                result.program.finish_checks()
            except Exception as exc:  # said; the checks stay pending, so Start stays refused
                self._failed(path, exc)
                return
            self.checked.emit(result)
        _yield_cpu()  # the rest is background work: the window comes first
        result = self._refine(result, view_size)
        _warm(result.program)  # about 1 s for a million lines
        self.prepared.emit(result)

    def _failed(self, path: Path, exc: Exception) -> None:
        said = QCoreApplication.translate("Loader", "%1 could not be loaded: %2")
        self.failed.emit(str(path), fill(said, path.name, f"{type(exc).__name__}: {exc}"))

    def _refine(self, result: LoadedProgram, view_size) -> LoadedProgram:
        if result.preview.tolerance <= self.tolerance:
            result.preview.build_all()  # every level of detail, for zooming
            return result
        fine = PreviewModel(result.program.toolpath, self.tolerance, threads=1)  # the window is in use
        fine.warm(view_size or DEFAULT_VIEW)
        fine.build_all()
        result = dataclasses.replace(result, preview=fine)
        self.refined.emit(result)
        return result


def _yield_cpu() -> None:
    """Lower this thread's scheduling priority where the platform allows (Linux nices
    threads one by one); elsewhere nothing changes."""
    with contextlib.suppress(AttributeError, OSError):
        os.setpriority(os.PRIO_PROCESS, threading.get_native_id(), BACKGROUND_NICE)


def _warm(program) -> None:
    """Render the device lines now, off the GUI thread, so Start and Save to SD need not
    wait, with their source lines (a job's progress reads them); then the machine
    planner's time estimate, which the toolpath's times become."""
    with contextlib.suppress(Exception):  # the job start reports any problem itself
        program.line_map  # noqa: B018 (a cached property)
        program.device_lines  # noqa: B018 (a cached property)
        program.planned  # noqa: B018


class LoadError(Exception):
    """A file that cannot be shown as a program; the message says why."""


def load_program(path: Path, tolerance: float = 0.01, view_size=None, tools=None,
                 block_delete: bool = False, systems=None) -> LoadedProgram:
    """The program and its preview model, with what the first picture of a preview of
    ``view_size`` pixels needs already computed (``block_delete``: the operator's switch)."""
    _sniff(path)
    from app.gcode import load

    started = time.perf_counter()
    try:
        program = load(path, tools=tools, block_delete=block_delete, systems=systems, later_checks=True)
    except (OSError, UnicodeError, ValueError) as exc:
        said = QCoreApplication.translate("Loader", "%1 could not be read as G-code: %2")
        raise LoadError(fill(said, path.name, exc)) from None
    loaded = time.perf_counter()
    _check_runnable(path, program)
    size = view_size or DEFAULT_VIEW
    facts = threading.Thread(target=_summary_facts, args=(program,), name="gcode-facts", daemon=True)
    facts.start()  # on the other core, while this one builds the first picture's model
    coarse = screen_tolerance(program.toolpath, size, tolerance)
    program.toolpath.polyline(coarse, threads=1)  # (cached) at this tolerance nearly every arc is one
    # chord: allocation more than arithmetic, which a second thread would only contend for
    preview = PreviewModel(program.toolpath, coarse)
    preview.warm(size)
    facts.join()
    return LoadedProgram(path, program, preview, loaded - started, time.perf_counter() - loaded)


def _summary_facts(program) -> None:
    """What the window's summary reads when the program arrives (all cached), worked
    out here rather than on the GUI thread: the exact bounds (arcs' bulges: 30-100 ms
    for a million moves), the moves' feeds, lengths and times (``Toolpath`` works them
    out on first use: 80-115 ms) and the lengths cut and moved at rapid rate (its first
    handler spent 40-70 ms on them). The device lines' source lines wait for ``_warm``:
    the summary counts the device lines from the plan."""
    with contextlib.suppress(Exception):  # the window meets any problem when it reads them
        program.toolpath.bounds  # noqa: B018 (a cached property)
        program.toolpath.cut_length  # noqa: B018 (a cached sum by kind)


def _sniff(path: Path) -> None:
    from app.gcode.reading import file_problem, looks_utf16

    problem = file_problem(path) if path.exists() else None  # a FIFO or a device is never opened
    if problem:
        raise LoadError(problem)
    try:
        with path.open("rb") as file:
            head = file.read(SNIFF_BYTES)
    except FileNotFoundError:
        said = QCoreApplication.translate("Loader", "%1 does not exist (moved or deleted?).")
        raise LoadError(fill(said, path)) from None
    except OSError as exc:
        said = QCoreApplication.translate("Loader", "%1 cannot be opened: %2.")
        raise LoadError(fill(said, path, exc.strerror or exc)) from None
    if looks_utf16(head):
        said = QCoreApplication.translate("Loader",
                                          "%1 is UTF-16 text: save it as UTF-8 (or plain ASCII) text.")
        raise LoadError(fill(said, path.name))
    if b"\0" in head or _mostly_binary(head):
        said = QCoreApplication.translate("Loader",
                                          "%1 is not a G-code file (it holds binary data, such as an image).")
        raise LoadError(fill(said, path.name))


def _mostly_binary(head: bytes) -> bool:
    if not head:
        return False
    odd = sum(1 for b in head if b < 9 or 13 < b < 32 or b == 127)
    return odd > len(head) // 20


def _check_runnable(path: Path, program) -> None:
    errors = list(program.errors)
    if len(program.toolpath) == 0 and errors:
        first = errors[0]
        said = LoaderTexts().not_gcode(len(errors))
        raise LoadError(fill(said, path.name, first.line, localize(first.message)))


class LoaderTexts(QObject):
    """Texts with plurals (``self.tr`` lets lupdate see them)."""

    def not_gcode(self, errors: int) -> str:
        return self.tr("%1 does not look like G-code: nothing in it can be run "
                       "(%n error(s); first, line %2: %3).", "", errors)
