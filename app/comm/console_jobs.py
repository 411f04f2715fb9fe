"""The console's commands that stream: ``run FILE``, ``resume [FILE | FROM SEQ]`` and
``sd put|ls|run|rm``, on top of ``ConsoleClient``.

``run`` homes first if the machine is not homed (outside check mode), starts the job
(from ``from_line`` with the modal state restored, when given), answers its program
stops as ``at_stops`` says (stdin, ``continue`` or ``stop``) and returns once it
completed, or raises ``ConsoleError``: 1 if it failed, 3 if the link was lost (the job
is then interrupted, and ``resume`` carries it on once the link is back). A hold the
console did not ask for (the panel, the cover, a lost host link ...: the status's
``why``) is printed with its reason; ``ask`` asks on stdin (Enter resumes, ``stop``
ends the job), ``continue`` waits for the operator at the machine, ``stop`` ends the
job and raises ``ConsoleError`` 4 (``HELD_EXIT``). ``resume``
without arguments resumes this console's interrupted job as the window does (RESUME
FROM acc+1 and the missing lines) or leaves a feed hold; ``resume FILE`` takes over a
job of FILE another client left open; ``resume FROM SEQ`` sends that verb as it is.
``sd put`` returns once the machine has stored and checked the file.
"""

from __future__ import annotations

from pathlib import Path

from app.comm.console_client import ConsoleClient, ConsoleError, load_lines, load_program
from app.comm.listener import SessionState
from app.comm.modal import device_index_of, restart_preamble

HELD_EXIT = 4
"""Exit status of ``run`` when ``--at-stops stop`` ended a job the machine held on its own."""


class JobCommands(ConsoleClient):
    """``cmd_run``, ``cmd_resume`` and ``cmd_sd`` (see the module docstring)."""

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

    def cmd_run(self, path: str) -> None:
        program = load_program(path)
        if not self.session.status.homed and not self.checking():
            print("not homed: homing first", file=self.out)
            self.cmd_home()
            self.command("STATUS")
        status = self.session.status  # a move relative to the start is read from where the machine is
        program = program.from_start((status.x, status.y, status.z))
        if program.errors:
            raise ConsoleError(f"{path}: read from where the machine stands: {program.errors[0]}", 2)
        lines = list(program.device_lines)
        start = 0
        if self.from_line is not None:
            start = device_index_of(program.line_map.tolist(), self.from_line)
            if start is None:
                raise ConsoleError(f"{path}: nothing runs from line {self.from_line} on", 2)
            print(f"starting at line {self.from_line} (device line {start}); restoring: "
                  + "; ".join(restart_preamble(lines, start)), file=self.out)
        jobs = len(self.printer.jobs)
        if not self.session.start_job(lines, start):
            raise ConsoleError(f"job refused: {self.printer.errors[-1].text}")
        self._wait_job(jobs)

    def _wait_job(self, jobs: int) -> None:
        """Wait for the job started after ``jobs`` ended ones (answering its program stops);
        print how it ended."""
        ended = lambda: len(self.printer.jobs) > jobs or self.session.state is SessionState.INTERRUPTED  # noqa: E731
        held = None
        self.printer.holds.clear()
        while not ended():
            asked = lambda: ended() or bool(self.printer.stops or self.printer.holds)  # noqa: E731
            self.wait(asked, what="the job to end", through_loss=True)
            if self.printer.stops:
                self.answer_stop(self.printer.stops.pop(0))
            if self.printer.holds:
                held = self.answer_hold(self.printer.holds.pop(0)) or held
        job = self.printer.jobs[-1] if len(self.printer.jobs) > jobs else None
        if job is None:
            raise ConsoleError("job interrupted: link lost (type resume when the link is back)", 3)
        self.command("STATUS", timeout=5.0)
        self.print_status()
        if not job.completed and held is not None:
            raise ConsoleError(f"job stopped at line {job.done + 1} of {job.total}: the machine held "
                               f"[{held.why}]: {held.text}", HELD_EXIT)
        if not job.completed:
            raise ConsoleError(f"job failed at line {job.done + 1} of {job.total}: {job.reason}")
        print(f"job completed: {job.total} lines", file=self.out)

    def _answer(self, prompt: str, enter: str) -> str:
        """``at_stops``, or with ``ask`` the operator's answer on stdin (Enter: ``enter``;
        no stdin: ``stop``)."""
        if self.at_stops != "ask":
            return self.at_stops
        try:
            return input(prompt).strip().lower() or enter
        except EOFError:
            return "stop"

    def answer_stop(self, event) -> None:
        """The machine holds at a program stop: continue or stop, as ``at_stops`` says."""
        print(f"program stop at device line {event.index}: {event.line}", file=self.out)
        if self._answer("Enter continues, 'stop' ends the job: ", "continue").startswith("s"):
            self.session.stop()
        else:
            self.session.resume()

    def answer_hold(self, event):
        """The machine holds on its own: resume, stop or wait, as ``at_stops`` says; the
        event if the job was stopped for it."""
        answer = self._answer("Enter resumes, 'stop' ends the job: ", "resume")
        if answer.startswith("s"):
            print("stopping the job", file=self.out)
            self.session.stop()
            return event
        if answer.startswith("r"):
            self.session.resume()
        else:
            print("waiting for the operator at the machine", file=self.out)
        return None

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
