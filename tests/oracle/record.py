"""Record LinuxCNC's ``rs274 -g`` canonical output for the oracle tests.

Run it where LinuxCNC is installed (Debian: ``apt-get install linuxcnc-uspace``)::

    python tests/oracle/record.py            # every sample and case
    python tests/oracle/record.py arc_r_long # only sources whose stem matches

CI never runs this: the tests read only the committed ``tests/oracle/data/*.canon``.

Sources: ``resources/samples/*.ngc`` and ``tests/oracle/cases/*.ngc`` except the
subroutine files ``cases/lib_*.ngc``, which are copied beside every program so that
``o<lib_name> call`` finds them (line k of the i-th of them, from 0, numbered
``N<LIB_LINES * (i + 1) + k>`` so that its moves can be told from the program's);
data goes to
``tests/oracle/data/<stem>.canon`` (stems must be unique across both folders). A few
cases are also run with other rs274 switches (``VARIANTS``): ``<stem>+<tag>.canon``.

How rs274 is run, for each source:

* ``rs274 -g -t tool.tbl FILE`` (batch mode, a tool table with only T1, or ``SEM_TOOLS``
  for the issue 9 cases ``sem_*``, no ini file so the interpreter's built-in defaults
  apply, block delete switch off, stop at the first error), with stdin from /dev/null,
  in its own temporary directory that is also its ``HOME``: rs274 truncates and maps
  ``$HOME/.tool.mmap`` and runs would trample on each other (or on a real user's file).
* rs274's ``-g`` output names each call's ``N`` word, not its physical line, so FILE is
  a copy of the source in which line ``k`` starts with the word ``N<k>`` (an existing
  leading ``N`` word is replaced; ``%`` lines are left alone). The ``N`` word has no
  other meaning to the interpreter; to prove it, the original source is run too and its
  output must be identical apart from the ``N`` column.
* On an error rs274 prints the message and the text of the failing line on stderr and
  exits 1; the ``N<k>`` at the start of that text gives the error line (a refused ``%``
  line has none: the source's one ``%`` line after its first is that line).

Each ``.canon`` file starts with ``#`` header lines (rs274's version and the command
first), then rs274's stdout verbatim.
"""

from __future__ import annotations

import argparse
import hashlib
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
SOURCE_DIRS = (ROOT / "resources" / "samples", HERE / "cases")

COMMAND = "rs274 -g -t tool.tbl FILE"
TOOL_TABLE = "T1 P1 D3.175 ;3.175 mm end mill\n"  # so that "T1 M6" is a valid tool change
# The cases of issue 9 (stems starting "sem_") run with this table: number -> (diameter,
# length) in mm. rs274 without an ini reads its tool table in inches, so the file holds
# these values / 25.4; the tests load the same table in mm (``SEM_TOOLS``).
SEM_PREFIX = "sem_"
SEM_TOOLS = {1: (6.0, 0.0), 2: (4.0, 12.5), 3: (10.0, -3.0), 4: (2.0, 5.0), 5: (20.0, 0.0)}


def tool_table_for(stem: str) -> str:
    """The rs274 tool table file for a source (inches, see ``SEM_TOOLS``)."""
    if not stem.startswith(SEM_PREFIX):
        return TOOL_TABLE
    return "".join(f"T{n} P{n} D{d / 25.4!r} Z{z / 25.4!r}\n" for n, (d, z) in SEM_TOOLS.items())
_LEADING_N = re.compile(r"^(\s*/?\s*)(?:[nN]\s*\d+\s*)?")
_ERROR_LINE = re.compile(r"^\s*/?\s*N(\d+)\b")
# Extra runs with other rs274 switches, stored as data/<stem>+<tag>.canon.
VARIANTS = {"block_delete": {"b": ("-b",)}}  # -b: block delete switch ON (skip "/" lines)
_N_COLUMN = re.compile(r"^(\s*\d+ )N(?:\d+|\.+)\s*")


def rs274_version() -> str:
    out = subprocess.run(
        ["dpkg-query", "-W", "-f", "${Package} ${Version}", "linuxcnc-uspace"],
        capture_output=True,
        text=True,
        check=False,
    )
    return out.stdout.strip() if out.returncode == 0 else "unknown linuxcnc version"


LIB_LINES = 10000


def number_lines(text: str, offset: int = 0) -> str:
    """Give line k the word N<offset + k> (after an optional block-delete slash)."""
    body, newline = (text[:-1], "\n") if text.endswith("\n") else (text, "")
    out = []
    for k, line in enumerate(body.split("\n"), start=1):
        if line.lstrip().startswith("%"):
            out.append(line)
            continue
        m = _LEADING_N.match(line)
        out.append(f"{m.group(1)}N{offset + k} {line[m.end() :]}")
    return "\n".join(out) + newline


def libraries() -> list[Path]:
    """The subroutine files copied beside every program (``cases/lib_*.ngc``)."""
    return sorted((HERE / "cases").glob("lib_*.ngc"))


def run_rs274(
    program: str, extra: tuple[str, ...] = (), tool_table: str = TOOL_TABLE, numbered: bool = True
) -> tuple[int, str, str]:
    """Run rs274 on ``program`` text in a fresh temporary HOME, the subroutine files beside
    it (numbered like the program when ``numbered``); (exit code, stdout, stderr)."""
    with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
        tmpdir = Path(tmp)
        (tmpdir / "tool.tbl").write_text(tool_table)
        (tmpdir / "program.ngc").write_text(program)
        for i, lib in enumerate(libraries()):
            text = lib.read_text()
            (tmpdir / lib.name).write_text(number_lines(text, LIB_LINES * (i + 1)) if numbered else text)
        env = {"HOME": tmp, "PATH": "/usr/bin:/bin", "LANG": "C", "LC_ALL": "C"}
        proc = subprocess.run(
            ["rs274", "-g", *extra, "-t", "tool.tbl", "program.ngc"],
            cwd=tmp,
            env=env,
            stdin=subprocess.DEVNULL,
            capture_output=True,
            text=True,
            timeout=120,
            check=False,
        )
    return proc.returncode, proc.stdout, proc.stderr


def strip_n_column(stdout: str) -> str:
    return "\n".join(_N_COLUMN.sub(r"\1", line) for line in stdout.splitlines())


def stderr_lines(stderr: str) -> list[str]:
    return [line for line in stderr.splitlines() if line.strip() and line.strip() != "executing"]


def record(source: Path, extra: tuple[str, ...] = ()) -> str:
    text = source.read_text()
    table = tool_table_for(source.stem)
    rc, out, err = run_rs274(number_lines(text), extra, table)
    rc0, out0, err0 = run_rs274(text, extra, table, numbered=False)
    if rc != rc0 or strip_n_column(out) != strip_n_column(out0):
        raise SystemExit(f"{source}: numbering the lines changed rs274's output")
    err_lines, err0_lines = stderr_lines(err), stderr_lines(err0)
    if err_lines[:-1] != err0_lines[:-1]:
        raise SystemExit(f"{source}: numbering the lines changed rs274's error")
    rel = source.relative_to(ROOT).as_posix()
    command = COMMAND.replace("-g", "-g " + " ".join(extra)) if extra else COMMAND
    tools = "tool table SEM_TOOLS" if source.stem.startswith(SEM_PREFIX) else "tool table with only T1"
    head = [
        f"# rs274: {rs274_version()}; command: {command} "
        f"(own temporary HOME, {tools}, no ini; FILE = source with line k numbered N<k>)",
        f"# source: {rel}",
        f"# sha256: {hashlib.sha256(source.read_bytes()).hexdigest()}",
        f"# exit: {rc}",
    ]
    if rc != 0:
        if not err_lines:
            raise SystemExit(f"{source}: rs274 failed with no message")
        m = _ERROR_LINE.match(err_lines[-1])
        line = m.group(1) if m else _percent_error_line(text, err_lines[-1])
        if len(err_lines) < 2 or not line:
            raise SystemExit(f"{source}: cannot find the error line in {err_lines!r}")
        head.append(f"# error_line: {line}")
        head.append(f"# error: {' | '.join(err_lines[:-1])}")
        head.append(f"# error_text: {err0_lines[-1] if err0_lines else ''}")
    elif err_lines:
        head.extend(f"# stderr: {line}" for line in err_lines)
    return "\n".join(head) + "\n" + out.rstrip("\n") + "\n"


def _percent_error_line(text: str, failing: str) -> str:
    """rs274 refused a ``%`` line (it has no ``N`` word): its line, when the source has
    exactly one ``%`` line after the first line; else ""."""
    found = [k for k, line in enumerate(text.splitlines(), start=1) if k > 1 and line.strip() == "%"]
    return str(found[0]) if failing.strip() == "%" and len(found) == 1 else ""


def sources() -> list[Path]:
    found = sorted(p for d in SOURCE_DIRS for p in d.glob("*.ngc") if p not in libraries())
    stems = [p.stem for p in found]
    dup = {s for s in stems if stems.count(s) > 1}
    if dup:
        raise SystemExit(f"duplicate source names: {sorted(dup)}")
    return found


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", help="only sources whose stem contains one of these")
    args = parser.parse_args(argv)
    DATA.mkdir(exist_ok=True)
    for source in sources():
        if args.names and not any(n in source.stem for n in args.names):
            continue
        runs = {source.stem: ()}
        runs.update({f"{source.stem}+{tag}": extra for tag, extra in VARIANTS.get(source.stem, {}).items()})
        for name, extra in runs.items():
            text = record(source, extra)
            (DATA / f"{name}.canon").write_text(text)
            status = re.search(r"^# error_line: (\d+)", text, re.M)
            print(f"{name}: {'error at line ' + status.group(1) if status else 'ok'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
