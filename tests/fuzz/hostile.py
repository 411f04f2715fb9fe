"""The hostile programs of issue 19, shared by the tests, the fuzz targets and
``bench/bench_hostile.py``: each must end within the loader's budgets (counted, never
timed) or be refused with a message naming a line.

``PROGRAMS`` maps a name to (main program text, {other file name: content}); a
content is text, ``SPARSE`` (a 600 MB file of NUL bytes that takes no disk) or
``FIFO`` (a named pipe). ``write(folder, name)`` lays out one program and returns
the main file's path. ``REFUSED`` names the programs that must be refused.
"""

from __future__ import annotations

import os
from pathlib import Path

SPARSE, FIFO = object(), object()
SPARSE_BYTES = 600 << 20


def _g5_lines() -> str:
    return "".join(f"G5 I100000000 J100000000 P-100000000 Q100000000 X{k % 2} Y1\n" for k in range(1000))


def _loop(body: str, count: int = 10**8) -> str:
    return f"G21 G90 F100\n#1 = 0\no1 while [#1 LT {count}]\n{body}#1 = [#1 + 1]\no1 endwhile\nM2\n"


PROGRAMS: dict[str, tuple[str, dict]] = {
    "nested loop of no moves": (
        _loop("#2 = 0\no2 while [#2 LT 1000]\n#2 = [#2 + 1]\no2 endwhile\n", 10**6), {}),
    "loop reading #<_x>": (_loop("#2 = #<_x>\n"), {}),
    "loop reading the position after each move": (_loop("G1 X[#1 MOD 7]\n#2 = #5420\n"), {}),
    "loop of 20 M moves": (_loop("".join(f"G1 X{k}\n" for k in range(1, 21)), 10**6), {}),
    "loop of interpreted lines": (_loop("G1 X1\nG91\nG90\n"), {}),
    "Fanuc GOTO back": (
        "O0001\nG21 G90 F100\n#1 = 0\nN10 #1 = #1 + 1\nIF [#1 LT 100000000] GOTO 10\nM30\n", {}),
    "G38.3 in a loop": (_loop("G38.3 Z-1\n", 10**6), {}),
    "G91 G81 L100000000": ("G21 G90 F100\nG0 Z5\nG91 G81 X0.001 Y0 Z-1 R1 L100000000\nG80\nM2\n", {}),
    "G83 Q0.00001": ("G21 G90 F100\nG0 X0 Y0 Z5\nG83 X1 Y1 Z-90 R1 Q0.00001\nG80\nM2\n", {}),
    "G82 P100000": ("G21 G90 F100\nG0 Z5\nG82 X1 Y1 Z-1 R1 P100000\nG80\nM2\n", {}),
    "1,000 G5 with huge control points": ("G21 G90 F100\nG0 X0 Y0\n" + _g5_lines() + "M2\n", {}),
    "300,000-term expression": ("G21 G90 F100\n#1 = [" + "+".join(["1"] * 300000) + "]\nG1 X#1\nM2\n", {}),
    "600 MB subprogram file": ("G21 F100\no<huge> call\nM2\n", {"huge.ngc": SPARSE}),
    "FIFO subprogram file": ("G21 F100\no<pipe> call\nM2\n", {"pipe.ngc": FIFO}),
    "subprogram name of 300 characters": ("G21 F100\no<" + "a" * 300 + "> call\nM2\n", {}),
    "subprogram name of 200 characters": ("G21 F100\no<" + "a" * 200 + "> call\nM2\n", {}),
    "O0001 mixed with o100 sub": ("O0001\nG21 F100\no100 sub\nG1 X1\no100 endsub\no100 call\nM30\n", {}),
    "o<../x> call": ("G21 F100\no<../x> call\nM2\n", {}),
    "o</abs/path> call": ("G21 F100\no</etc/passwd> call\nM2\n", {}),
    "main program ended by M99": ("O0001\nG21 G90 F100\nG1 X1\nM99\n", {}),
    "60,000 lines with a parameter each": (
        "#1 = 1\nG21 G90 F100\n" + "G1 X#1 Y2\nG1 X2 Y#1\n" * 30000 + "M2\n", {}),
    "recursion without end": ("G21 F100\no1 sub\no1 call\no1 endsub\no1 call\nM2\n", {}),
}
REFUSED = set(PROGRAMS)  # every one of them is refused, each on a line it names


def write(folder: Path, name: str) -> Path:
    """Lay out program ``name`` in ``folder`` (which must be empty of its files)."""
    main, others = PROGRAMS[name]
    for file_name, content in others.items():
        path = folder / file_name
        if content is SPARSE:
            with open(path, "wb") as f:
                f.truncate(SPARSE_BYTES)
        elif content is FIFO:
            os.mkfifo(path)
        else:
            path.write_text(content)
    path = folder / "main.ngc"
    path.write_text(main)
    return path
