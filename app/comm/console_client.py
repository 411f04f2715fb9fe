"""The console's synchronous driver of one ``Session`` over one transport.

``ConsoleClient(transport, ...)`` attaches a session to the transport; ``pump()`` reads
what arrived, feeds the session and lets it tick (``ConsoleError`` 3 once the port
went away); ``wait(predicate)`` pumps until the predicate holds, ``ConsoleError`` 3 on
its timeout or a lost link (unless ``through_loss``); ``command(verb, *args)`` sends a
command and returns its ``CommandResult``, ``ConsoleError`` 1 if refused, 3 if the link
was lost. The clock is the transport's own (``sim://``) or the wall clock; ``sleep`` and
``wall`` are injectable. ``load_program``/``load_lines`` read a G-code file for a job
(``ConsoleError`` 2 if it cannot run). The commands themselves are in
``console_jobs`` and ``console``.
"""

from __future__ import annotations

import sys
import time

from app.comm.console_printer import Printer
from app.comm.heartbeat import LinkState
from app.comm.listener import SessionState
from app.comm.session import Session

PUMP_S = 0.005


class ConsoleError(Exception):
    """A command failed; ``code`` is the exit status."""

    def __init__(self, text: str, code: int = 1) -> None:
        super().__init__(text)
        self.code = code


class ConsoleClient:
    """One session over one transport, driven synchronously (see the module docstring)."""

    def __init__(self, transport, out=None, quiet: bool = False, timeout: float = 3600.0,
                 at_stops: str = "ask", from_line: int | None = None, sleep=time.sleep,
                 wall=time.monotonic) -> None:
        self.transport, self.out, self.timeout = transport, out or sys.stdout, timeout
        self.sleep, self.wall = sleep, wall
        self.at_stops = at_stops  # "ask" (stdin), "continue" or "stop"
        self.from_line = from_line  # run FILE starts at this source line (start from a line)
        self.printer = Printer(self.out, quiet)
        clock = getattr(transport, "clock", None) or time.monotonic
        self.session = Session(None, self.printer, clock)
        self.session.attach(transport.write)

    def pump(self) -> None:
        try:
            waiting = self.transport.in_waiting
            if waiting:
                self.session.feed(self.transport.read(waiting))
        except OSError as exc:
            self.session.detach(f"read failed: {exc}")
        self.session.tick()
        if not self.session.attached:
            raise ConsoleError("link lost: the port went away", 3)

    def wait(self, predicate, timeout: float | None = None, what: str = "an answer",
             through_loss: bool = False) -> None:
        """Pump until ``predicate()``; ConsoleError(3) on timeout, and on a lost link
        unless ``through_loss`` (waiting for a job, which a link loss interrupts)."""
        end = self.wall() + (self.timeout if timeout is None else timeout)
        while not predicate():
            if self.wall() > end:
                raise ConsoleError(f"timed out waiting for {what}", 3)
            self.pump()
            if not through_loss and self.session.link.state is LinkState.LOST:
                raise ConsoleError(f"link lost while waiting for {what}: no valid frame for "
                                   f"{self.session.link.lost_s:g} s", 3)
            self.sleep(PUMP_S)

    def command(self, verb: str, *args, timeout: float | None = None):
        cid = self.session.submit(verb, *args)
        found = lambda: [r for r in self.printer.results if r.id == cid]  # noqa: E731
        self.wait(lambda: bool(found()), timeout, f"{verb} to be answered")
        result = found()[0]
        if result.code == "LINK_LOST":
            raise ConsoleError(f"link lost while waiting for {verb}: {result.info}", 3)
        if not result.ok:
            raise ConsoleError(f"{verb} refused: {result.code} {result.info}".strip())
        return result

    def connect(self) -> None:
        self.wait(lambda: self.session.state is SessionState.READY, 5.0, "the machine's status")
        self.wait(lambda: self.session.boot is not None, 5.0, "the CNC MCU")

    def checking(self) -> bool:
        return any(r.ok and r.info == "CHECK 1" for r in self.printer.results[-50:])

    def print_status(self) -> None:
        s = self.session.status
        print(f"status {s.state} X{s.x:.3f} Y{s.y:.3f} Z{s.z:.3f} acc {s.acc} done {s.done} "
              f"free {s.free} rpm {s.rpm} flags {s.flags or '-'} boot {s.boot}", file=self.out)


def load_lines(path: str) -> list[str]:
    """The normalised device lines of a G-code file; ConsoleError(2) if unusable."""
    return list(load_program(path).device_lines)


def load_program(path: str):
    """The loaded ``Program`` of a G-code file with lines to run; ConsoleError(2) if unusable."""
    from app.gcode import load

    try:
        program = load(path)
    except OSError as exc:
        raise ConsoleError(f"cannot read {path}: {exc}", 2) from None
    errors = [d for d in program.diagnostics if d.severity == "error"]
    if errors:
        first = errors[0]
        raise ConsoleError(f"{path}: {len(errors)} error(s); line {first.line}: {first.message}", 2)
    if not program.device_lines:
        raise ConsoleError(f"{path}: no lines to run", 2)
    return program
