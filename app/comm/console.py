"""``python -m app.comm.console URL [COMMAND ...]``: a headless second client of the link.

Commands (several may follow each other, separated by ``,``; with none, one command
per line is read from stdin): ``ping``, ``status``, ``home``, ``run FILE``,
``sd put FILE [NAME]``, ``sd ls``, ``sd run NAME``, ``sd rm NAME``, ``pause``,
``resume [FILE | FROM SEQ]``, ``stop``, ``check on|off``, or any raw verb
(``JOG X 10 300``).

``resume`` does what the window's Resume does: with the job of this console
interrupted by a link loss, it waits for the link, sends ``RESUME FROM acc+1`` and
the missing lines, and waits for the job to end as ``run`` does; with no job, it
leaves a feed hold. ``resume FILE`` takes over a job of FILE that another client left
interrupted (same boot): ``RESUME FROM acc+1``, then the rest of FILE. ``resume FROM
SEQ`` sends that verb as it is. Read from stdin, a failed command prints its error
and the console goes on (so ``resume`` can follow an interrupted ``run``); the exit
status is then that of the last failure.

Frames are printed as ``> `` (sent) and ``< `` (received); ``-q`` hides the stream
traffic (D, A, F, S). ``run`` homes if the machine is not homed, streams the file,
waits for the last ``F``, prints the final status line and exits 0 only if the job
completed; otherwise it exits 1 with the reason. Exit 2: bad usage or file; 3: the
port cannot be opened or the link was lost (no valid frame for 3 s, or the port
went away). At a program stop (``M00``/``M01``/``M06``)
``run`` asks on stdin (Enter continues, ``stop`` ends the job), or answers as
``--at-stops continue|stop`` says. ``--from LINE`` runs FILE from that source line,
the modal state of the lines before it restored first (as the window's "Start here").
The heartbeat runs on the wall clock, also against ``cnc-sim --pty --speed N`` (the
machine keeps its link timers in wall time).
"""

from __future__ import annotations

import argparse
import shlex
import sys
import time
from pathlib import Path

from app.comm.events import FrameEvent
from app.comm.heartbeat import LinkState
from app.comm.listener import SessionListener, SessionState
from app.comm.modal import device_index_of, restart_preamble
from app.comm.session import Session
from app.comm.transport import open_transport

PUMP_S = 0.005
QUIET = frozenset("DAFS")


class ConsoleError(Exception):
    """A command failed; ``code`` is the exit status."""

    def __init__(self, text: str, code: int = 1) -> None:
        super().__init__(text)
        self.code = code


class Printer(SessionListener):
    """Prints traffic, logs, alarms, errors and throttled progress."""

    def __init__(self, out, quiet: bool) -> None:
        self.out, self.quiet = out, quiet
        self.results, self.jobs, self.errors = [], [], []
        self.stops: list = []  # program stops not answered yet
        self._last_progress = 0.0

    def on_frame(self, event: FrameEvent):
        if event.kind != "L" and not (self.quiet and event.kind in QUIET and event.ok):
            print(("> " if event.direction == "tx" else "< ") + event.text, file=self.out)

    def on_progress(self, event):
        now = time.monotonic()
        if now - self._last_progress >= 0.5 or event.done + 1 == event.total:
            self._last_progress = now
            print(f"progress {event.kind}: {event.done + 1}/{event.total} done, "
                  f"{event.acked + 1} queued, {event.resends} resends", file=self.out)

    def on_log(self, event):
        print(f"[{event.source} {event.level}] {event.text}", file=self.out)

    def on_alarm(self, event):
        print(f"ALARM {event.code} {event.text}", file=self.out)

    def on_link_changed(self, event):
        print(f"link {event.state}" + (" (poor quality)" if event.quality_warning else ""), file=self.out)

    def on_command_done(self, event):
        self.results.append(event)

    def on_job_finished(self, event):
        self.jobs.append(event)

    def on_error(self, event):
        self.errors.append(event)

    def on_program_stop(self, event):
        self.stops.append(event)


class Console:
    """Drives one Session over one transport, synchronously, for the commands above."""

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

    # ------------------------------------------------------------------ commands

    def do(self, words: list[str]) -> None:
        verb = words[0].lower()
        handler = getattr(self, f"cmd_{verb}", None)
        if handler is None:
            self.command(*[w.upper() for w in words])
            return
        handler(*words[1:])

    def cmd_ping(self) -> None:
        self.command("PING", timeout=5.0)
        self.print_status()

    def cmd_status(self) -> None:
        self.command("STATUS", timeout=5.0)
        self.print_status()

    def cmd_home(self, mode: str = "NORMAL") -> None:
        self.command("HOME", mode.upper())

    def cmd_check(self, state: str = "on") -> None:
        self.command("SET", "CHECK", 1 if state.lower() in ("on", "1") else 0)

    def cmd_pause(self) -> None:
        self.session.pause()
        self.wait(lambda: self.session.status.state in ("HOLD", "IDLE"), 10.0, "the hold")

    def cmd_resume(self, *args: str) -> None:
        if args and args[0].upper() == "FROM":
            if len(args) != 2 or not args[1].isdigit():
                raise ConsoleError("usage: resume FROM <seq>", 2)
            self.command("RESUME", "FROM", args[1])
        elif args:
            self._take_over(args[0])
        elif self.session.stream is not None and self.session.stream.kind == "job":
            self._resume_own_job()
        else:
            self.command("RESUME")

    def _resume_own_job(self) -> None:
        offered = (SessionState.RESUME_OFFERED, SessionState.RESTART_REQUIRED)
        self.wait(lambda: self.session.state not in (SessionState.INTERRUPTED,), what="the link to come back",
                  through_loss=True)
        if self.session.state is SessionState.RESTART_REQUIRED:
            raise ConsoleError("the machine was reset: home it and run the job again", 1)
        jobs = len(self.printer.jobs)
        if self.session.state in offered and not self.session.resume():
            raise ConsoleError(f"resume refused: {self.printer.errors[-1].text}")
        if self.session.state is SessionState.PAUSED:
            self.session.resume()
        self._wait_job(jobs)

    def _take_over(self, path: str) -> None:
        lines = load_lines(path)
        self.command("STATUS", timeout=5.0)
        jobs = len(self.printer.jobs)
        if not self.session.take_over_job(lines):
            raise ConsoleError(f"resume refused: {self.printer.errors[-1].text}")
        self._wait_job(jobs)

    def cmd_stop(self) -> None:
        self.session.stop()
        self.wait(lambda: self.session.status.state in ("IDLE", "ALARM"), 30.0, "the stop")

    def cmd_run(self, path: str) -> None:
        program = load_program(path)
        lines = list(program.device_lines)
        start = 0
        if self.from_line is not None:
            start = device_index_of(program.line_map.tolist(), self.from_line)
            if start is None:
                raise ConsoleError(f"{path}: nothing runs from line {self.from_line} on", 2)
            print(f"starting at line {self.from_line} (device line {start}); restoring: "
                  + "; ".join(restart_preamble(lines, start)), file=self.out)
        if not self.session.status.homed and not self.checking():
            print("not homed: homing first", file=self.out)
            self.cmd_home()
            self.command("STATUS")
        jobs = len(self.printer.jobs)
        if not self.session.start_job(lines, start):
            raise ConsoleError(f"job refused: {self.printer.errors[-1].text}")
        self._wait_job(jobs)

    def _wait_job(self, jobs: int) -> None:
        """Wait for the job started after ``jobs`` ended ones (answering its program stops);
        print how it ended."""
        ended = lambda: len(self.printer.jobs) > jobs or self.session.state is SessionState.INTERRUPTED  # noqa: E731
        while not ended():
            self.wait(lambda: ended() or bool(self.printer.stops), what="the job to end", through_loss=True)
            if self.printer.stops:
                self.answer_stop(self.printer.stops.pop(0))
        job = self.printer.jobs[-1] if len(self.printer.jobs) > jobs else None
        if job is None:
            raise ConsoleError("job interrupted: link lost (type resume when the link is back)", 3)
        self.command("STATUS", timeout=5.0)
        self.print_status()
        if not job.completed:
            raise ConsoleError(f"job failed at line {job.done + 1} of {job.total}: {job.reason}")
        print(f"job completed: {job.total} lines", file=self.out)

    def answer_stop(self, event) -> None:
        """The machine holds at a program stop: continue or stop, as ``at_stops`` says."""
        print(f"program stop at device line {event.index}: {event.line}", file=self.out)
        answer = self.at_stops
        if answer == "ask":
            try:
                answer = input("Enter continues, 'stop' ends the job: ").strip().lower() or "continue"
            except EOFError:
                answer = "stop"
        if answer.startswith("s"):
            self.session.stop()
        else:
            self.session.resume()

    def cmd_sd(self, action: str, *args) -> None:
        action = action.lower()
        if action == "put":
            lines = load_lines(args[0])
            name = args[1] if len(args) > 1 else Path(args[0]).name
            jobs = len(self.printer.jobs)
            if not self.session.upload_to_sd(name, lines):
                raise ConsoleError(f"upload refused: {self.printer.errors[-1].text}")
            self.wait(lambda: len(self.printer.jobs) > jobs, what="the upload")
            job = self.printer.jobs[-1]
            if not job.completed:
                raise ConsoleError(f"upload failed: {job.reason}")
            print(f"stored {name}: {len(lines)} lines", file=self.out)
        elif action in ("ls", "list"):
            for row in self.command("SD", "LIST").rows:
                print(row, file=self.out)
        elif action == "run":
            self.command("SD", "RUN", args[0])
        elif action in ("rm", "del"):
            self.command("SD", "DEL", args[0])
        else:
            raise ConsoleError(f"unknown sd action {action!r}: put, ls, run, rm", 2)

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


def split_commands(words: list[str]) -> list[list[str]]:
    """``["home", ",", "run", "a.ngc"]`` (or ``"home,"``) -> ``[["home"], ["run", "a.ngc"]]``."""
    groups, current = [], []
    for word in words:
        for part in word.replace(",", " , ").split():
            if part == ",":
                groups.append(current)
                current = []
            else:
                current.append(part)
    groups.append(current)
    return [g for g in groups if g]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m app.comm.console", description=__doc__.split("\n")[0])
    parser.add_argument("url", help="sim://[?speed=X], /dev/ttyUSB0, socket://host:port, ...")
    parser.add_argument("command", nargs="*", help="command and arguments (see module help)")
    parser.add_argument("-q", "--quiet", action="store_true", help="hide D/A/F/S traffic")
    parser.add_argument("--timeout", type=float, default=3600.0, help="seconds to wait per command")
    parser.add_argument("--at-stops", choices=("ask", "continue", "stop"), default="ask",
                        help="at M00/M01/M06 program stops: ask on stdin, continue or stop the job")
    parser.add_argument("--from", dest="from_line", type=int, metavar="LINE",
                        help="run FILE from this source line, the modal state before it restored")
    args = parser.parse_intermixed_args(argv)
    try:
        transport = open_transport(args.url)
    except (OSError, ValueError) as exc:
        print(f"cannot open {args.url}: {exc}", file=sys.stderr)
        return 3
    console = Console(transport, quiet=args.quiet, timeout=args.timeout, at_stops=args.at_stops,
                      from_line=args.from_line)
    given = split_commands(args.command)
    try:
        console.connect()
        if given:
            return run_commands(console, given, stop_at_error=True)
        return run_commands(console, (shlex.split(line) for line in sys.stdin), stop_at_error=False)
    except ConsoleError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return exc.code
    finally:
        transport.close()


def run_commands(console: Console, commands, stop_at_error: bool) -> int:
    """Run each command; the exit status of the last failure (0 if none)."""
    status = 0
    for words in commands:
        if not words:
            continue
        try:
            console.do(words)
        except ConsoleError as exc:
            print(f"error: {exc}", file=sys.stderr)
            status = exc.code
        except (TypeError, IndexError, ValueError) as exc:
            print(f"error: bad command {' '.join(words)!r}: {exc}", file=sys.stderr)
            status = 2
        if status and stop_at_error:
            break
    return status


if __name__ == "__main__":
    sys.exit(main())
