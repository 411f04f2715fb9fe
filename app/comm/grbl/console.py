"""The console's commands on a GRBL machine (``python -m app.comm.console URL --driver
grbl ...``; ``sim://grbl`` and a machine that greets as GRBL choose it by themselves).

Commands: ``status``, ``info`` (``$I``), ``home`` (``$H``), ``unlock`` (says why the
machine is locked, then ``$X``), ``run FILE`` (home if locked, or refuse on a machine
without homing, ``$22=0``; stream, answer
program stops as ``--at-stops`` says, exit 0 only if every line completed), ``check
FILE`` (the whole program through ``$C`` check mode; every refused line listed),
``hold``/``pause``, ``resume``, ``stop``, ``reset``, ``jog AXIS MM FEED``, ``cancel``
(jog cancel), ``feed|rapid|spindle PERCENT`` (overrides), ``settings [save FILE |
diff FILE | restore FILE]`` (the ``$$`` table with names, units and meanings),
``offsets`` (``$#``), ``modes`` (``$G``), or any line sent as it is (``G0 X10``, ``$10=3``).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from app.comm.console_client import ConsoleClient, ConsoleError, load_program
from app.comm.console_jobs import JobCommands
from app.comm.console_printer import Printer
from app.comm.grbl.events import GrblListener
from app.comm.grbl.protocol import STREAM_KINDS
from app.comm.grbl.session import GrblSession
from app.comm.grbl.settings import read_backup, table, write_backup
from app.comm.grbl.status import hold_event
from app.comm.listener import SessionState
from app.comm.modal import device_index_of
from app.i18n import localize


class GrblPrinter(Printer, GrblListener):
    """The console's printer with GRBL's traffic: ``-q`` hides job lines, their ``ok``
    and the reports; holds and door states in words."""

    def __init__(self, out, quiet: bool) -> None:
        super().__init__(out, quiet)
        self.why = ""  # the hold last printed (a status's ``why``)

    def on_frame(self, event):
        quiet = self.quiet and event.kind in STREAM_KINDS
        if not quiet:
            print(("> " if event.direction == "tx" else "< ") + event.text, file=self.out)

    def on_log(self, event):
        print(f"[{event.source} {event.level}] {localize(event.text)}", file=self.out)

    def on_status(self, event):
        """A hold or door state in words when it changes (``status.hold_event``), as the
        mill's console prints the holds its machine explains."""
        if event.why != self.why:
            self.why = event.why
            self.on_hold(hold_event(event))


class GrblConsole(ConsoleClient):
    """``ConsoleClient`` over a ``GrblSession`` (see the module docstring)."""

    def __init__(self, transport, out=None, quiet: bool = False, timeout: float = 3600.0,
                 at_stops: str = "ask", from_line: int | None = None, sleep=time.sleep,
                 wall=time.monotonic) -> None:
        self.transport, self.out, self.timeout = transport, out or sys.stdout, timeout
        self.sleep, self.wall = sleep, wall
        self.at_stops, self.from_line = at_stops, from_line
        self.printer = GrblPrinter(self.out, quiet)
        clock = getattr(transport, "clock", None) or time.monotonic
        self.session = GrblSession(None, self.printer, clock)
        self.session.attach(transport.write)
        early = getattr(transport, "probe_bytes", b"")
        if early:
            self.session.feed(early)

    def do(self, words: list[str]) -> None:
        handler = getattr(self, f"cmd_{words[0].lower()}", None)
        if handler is None:
            self.command(" ".join(words))
            return
        handler(*words[1:])

    def command(self, text: str, *args, timeout: float | None = None):
        cid = self.session.send_command(" ".join([text, *map(str, args)]))
        found = lambda: [r for r in self.printer.results if r.id == cid]  # noqa: E731
        self.wait(lambda: bool(found()), timeout, f"{text} to be answered")
        result = found()[0]
        if result.code == "LINK_LOST":
            raise ConsoleError(f"link lost while waiting for {text}: {result.info}", 3)
        if not result.ok:
            raise ConsoleError(f"{text} refused: {result.code} {localize(result.info)}".strip())
        return result

    def connect(self) -> None:
        self.wait(lambda: self.session.state is SessionState.READY, 5.0, "a status report")
        self.wait(lambda: not self.session._queue and not len(self.session.counter), 10.0,
                  "the machine's settings")

    def print_status(self) -> None:
        s, g = self.session.status, self.session.grbl_status
        print(f"status {g.state}{'' if g.substate is None else f':{g.substate}'} "
              f"WPos X{s.x:.3f} Y{s.y:.3f} Z{s.z:.3f} MPos {','.join(f'{v:.3f}' for v in g.mpos)} "
              f"feed {g.feed:g} rpm {g.rpm:g} Ov {','.join(map(str, g.overrides))} "
              f"flags {s.flags or '-'}", file=self.out)

    # ------------------------------------------------------------------ short commands

    def _fresh_status(self) -> None:
        before = self.session.grbl_status
        self.wait(lambda: self.session.grbl_status is not before, 3.0, "a status report")

    def cmd_status(self) -> None:
        self._fresh_status()
        self.print_status()

    def cmd_info(self) -> None:
        for row in self.command("$I").rows:
            print(row, file=self.out)

    def cmd_home(self) -> None:
        self.command("$H", timeout=300.0)

    def cmd_unlock(self) -> None:
        print(localize(self.session.unlock_advice()), file=self.out)
        self.command("$X")

    def cmd_hold(self) -> None:
        self.session.pause()
        self.wait(lambda: self.session.grbl_status.state in ("Hold", "Idle") and
                  self.session.grbl_status.substate in (None, 0), 10.0, "the hold")

    cmd_pause = cmd_hold

    def cmd_resume(self) -> None:
        self.session.resume()

    def cmd_stop(self) -> None:
        self.session.stop()
        self.wait(lambda: self.session.job is None, 30.0, "the stop")

    def cmd_reset(self) -> None:
        boots = self.session.boots
        self.session.reset()
        self.wait(lambda: self.session.boots > boots, 5.0, "the machine's welcome")

    def cmd_jog(self, axis: str, distance: str, feed: str) -> None:
        cid = self.session.jog(axis, float(distance), float(feed))
        self.wait(lambda: any(r.id == cid for r in self.printer.results), 10.0, "the jog")

    def cmd_cancel(self) -> None:
        self.session.jog_cancel()

    def cmd_feed(self, percent: str) -> None:
        self.session.set_feed_override(int(percent))

    def cmd_rapid(self, percent: str) -> None:
        self.session.set_rapid_override(int(percent))

    def cmd_spindle(self, percent: str) -> None:
        self.session.set_spindle_override(int(percent))

    def cmd_offsets(self) -> None:
        for row in self.command("$#").rows:
            print(row, file=self.out)

    def cmd_modes(self) -> None:
        for row in self.command("$G").rows:
            print(row, file=self.out)

    def cmd_settings(self, action: str = "", path: str = "") -> None:
        self.command("$$")
        current = self.session.settings
        if action == "save":
            Path(path).write_text(write_backup(current), encoding="ascii")
            print(f"saved {len(current)} settings to {path}", file=self.out)
            return
        if action in ("diff", "restore"):
            wanted = self._backup(path)
            changes = self.session.settings_diff(wanted)
            for change in changes:
                print(localize(change.describe()), file=self.out)
            if action == "restore":
                for change in changes:
                    if change.new is not None:
                        self.command(f"${change.number}={change.new}")
                print(f"restored {sum(c.new is not None for c in changes)} settings", file=self.out)
            return
        for row in table(current):
            print(f"${row.number}={row.value}\t{localize(row.name)} [{localize(row.unit)}]: "
                  f"{localize(row.meaning)}", file=self.out)

    def _backup(self, path: str) -> dict[int, str]:
        try:
            return read_backup(Path(path).read_text(encoding="utf-8", errors="replace"), path)
        except OSError as exc:
            raise ConsoleError(f"cannot read {path}: {exc}", 2) from None
        except ValueError as exc:
            raise ConsoleError(localize(str(exc)), 2) from None

    # ------------------------------------------------------------------ jobs

    def cmd_check(self, path: str) -> None:
        program = load_program(path)
        if not self.session.check_mode:
            self.command("$C")
        try:
            self._run(program, path)
        finally:
            if self.session.check_mode:
                self.command("$C")

    def cmd_run(self, path: str) -> None:
        program = load_program(path)
        self._fresh_status()
        if self.session.status.state == "ALARM" and not self.session.check_mode:
            print(localize(self.session.unlock_advice()), file=self.out)
            if not self.session.homing_enabled:  # nothing to home ($22=0): the operator unlocks
                raise ConsoleError("the machine is in alarm and has no homing: unlock it first (unlock)")
            print("homing first ($H)", file=self.out)
            self.cmd_home()
            self._fresh_status()
        self._run(program, path)

    def _run(self, program, path: str) -> None:
        lines = list(program.device_lines)
        line_map = program.line_map.tolist()
        start = 0
        if self.from_line is not None:
            start = device_index_of(line_map, self.from_line)
            if start is None:
                raise ConsoleError(f"{path}: nothing runs from line {self.from_line} on", 2)
        jobs = len(self.printer.jobs)
        if not self.session.start_job(lines, start, Path(path).name, line_map):
            raise ConsoleError(f"job refused: {localize(self.printer.errors[-1].text)}")
        self._wait_job(jobs)

    def _wait_job(self, jobs: int) -> None:
        ended = lambda: len(self.printer.jobs) > jobs or self.session.state in (  # noqa: E731
            SessionState.INTERRUPTED, SessionState.RESTART_REQUIRED)
        while not ended():
            self.wait(lambda: ended() or bool(self.printer.stops), what="the job to end", through_loss=True)
            if self.printer.stops:
                self.answer_stop(self.printer.stops.pop(0))
        job = self.printer.jobs[-1] if len(self.printer.jobs) > jobs else None
        if job is None:
            raise ConsoleError("job cut off: the link was lost or the machine reset", 3)
        self._fresh_status()
        self.print_status()
        if not job.completed:
            raise ConsoleError(f"job failed: {localize(job.reason)}")
        print(f"job completed: {job.total} lines", file=self.out)

    answer_stop = JobCommands.answer_stop  # the mill's console's prompt, as it is
