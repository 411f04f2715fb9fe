"""Write the arc-tolerance cases ``tests/oracle/cases/arctol_*.ngc`` (one arc per file).

Each program moves to the start of one arc whose end point lies a chosen distance off
the circle through its start, around the limits of LinuxCNC's interpreter (2.9, no ini):

* centre format (IJK): refused when ``|r_end - r_start| > 100 * T`` or when it is
  ``> T`` *and* more than 0.1 % of the larger radius, with T = 2 * 0.01 * sqrt(2) mm
  (0.028284 mm) or 2 * 0.001 * sqrt(2) in (0.0028284 in), in the program's units;
* radius format (R): refused when half the chord exceeds ``|R|`` by more than
  0.00127 mm (0.00005 in).

rs274 stops at the first error, so each file holds a single arc, on line 5. Whether
rs274 accepts or refuses each one is what ``record.py`` records; the rule above is only
how the distances were chosen. Run: ``python tests/oracle/make_arc_cases.py``.
"""

from __future__ import annotations

import math
from pathlib import Path

CASES = Path(__file__).resolve().parent / "cases"


def fmt(v: float) -> str:
    s = f"{v:.7f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def center_case(
    units: str, radius: float, off: float, plane: str = "XY", angle: float = 90.0
) -> tuple[str, str]:
    """An arc of ``angle`` degrees CCW about a centre, its end ``off`` outside the circle."""
    unit_word = "G21" if units == "mm" else "G20"
    feed = "F300" if units == "mm" else "F12"
    x0, y0 = (75.0, 75.0) if units == "mm" else (3.0, 3.0)
    # start = centre + (r, 0); end = centre + (r + off) * (cos a, sin a)
    cx, cy = x0 - radius, y0
    a = math.radians(angle)
    ex, ey = cx + (radius + off) * math.cos(a), cy + (radius + off) * math.sin(a)
    if plane == "XY":
        select, start, arc = (
            "G17",
            f"X{fmt(x0)} Y{fmt(y0)} Z0",
            (f"G3 X{fmt(ex)} Y{fmt(ey)} I{fmt(cx - x0)} J0"),
        )
    elif plane == "XZ":  # first axis Z, second X: start Z=x0, X=y0
        select, start, arc = (
            "G18",
            f"X{fmt(y0)} Y0 Z{fmt(x0)}",
            (f"G3 Z{fmt(ex)} X{fmt(ey)} K{fmt(cx - x0)} I0"),
        )
    else:
        raise ValueError(plane)
    title = (
        f"centre format, {units}, {plane}, radius {fmt(radius)}, {angle:g} deg arc, "
        f"end {fmt(off)} {units} {'outside' if off >= 0 else 'inside'} the circle"
    )
    text = f"({title})\n{unit_word} G90 {select}\nG0 {start}\nG1 {feed}\n{arc}\nG0 X0 Y0\nM2\n"
    return title, text


def radius_case(units: str, radius: float, excess: float) -> tuple[str, str]:
    """An R-format arc whose half chord is ``|radius| + excess``."""
    unit_word = "G21" if units == "mm" else "G20"
    feed = "F300" if units == "mm" else "F12"
    x0, y0 = (40.0, 75.0) if units == "mm" else (1.5, 3.0)
    ex = x0 + 2 * (abs(radius) + excess)
    title = f"radius format, {units}, R{fmt(radius)}, half chord {fmt(excess)} {units} longer than |R|"
    text = (
        f"({title})\n{unit_word} G90 G17\nG0 X{fmt(x0)} Y{fmt(y0)} Z0\nG1 {feed}\n"
        f"G2 X{fmt(ex)} Y{fmt(y0)} R{fmt(radius)}\nG0 X0 Y0\nM2\n"
    )
    return title, text


def all_cases() -> dict[str, str]:
    cases: dict[str, str] = {}

    def add(name: str, made: tuple[str, str]) -> None:
        cases[f"arctol_{name}"] = made[1]

    # mm, r = 10: 0.1 % is 0.01 mm, so T = 0.028284 mm decides
    for off in (0.02, 0.028, 0.0282, 0.0284, 0.029, 0.1, -0.028, -0.029):
        tag = f"{'m' if off < 0 else 'p'}{abs(off):.4f}".replace(".", "_")
        add(f"mm_ijk_r10_{tag}", center_case("mm", 10.0, off))
    # mm, r = 50: 0.1 % of r is 0.05 mm, above T, so the relative limit decides
    for off in (0.045, 0.0499, 0.0502, 0.06):
        add(f"mm_ijk_r50_p{off:.4f}".replace(".", "_"), center_case("mm", 50.0, off))
    # mm, r = 3000 (a 0.6 deg arc): 0.1 % is 3 mm, so the absolute cap 100 * T = 2.83 mm decides
    for off in (2.8, 2.86):
        add(f"mm_ijk_r3000_p{off:.4f}".replace(".", "_"), center_case("mm", 3000.0, off, angle=0.6))
    # XZ plane, mm
    for off in (0.028, 0.029):
        add(f"mm_ijk_g18_r10_p{off:.4f}".replace(".", "_"), center_case("mm", 10.0, off, "XZ"))
    # inch, r = 1: T = 0.0028284 in decides
    for off in (0.002, 0.0028, 0.0029, -0.0029):
        tag = f"{'m' if off < 0 else 'p'}{abs(off):.5f}".replace(".", "_")
        add(f"in_ijk_r1_{tag}", center_case("in", 1.0, off))
    # inch, r = 5: 0.1 % is 0.005 in, the relative limit decides
    for off in (0.0049, 0.0051):
        add(f"in_ijk_r5_p{off:.5f}".replace(".", "_"), center_case("in", 5.0, off))
    # R format: half chord longer than |R| by more than 0.00127 mm / 0.00005 in
    for excess in (0.0, 0.001, 0.0012, 0.0013, 0.002, 0.01):
        add(f"mm_r_r10_p{excess:.4f}".replace(".", "_"), radius_case("mm", 10.0, excess))
    add("mm_r_rneg10_p0_0013", radius_case("mm", -10.0, 0.0013))
    add("mm_r_rneg10_p0_0012", radius_case("mm", -10.0, 0.0012))
    for excess in (0.00004, 0.00006, 0.0002):
        add(f"in_r_r1_p{excess:.5f}".replace(".", "_"), radius_case("in", 1.0, excess))
    # degenerate arcs: zero radius (centre on the start point), R arc ending where it starts
    cases["arctol_mm_ijk_zero_radius"] = (
        "(centre format with the centre on the start point: zero radius)\n"
        "G21 G90 G17\nG0 X75 Y75 Z0\nG1 F300\nG2 X80 Y75 I0 J0\nG0 X0 Y0\nM2\n"
    )
    cases["arctol_mm_r_same_end"] = (
        "(radius format ending where it starts: no circle is defined)\n"
        "G21 G90 G17\nG0 X75 Y75 Z0\nG1 F300\nG2 X75 Y75 R10\nG0 X0 Y0\nM2\n"
    )
    return cases


def main() -> None:
    for old in CASES.glob("arctol_*.ngc"):
        old.unlink()
    for name, text in all_cases().items():
        (CASES / f"{name}.ngc").write_text(text)
        print(name)


if __name__ == "__main__":
    main()
