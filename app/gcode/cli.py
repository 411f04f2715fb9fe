"""``cnc-gcode check|normalize|moves|expand FILE`` (also ``python -m app.gcode``), and
``cnc-gcode feature KIND [options]`` (``features/cli.py``) and ``cnc-gcode import FILE
[options]`` (``pointlist/cli.py``).

- ``check``: a summary (lines, moves, bounds, cut and rapid length, estimated time,
  warnings, errors with their lines); exit status 1 when there are errors;
- ``normalize``: the device lines, one per line;
- ``moves``: the interpreted motion as JSON Lines (see ``moves.py``);
- ``expand``: the device lines of any program (parametric ones expanded), with
  ``--trace`` each followed by the source line it came from as a comment:
  ``(line 12)``, or ``(O0010.nc line 3, called at line 7)`` for a subprogram file.
``--block-delete`` turns the operator's block delete switch on: lines starting with
``/`` are skipped (without it they run, as on LinuxCNC and Fanuc controls with the
switch off). Exit status 2 for a usage error. Diagnostics go to standard error for
``normalize`` and ``moves``, to standard output for ``check``.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import sys
from pathlib import Path

# Before numpy is imported (below): numpy's OpenBLAS would otherwise start a thread per
# core at import, about 40 ms of wall and 80 ms of CPU time in a 0.1-1 s command; the
# core does no linear algebra. (``app.gcode`` imports nothing until asked, see its
# ``__init__``; a value already in the environment is kept.)
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from . import forked  # noqa: E402, I001 (first: it watches the machine's idle time from here on)

import numpy as np  # noqa: E402

from app.i18n import N_, localize, msg  # noqa: E402

from . import workers  # noqa: E402
from .heap import one_heap  # noqa: E402
from .program import Program, load  # noqa: E402


def _summary(p: Program) -> str:
    """The ``check`` report in the language of LANG / LC_MESSAGES (``app.i18n``)."""
    tp = p.toolpath
    low, high = tp.bounds
    planned = p.planned  # the planner's time becomes the toolpath's
    minutes, seconds = divmod(tp.estimated_time, 60)
    bounds = "  ".join(f"{a} {localize(msg('{lo:.3f}..{hi:.3f}', lo=float(lo), hi=float(hi)))}"
                       for a, lo, hi in zip("XYZ", low, high, strict=True))
    rows = [
        msg("file: {name}", name=p.name),
        msg("lines: {lines}  device lines: {device}  moves: {moves}", lines=len(p.lines),
            device=p.plan.total, moves=len(tp)),
        msg("bounds: {bounds}", bounds=bounds),
        msg("start: {where}", where=p.start.note()),
        msg("cut length: {cut:.1f} mm  rapid length: {rapid:.1f} mm", cut=float(tp.cut_length),
            rapid=float(tp.rapid_length)),
        msg("estimated time: {minutes} min {seconds:.0f} s", minutes=int(minutes), seconds=float(seconds)),
        msg("program stops: {stops} (tool changes: {changes}), not counted: {seconds:.0f} s of machine "
            "moves around them, plus the operator's wait", stops=planned.stops, changes=planned.tool_changes,
            seconds=float(planned.stop_seconds)),
        msg("warnings: {warnings}  errors: {errors}", warnings=len(p.warnings), errors=len(p.errors)),
    ]
    rows = [localize(row) for row in rows]
    rows += [localize(msg("warning: {what}", what=d.localized())) for d in p.warnings]
    rows += [localize(msg("error: {what}", what=d.localized())) for d in p.errors]
    return "\n".join(rows) + "\n"


def _check(p: Program) -> int:
    sys.stdout.write(_summary(p))
    return 1 if p.errors else 0


def _print_diagnostics(p: Program) -> None:
    for d in p.diagnostics:
        severity = localize(msg(d.severity))
        print(f"{p.name}: {severity}: {d.localized()}", file=sys.stderr)


def _normalize(p: Program) -> int:
    _print_diagnostics(p)
    sys.stdout.write("".join(line + "\n" for line in p.device_lines))
    return 1 if p.errors else 0


def _moves(p: Program) -> int:
    _print_diagnostics(p)
    from .moves import to_jsonl  # (and json) only for this command: 3 ms of every other start

    sys.stdout.write(to_jsonl(p.moves))
    return 1 if p.errors else 0


def trace_comments(p: Program) -> list[str]:
    """Per device line, where it comes from: ``(line 12)`` or ``(F line 3, called at line 7)``."""
    rows = np.repeat(np.arange(len(p.ops)), p.plan.count)
    lines = p.ops.line[rows].tolist()
    source = p.ops.source
    if source is None:
        return [f"(line {n})" for n in lines]
    names = [Path(f).name for f in source.files]
    files, calls = source.file[rows].tolist(), source.call_line[rows].tolist()
    return [f"({names[f]} line {n}, called at line {c})" if f else f"(line {n})"
            for n, f, c in zip(lines, files, calls, strict=True)]


def _expand(p: Program, trace: bool = False) -> int:
    _print_diagnostics(p)
    if trace:
        comments = trace_comments(p)
        sys.stdout.write("".join(f"{line} {c}\n" for line, c in zip(p.device_lines, comments, strict=True)))
    else:
        sys.stdout.write("".join(line + "\n" for line in p.device_lines))
    return 1 if p.errors else 0


SEVERITIES = (N_("error"), N_("warning"))


def _load(path: str, block_delete: bool = False, plan_ahead: bool = False) -> Program:
    """``load`` without the helper process: for a one-shot run its start-up costs more
    than the part of the scan it would take over (the setting is restored after), its
    threads on one heap (``one_heap``);
    ``plan_ahead`` for ``check``, which prints the planner's estimate."""
    was = workers.enabled()
    workers.set_enabled(False)
    one_heap()
    try:
        with forked.allowed():  # a big file's scan shared with a forked child (forked.py)
            return load(path, block_delete=block_delete, plan_ahead=plan_ahead)
    finally:
        workers.set_enabled(was)


COMMANDS = {"check": _check, "normalize": _normalize, "moves": _moves, "expand": _expand}


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status."""
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["feature"]:
        from .features.cli import main as feature_main
        return feature_main(argv[1:])
    if argv[:1] == ["import"]:
        from .pointlist.cli import main as import_main
        return import_main(argv[1:])
    parser = argparse.ArgumentParser(prog="cnc-gcode", description="Check and convert G-code for the mill.")
    parser.add_argument("command", choices=sorted(COMMANDS))
    parser.add_argument("file")
    parser.add_argument("--trace", action="store_true", help="expand: each line's source line as a comment")
    parser.add_argument("--block-delete", action="store_true",
                        help="the block delete switch on: lines starting with '/' are skipped "
                             "(off: they run)")
    args = parser.parse_args(argv)
    if args.trace and args.command != "expand":
        parser.error("--trace goes with expand")
    try:
        program = _load(args.file, args.block_delete, plan_ahead=args.command == "check")
        return _expand(program, args.trace) if args.command == "expand" else COMMANDS[args.command](program)
    except BrokenPipeError:
        return 0


def run() -> None:
    """The ``cnc-gcode`` command (and ``python -m app.gcode``): ``main()``, then the
    process ends at once, its output flushed: freeing a big program's arrays and objects
    one by one at exit took 30-90 ms for nothing. (Every command writes only to
    standard output and error; an exception still ends the process the usual way.)"""
    status = main()
    with contextlib.suppress(BrokenPipeError):  # the reader has gone: as main() treats it
        sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)
