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
``--at-stops continue|stop`` says. A hold the console did not ask for (panel, cover,
lost host link, ...: the status says why) is printed with its reason and answered
the same way: asked on stdin, waited out (``continue``: the operator acts at the
machine) or the job stopped with exit status 4 (``stop``). ``link`` lines carry the
resend rate of the last minute. ``--from LINE`` runs FILE from that source line,
the modal state of the lines before it restored first (as the window's "Start here").
The heartbeat runs on the wall clock, also against ``cnc-sim --pty --speed N`` (the
machine keeps its link timers in wall time).

GRBL machines (``--driver grbl``; ``sim://grbl`` and a machine that greets as GRBL are
found by themselves) get the commands of ``app.comm.grbl.console``.

The parts: ``console_client`` (the session driven over the transport, waiting,
commands, files), ``console_printer`` (what is printed), ``console_jobs`` (``run``,
``resume``, ``sd``); here the short commands, the command line and the loop over the
commands.
"""

from __future__ import annotations

import argparse
import shlex
import sys

from app.comm.console_client import ConsoleError, load_lines
from app.comm.console_jobs import JobCommands
from app.comm.driver import DRIVERS, kind_for_url, probe
from app.comm.grbl.console import GrblConsole
from app.comm.transport import open_transport

__all__ = ["Console", "ConsoleError", "load_lines", "main", "run_commands", "split_commands"]


class Console(JobCommands):
    """Drives one Session over one transport, synchronously, for the commands above."""

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
        self.wait(lambda: not self.session.urgent.pending("HOLD"), 10.0, "the hold")

    def cmd_stop(self) -> None:
        self.session.stop()
        self.wait(lambda: not self.session.urgent.pending("STOP")
                  and self.session.status.state in ("IDLE", "ALARM"), 30.0, "the stop")


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
                        help="at M00/M01/M06 program stops and at holds the machine makes on its own: "
                             "ask on stdin, continue (wait for the operator at the machine) or stop the job "
                             "(exit 4 after a hold)")
    parser.add_argument("--from", dest="from_line", type=int, metavar="LINE",
                        help="run FILE from this source line, the modal state before it restored")
    parser.add_argument("--driver", choices=("auto", *DRIVERS), default="auto",
                        help="the machine's protocol: this mill's frames or GRBL (auto: detect)")
    args = parser.parse_intermixed_args(argv)
    try:
        transport = open_transport(args.url)
    except (OSError, ValueError) as exc:
        print(f"cannot open {args.url}: {exc}", file=sys.stderr)
        return 3
    kind = args.driver if args.driver != "auto" else kind_for_url(args.url) or probe(transport) or "frame"
    console_class = Console if kind == "frame" else GrblConsole
    console = console_class(transport, quiet=args.quiet, timeout=args.timeout, at_stops=args.at_stops,
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
