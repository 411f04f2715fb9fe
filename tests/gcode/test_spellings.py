"""Every legal spelling of a plain program takes the fast path and reads as the
reference path (``lexer`` + ``interp``) reads it.

A program is drawn as moves (G0/G1 with X Y Z F, G2/G3 arcs in XY with I J, spindle
lines, units) and then spelled at random as rs274ngc allows: spaces and tabs anywhere
in a word (between the letter and its number, inside the number), either case, leading
zeros, ``+`` signs, no leading zero (``X.5``), trailing zeros and dots (``X1.``),
``G1``/``G01``/``G001``, the motion code left out when modal, block numbers ``N10``,
comments in both forms (``( )`` between words, ``;`` to the end, comment-only lines),
a leading ``/`` (block delete), a ``*checksum`` at the end, ``%`` lines, blank lines
and CRLF line ends. The same moves spelled compactly are the expectation (block delete
off); with the switch on, the fast path skips what the reference skips.
"""

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.gcode import bulk, load_text, sniff
from tests.gcode.scans import reference_load

SETTINGS = settings(max_examples=60, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.large_base_example])
MAX_DECIMALS = 4
COMMENT_TEXT = st.text(alphabet="abcXYZ019 .,:;-+#[]%/*=", max_size=12)  # anything but parentheses


def _decimals(value: float) -> int:
    return len(f"{value:.{MAX_DECIMALS}f}".rstrip("0").split(".")[1])


@st.composite
def coordinate(draw, low: float, high: float) -> float:
    return round(draw(st.floats(low, high, allow_nan=False)), draw(st.integers(0, MAX_DECIMALS)))


@st.composite
def plain_program(draw) -> list[list[tuple[str, float]]]:
    """Lines of (letter, value) words: the moves of a plain program, valid arcs."""
    lines = [[("G", draw(st.sampled_from([21.0, 20.0])))]]
    inch = lines[0][0][1] == 20.0
    k = 1 / 25.4 if inch else 1.0
    pos = [0.0, 0.0, 0.0]
    for n in range(draw(st.integers(1, 14))):
        kind = draw(st.sampled_from(["line", "line", "arc", "arc", "spindle"])) if n else "line"
        if kind == "line":
            end = [draw(coordinate(10 * k, 140 * k)), draw(coordinate(10 * k, 140 * k)),
                   draw(coordinate(-5 * k, 5 * k))]
            words = [("G", float(draw(st.integers(0, 1))))]
            axes = [(c, v) for c, v in zip("XYZ", end, strict=True) if not n or v != pos["XYZ".index(c)]
                    or draw(st.booleans())]
            words += axes or [("Z", end[2])]  # a motion word alone: rs274 moves nowhere but counts a move
            if not n or draw(st.booleans()):
                words.append(("F", float(draw(st.integers(1, 900)))))
            pos = end
        elif kind == "arc":
            r = round(draw(st.floats(0.5, 5)) * k, 3)
            a0, sweep = draw(st.floats(0, 6.28)), draw(st.floats(-6.2, 6.2))
            i, j = round(-r * math.cos(a0), 3), round(-r * math.sin(a0), 3)
            cx, cy = pos[0] + i, pos[1] + j
            radius = math.hypot(i, j)
            end = [round(cx + radius * math.cos(a0 + sweep), 3), round(cy + radius * math.sin(a0 + sweep), 3),
                   pos[2]]
            words = [("G", 2.0 if sweep < 0 else 3.0), ("X", end[0]), ("Y", end[1]), ("I", i), ("J", j)]
            if draw(st.booleans()):
                words.append(("F", float(draw(st.integers(1, 900)))))
            pos = end
        else:
            words = draw(st.sampled_from([[("M", 3.0), ("S", 1000.0)], [("M", 5.0)], [("S", 2500.0)],
                                          [("M", 3.0)]]))
        lines.append(words)
    return lines


def compact(lines) -> str:
    """The program as compact text: ``G1 X1.5 Y-2``, one line per line of words."""
    return "".join(" ".join(f"{c}{v:.{_decimals(v)}f}" if c != "G" else f"G{int(v)}" for c, v in words) + "\n"
                   for words in lines)


@st.composite
def spaces(draw, least: int = 0) -> str:
    return "".join(draw(st.lists(st.sampled_from(" \t"), min_size=least, max_size=2)))


@st.composite
def number(draw, value: float, code: bool) -> str:
    """``value`` spelled: sign, leading zeros, no leading zero, trailing zeros or dot."""
    if code:  # G and M codes, block numbers: integers, with leading zeros
        return "0" * draw(st.integers(0, 2)) + str(int(value))
    text = f"{abs(value):.{_decimals(value)}f}"
    whole, _, fraction = text.partition(".")
    fraction += "0" * draw(st.integers(0, 2))
    whole = "0" * draw(st.integers(0, 3)) + whole
    if fraction and whole.strip("0") == "" and draw(st.booleans()):
        whole = ""  # X.5
    sign = "-" if value < 0 or (value == 0 and draw(st.booleans())) else draw(st.sampled_from(["", "+"]))
    dot = "." if fraction else draw(st.sampled_from(["", "."]))
    return sign + whole + dot + fraction


@st.composite
def spelled_word(draw, letter: str, value: float) -> str:
    chars = list(draw(st.sampled_from([letter, letter.lower()])) + draw(number(value, letter in "GMN")))
    return "".join(c + draw(spaces()) for c in chars[:-1]) + chars[-1]  # spaces anywhere inside


@st.composite
def spelled_line(draw, words, motion_before) -> str:
    """One line of ``words`` spelled at random (the motion code left out when modal)."""
    if words[0][0] == "G" and words[0][1] == motion_before and len(words) > 1 and draw(st.booleans()):
        words = words[1:]
    words = draw(st.permutations(words)) if draw(st.booleans()) else words
    parts = [draw(spelled_word(c, v)) for c, v in words]
    if draw(st.booleans()):
        parts.insert(0, draw(spelled_word("N", float(draw(st.integers(0, 99999))))))
    out = draw(spaces())
    if draw(st.integers(0, 5)) == 0:  # block delete: the line runs unless the switch is on
        out += "/" + draw(spaces())
    for part in parts:
        out += part + draw(spaces())
        if draw(st.integers(0, 5)) == 0:
            out += f"({draw(COMMENT_TEXT)})" + draw(spaces())
    if draw(st.integers(0, 5)) == 0:  # a checksum, as RepRap hosts send (ignored)
        out += "*" + str(draw(st.integers(0, 255))) + draw(spaces())
    if draw(st.integers(0, 4)) == 0:
        out += ";" + draw(COMMENT_TEXT) + draw(st.sampled_from(["", "(", ")", "(x)"]))
    return out


@st.composite
def spelled(draw, lines) -> tuple[str, list[int | None]]:
    """The program spelled at random, and the compact line each of its lines stands for."""
    out, source = [], []
    percent = draw(st.booleans())  # rs274: a file that starts with "%" ends with one
    if percent:
        out.append("%"), source.append(None)
    motion = None
    for k, words in enumerate(lines):
        while draw(st.integers(0, 6)) == 0:  # blank and comment-only lines
            out.append(draw(st.sampled_from(["", f"({draw(COMMENT_TEXT)})", f";{draw(COMMENT_TEXT)}"])))
            source.append(None)
        out.append(draw(spelled_line(words, motion)))
        source.append(k + 1)
        if words[0][0] == "G" and words[0][1] in (0.0, 1.0, 2.0, 3.0):
            motion = words[0][1]
    if percent:
        out.append("%"), source.append(None)
    end = draw(st.sampled_from(["\n", "\r\n"]))
    return end.join(out) + end, source


def _moves_by_source(program, source: list[int | None]) -> list[dict]:
    return [{**m, "line": source[m["line"] - 1]} for m in program.moves]


@SETTINGS
@given(st.data())
def test_every_spelling_takes_the_fast_path_and_reads_as_the_reference(data):
    lines = data.draw(plain_program())
    text, source = data.draw(spelled(lines))
    raw = text.encode()
    assert not sniff.needs_expander(raw), text
    scan = bulk.scan(raw.replace(b"\r\n", b"\n"), len(source))
    worded = [i for i, k in enumerate(source) if k is not None]
    assert scan.simple[worded].all(), [text.splitlines()[i] for i in worded if not scan.simple[i]]
    fast, reference = load_text(text), reference_load(text)
    assert fast.moves == reference.moves, text
    assert fast.diagnostics == reference.diagnostics, text
    expected = load_text(compact(lines))
    assert _moves_by_source(fast, source) == expected.moves, text
    assert [(d.line and source[d.line - 1], d.message) for d in fast.diagnostics] == \
        [(d.line, d.message) for d in expected.diagnostics], text
    assert np.isfinite(fast.toolpath.end).all()
    skipping, reference_skipping = load_text(text, block_delete=True), reference_load(text, block_delete=True)
    assert skipping.moves == reference_skipping.moves, text
    assert skipping.diagnostics == reference_skipping.diagnostics, text


def test_a_long_run_of_block_deleted_lines_is_skipped_as_the_reference_skips_it():
    text = "G21 G1 F100\n" + "".join(f"/G1 X{k % 90 + 1} Y2\n" for k in range(500)) + "G1 X5 Y5\n/M5\n"
    for switch in (False, True):
        fast, reference = load_text(text, block_delete=switch), reference_load(text, block_delete=switch)
        assert fast.moves == reference.moves
        assert fast.diagnostics == reference.diagnostics
    assert len(load_text(text, block_delete=True).moves) == 1
    assert str(load_text(text, block_delete=True).diagnostics[-1]).endswith("301 more like: block delete")
