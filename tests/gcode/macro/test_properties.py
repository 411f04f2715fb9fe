"""Property tests of the expander: an expansion is deterministic, and a program with
nothing to expand gives through the expander exactly what the fast path gives."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.gcode import load_text, sniff

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
number = st.integers(-2000, 2000).map(lambda v: f"{v / 100:g}")
axis = st.tuples(st.sampled_from("XYZ"), number).map("".join)
axes = st.lists(axis, min_size=1, max_size=3, unique_by=lambda w: w[0])
arc = st.tuples(st.sampled_from(["G2", "G3"]), number, number, number)
plain_line = st.one_of(
    st.tuples(st.sampled_from(["G0", "G1", "g1", ""]), axes).map(lambda t: " ".join([t[0], *t[1]]).strip()),
    arc.map(lambda t: f"{t[0]} X{t[1]} Y{t[2]} R{t[3]}"),
    st.sampled_from(["G20", "G21", "G90", "G91", "F100", "G1 F250", "M3 S1000", "M5", "G4 P0.5",
                     "(a comment)", "", "G18", "G17", "N10 G0 X1", "M0", "G0 A1", "G41", "M2", "/G0 X5"]),
)
plain_program = st.lists(plain_line, max_size=25).map("\n".join)


@SETTINGS
@given(plain_program)
def test_a_plain_program_expands_to_what_the_fast_path_reads(text):
    fast = load_text(text)
    assert fast.ops.source is None  # nothing to expand: the loader takes the fast path
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(sniff, "needs_expander", lambda raw: True)
        slow = load_text(text)
    assert slow.ops.source is not None
    assert slow.moves == fast.moves
    assert slow.device_lines == fast.device_lines
    assert slow.diagnostics == fast.diagnostics


macro_line = st.one_of(
    plain_line,
    st.tuples(st.integers(1, 5), number).map(lambda t: f"#{t[0]} = [{t[1]} * 2 + #{t[0]}]"),
    st.tuples(st.sampled_from("XYZ"), st.integers(1, 5)).map(lambda t: f"G1 {t[0]}[#{t[1]} / 3] F100"),
)


@SETTINGS
@given(st.lists(macro_line, max_size=20).map(lambda lines: "\n".join(["#1 = 1", *lines])))
def test_an_expansion_is_deterministic(text):
    a, b = load_text(text), load_text(text)
    assert a.moves == b.moves and a.diagnostics == b.diagnostics
    assert a.device_lines == b.device_lines
    assert np.array_equal(a.ops.source.call_line, b.ops.source.call_line)


MACRO_ALPHABET = "GXYZFIJMOPLNW#[]<>_=+-*/.0123456789 \n()oifdnwhlegtsqrabcu"
WORDS = "#1 #<a> #<_b> [ ] = + * / EQ LT GOTO IF WHILE DO1 END1 o1 sub endsub call while endwhile do if " \
        "else endif repeat break M98 M99 G65 P1 O1 N1 G1 X SQRT ATAN 1 0 -"
TOKENS = [*WORDS.split(" "), "\n", " "]
macro_tokens = st.sampled_from(TOKENS)
macro_text = st.one_of(st.text(alphabet=MACRO_ALPHABET, max_size=200),
                       st.lists(macro_tokens, max_size=60).map("".join))


@SETTINGS
@given(macro_text)
def test_any_macro_text_loads_without_exception(text):
    program = load_text("#1 = 1\n" + text)
    for d in program.diagnostics:
        assert d.line >= 1 and d.message
    assert len(program.line_map) == len(program.device_lines)
