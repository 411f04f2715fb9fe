"""A 1 M-line program made of a REAL traced drawing (``bench/data/traced.ngc``), for the
load benchmarks: the honest counterpart of ``bench/arcfile.py``'s imitation.

Its source is ``resources/samples/traced_drawing.ngc``: a bitmap drawn by ImageMagick
(text in three fonts, a spiral, rings, a field of noise blobs), traced by ``potrace -s``
and written by real Inkscape Gcodetools (``resources/samples/make_samples.sh``), about
28,000 lines, four moves in five ``G02``/``G03`` with ``I J``. The file is that sample's
body (its ``%`` lines and its ``M2`` dropped) copied as often as it takes to reach a
million lines, each copy shifted as ``far.ngc``'s are: one in ten stays where it was
(the sample's own bytes), the rest move 200-680 mm in X and Y, far outside the 150 mm
travel. Every ``X``/``Y`` word of a shifted copy is rewritten with six decimals, as
``bench_gcode._shift`` does (the header's and footer's ``X0.0000`` too); ``I J`` stay as
they are (they are relative to the arc's start). One ``%`` first, one ``M2`` and ``%``
last. Made once (the same bytes every time), rebuilt only when the sample is newer.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from bench.copies import AXIS, ENDS, count_lines, far_offset

ROOT = Path(__file__).resolve().parents[1]
SAMPLE = ROOT / "resources" / "samples" / "traced_drawing.ngc"
TRACED = ROOT / "bench" / "data" / "traced.ngc"
TARGET_LINES = 1_000_000
_MOTION = re.compile(r"^\s*G0?([0-3])(?!\d)", re.MULTILINE)


def body(sample: Path = SAMPLE) -> str:
    """The sample without its ``%`` lines and its ``M2``, ending in a newline."""
    lines = sample.read_text().splitlines()
    return "\n".join(line for line in lines if not ENDS.match(line)) + "\n"


def _shifter(text: str):
    """A function of (dx, dy) giving ``text`` with every X/Y word moved: the text is split
    at its X/Y words once, so a copy is a join of formatted numbers, not a regex pass."""
    parts = AXIS.split(text)  # text, letter, number, text, letter, number, ..., text
    texts, letters = parts[0::3], parts[1::3]
    values = [float(v) for v in parts[2::3]]
    is_x = [letter == "X" for letter in letters]

    def shifted(dx: float, dy: float) -> str:
        out = [texts[0]]
        for k, value in enumerate(values):
            if is_x[k]:
                out.append(f"X{value + dx:.6f}")
            else:
                out.append(f"Y{value + dy:.6f}")
            out.append(texts[k + 1])
        return "".join(out)

    return shifted


def build(path: Path = TRACED, lines: int = TARGET_LINES, sample: Path = SAMPLE) -> Path:
    """The file of at least ``lines`` lines (made once, then reused)."""
    if (path.exists() and path.stat().st_size > 0 and path.stat().st_mtime >= sample.stat().st_mtime
            and count_lines(path) >= lines):
        return path
    text = body(sample)
    copies = math.ceil((lines - 3) / text.count("\n"))
    shifted, made = _shifter(text), {}
    out = ["%\n"]
    for copy in range(copies):
        d = far_offset(copy)
        if d not in made:
            made[d] = shifted(d, d) if d else text
        out.append(made[d])
    out.append("M2\n%\n")
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp")
    tmp.write_text("".join(out))
    tmp.replace(path)
    return path


def copies(path: Path = TRACED, sample: Path = SAMPLE) -> int:
    """How many copies of the sample's body ``path`` holds."""
    return (count_lines(path) - 3) // body(sample).count("\n")


def describe(path: Path = TRACED, sample: Path = SAMPLE) -> str:
    """Where the file comes from, for the benchmark's report."""
    text = sample.read_text()
    kinds = [m.group(1) for m in _MOTION.finditer(text)]
    arcs = sum(k in "23" for k in kinds) / max(len(kinds), 1)
    return (f"{sample.relative_to(ROOT)} (real potrace + Gcodetools: {text.count(chr(10)) + 1:,} lines, "
            f"{arcs:.0%} of its moves G02/G03), {copies(path, sample)} copies, 9 in 10 outside the travel")



if __name__ == "__main__":
    import time

    started = time.perf_counter()
    built = build()
    print(f"{built.relative_to(ROOT)}: {count_lines(built):,} lines, {built.stat().st_size / 1e6:.1f} MB, "
          f"from {describe(built)} ({time.perf_counter() - started:.2f} s)")
