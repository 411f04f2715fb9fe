"""Compare the loader with rs274 on LinuxCNC's own example programs (a maintainer's check).

Needs rs274 (Debian ``linuxcnc-uspace``), which installs the examples under
/usr/share/linuxcnc/ncfiles; nothing here runs in CI. Programs with rotary or UVW
axes are skipped. Each line says OK, DIFF (moves differ), ERRDIFF (rs274 and the
loader refuse different lines: some are deliberate, see tests/oracle/README.md) or
PARSEFAIL (rs274's output holds calls the canon reader does not know, e.g. probing).

    .venv/bin/python -m tests.oracle.linuxcnc_examples [FOLDER]
"""

from __future__ import annotations

import re
import sys
import tempfile
from pathlib import Path

from app.gcode import load
from app.gcode.tools import Tool
from tests.oracle import record as rec
from tests.oracle.canon import CanonError, compare_moves, drop_axisless_moves, parse_record

EXAMPLES = Path("/usr/share/linuxcnc/ncfiles")
TOOLS = {1: Tool(1, 3.175 * 25.4)}  # rec.TOOL_TABLE's T1 (rs274 reads it in inches)
_OTHER_AXES = re.compile(r"(?im)^[^(;]*\b[ABCUVW]\s*[-+.\d#\[]")


def rs274_record(text: str):
    rc, out, err = rec.run_rs274(rec.number_lines(text), (), rec.TOOL_TABLE)
    head = [f"# exit: {rc}"]
    errors = rec.stderr_lines(err)
    found = rec._ERROR_LINE.match(errors[-1]) if rc and errors else None
    if found:
        head += [f"# error_line: {found.group(1)}", f"# error: {' | '.join(errors[:-1])}"]
    return parse_record("\n".join(head) + "\n" + out)


def compare(source: Path) -> str:
    text = source.read_text(errors="replace")
    if _OTHER_AXES.search(text):
        return "SKIP rotary or UVW axes"
    try:
        theirs = rs274_record(text)
        expected = drop_axisless_moves(theirs.moves, text.splitlines())
    except CanonError as exc:
        return f"PARSEFAIL {exc}"
    with tempfile.TemporaryDirectory() as tmp:
        copy = Path(tmp) / source.name
        copy.write_text(text)
        ours = load(copy, tools=TOOLS)
    errors = [(e.line, e.message) for e in ours.errors]
    if theirs.error_line:
        status = "OK" if errors and errors[0][0] == theirs.error_line else "ERRDIFF"
        return f"{status} rs274 refuses line {theirs.error_line} ({theirs.error_message}); ours {errors[:2]}"
    problems = compare_moves(ours.moves, expected, limit=2)
    status = "OK" if not problems and not errors else "DIFF"
    return f"{status} {len(ours.moves)} moves, rs274 {len(expected)}; our errors {errors[:2]} {problems}"


def main(argv: list[str]) -> int:
    folder = Path(argv[0]) if argv else EXAMPLES
    for source in sorted(folder.rglob("*.ngc")):
        print(f"{source.relative_to(folder)}: {compare(source)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
